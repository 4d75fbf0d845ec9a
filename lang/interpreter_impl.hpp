// The interpreter's internals, shared by its source files (not a public header).
#pragma once

#include "builtins.hpp"
#include "interpreter.hpp"

#include "scene/function_program.hpp"
#include "scene/instancing.hpp"
#include "scene/primitive_count.hpp"

#include <fmt/format.h>

#include <array>
#include <map>
#include <memory>
#include <set>
#include <tuple>
#include <filesystem>
#include <optional>
#include <compare>
#include <span>
#include <string>
#include <string_view>

namespace crt::lang {

/// Bytes that cost one evaluation step: making a long string or list takes time in
/// proportion to its size, and the step limit and the time budget must see it.
inline constexpr uint64_t kBytesPerStep = 1024;

/// Thrown after a run-time error has been reported (or, leaving a statement that read a
/// poisoned variable, with none to report). The statement is abandoned and evaluation goes on
/// with the next top-level or Scene statement, unless a limit was reached.
struct EvalError {};

/// Per-entity facts the scene description does not carry, for warnings and str().
struct EntityInfo {
    SourceRange range{};
    ObjectType type = ObjectType::Count; ///< Count for CSG, transforms and groups
    bool literal = false; ///< built by an object literal (so "never drawn" is worth saying)
    bool outsideScene = false; ///< part of what a statement outside every Scene left (warned there)
};
static_assert(sizeof(EntityInfo) <= 16, "one per entity: keep it small");

struct LightInfo {
    ObjectType type;
    SourceRange range;
    bool listed = false;
};

/// An error found now and reported later, as fail() would report it.
struct DeferredError {
    SourceRange where;
    std::string message;
};

struct ObjectBuilder;

/// A list of modifiers held as a value (`spin = <rotate v, material m>`), or read from one
/// before it is applied.
struct ModifierList {
    std::vector<scene::Modifier> moves;
    int32_t material = -1;       ///< given to the parts that have none; -1: none
    SourceRange materialRange{}; ///< where the material was given
    uint8_t hidden = 0;          ///< scene::HiddenFrom bits (`shadow false` …)
    SourceRange hiddenRange{};   ///< where the first of them was given
    SourceRange range{};         ///< where the list was written
};

/// What a statement's value is used for.
enum class EmitMode : uint8_t { None, Scene, Macro };

class Interpreter {
public:
    Interpreter(Compilation& compilation, const EvalOptions& options);
    /// Resolves the main script and, if `evaluate` and there are no errors, evaluates it;
    /// fills compilation.scene unless an error occurred.
    void run(bool evaluate);
    /// Evaluates the main script resolved before (by run(false), maybe in another Interpreter).
    void evaluateResolved();

    // --- services for built-ins and object builders ---
    [[noreturn, gnu::cold, gnu::noinline]] void fail(SourceRange where, std::string message);
    /// fail() for a limit reached (steps, memory, nesting, entities, ...): the evaluation ends
    /// there, rather than go on with the next statement.
    [[noreturn, gnu::cold, gnu::noinline]] void failAtLimit(SourceRange where, std::string message);
    const std::string* newString(std::string text);
    const std::vector<Value>* newList(std::vector<Value> items);
    uint64_t nextRandom();
    std::ostream& printOut();
    /// Writes print()'s line, escaped if EvalOptions::escapePrint says so.
    void print(const std::string& line);
    /// The point of Spline value `index` at t (spline(s, t)).
    glm::dvec3 splineAt(uint32_t index, double t) const;
    /// The text form of `value`, as str() gives it; an error at the statement running if it
    /// would pass the memory limit (a list holding itself many times grows exponentially).
    std::string str(const Value& value);
    /// At most about `maxBytes` of the text form; false if it was cut short there.
    /// `onItems` is called after every kTextItemsPerCall list items written.
    bool appendText(std::string& out, const Value& value, size_t maxBytes,
                    const std::function<void()>& onItems = {}) const;
    static constexpr size_t kTextItemsPerCall = 4096;
    /// The text of a macro, built-in or object: its kind and where it was made.
    std::string objectText(const Value& value) const;
    /// "Sphere", or for a (moved) CSG result or group "Union", "Group" and so on.
    std::string entityTypeName(const Value& entity) const;
    /// Counts `bytes` that evaluation is about to hold against --max-memory, and their cost
    /// in steps (copying them takes time), reporting an error at the running statement if
    /// either limit is passed. Call it before allocating, so that the limit holds.
    void charge(uint64_t bytes);
    /// Reports an error at the running statement unless `bytes` more fit in --max-memory.
    void checkRoom(uint64_t bytes);
    /// `a + b` for a string and a string, number or bool.
    Value concatenate(const Value& a, const Value& b);
    /// Reports running out of memory at the running statement (after a std::bad_alloc).
    void reportOutOfMemory();
    const Limits& limits() const { return options_.limits; }
    SourceRange argRange(const CallExpr* site, size_t index) const;

    /// The program of Function value `index`.
    const std::shared_ptr<const scene::FunctionProgram>& functionProgram(uint32_t index) const {
        return functions_[index].program;
    }

private:
    friend struct ObjectBuilder;
    friend class FunctionCompiler;

    // statements
    void execStatements(std::span<Node* const> statements);
    /// Runs the main script's and the Scene blocks' statements each on its own: an error
    /// abandons its statement (poisonAssigned) and the next one runs, so that one evaluation
    /// reports every error it can. Limits still end it.
    void execRecovering(std::span<Node* const> statements);
    /// After `failed` was abandoned: the variables it would have set read as poisoned.
    void poisonAssigned(const Node* failed);
    Value exec(const Node* node);
    void execInclude(const IncludeStmt* node);
    void execSettings(const SettingsStmt* node);
    void execScene(const SceneStmt* node);
    void execFor(const ForStmt* node);
    /// After a loop's first iteration: room for `remaining` more iterations that each add the
    /// entities and materials the first one added.
    void reserveLike(size_t entitiesBefore, size_t materialsBefore, uint64_t remaining);
    void emit(const Value& value, const Node* where);
    void draw(const Value& value, const Node* where);
    /// An entity a statement outside every Scene block made and dropped: it is not drawn.
    void leftOutsideScene(const Value& entity, const Node* statement);
    /// Appends the entities of a (nested) list in order; returns the first item that is
    /// neither an entity nor a list, or null.
    static const Value* flattenEntities(const Value& list, std::vector<Value>& out);

    // expressions
    Value eval(const Expr* node);
    /// Counts one more level of nesting (expressions and blocks, across macro calls) for as
    /// long as it lives: every level takes stack, so their number is limited.
    struct NestingLevel {
        Interpreter& in;
        NestingLevel(Interpreter& interpreter, const Node* node) : in(interpreter) {
            if (++in.nesting_ > in.maxNesting_) [[unlikely]] in.nestedTooDeep(node);
        }
        ~NestingLevel() { --in.nesting_; }
        NestingLevel(const NestingLevel&) = delete;
        NestingLevel& operator=(const NestingLevel&) = delete;
    };
    [[noreturn, gnu::cold, gnu::noinline]] void nestedTooDeep(const Node* node);
    Value evalVar(const VarExpr* node);
    Value evalString(const StringLit* node);
    /// Stores an assignment's value (none for a value-less one) and returns it. Inline, so
    /// that an assignment statement, whose value is dropped, does not copy it back.
    [[gnu::always_inline]] Value assign(const AssignExpr* node) {
        Value value = eval(node->value);
        if (value.kind == ValueKind::Unset) value = Value::none();
        store(node->resolution, value);
        return value;
    }
    Value evalTernary(const TernaryExpr* node);
    [[noreturn, gnu::cold, gnu::noinline]] Value notAnExpression(const Expr* node);
    [[noreturn, gnu::cold, gnu::noinline]] void unboundVariable(const VarExpr* node);
    /// Inline: loops store every iteration. The resolver assigns only locals and globals, and
    /// the table of globals is sized after every resolve.
    void store(const Resolution& resolution, const Value& value) {
        if (resolution.binding == Binding::Local) {
            locals_[resolution.slot] = value;
        } else if (resolution.binding == Binding::Global) {
            globalValues_[resolution.slot] = value;
        }
    }
    Value evalBinary(const BinaryExpr* node);
    Value evalLogical(const BinaryExpr* node);
    [[gnu::noinline]] Value binaryOnValues(const BinaryExpr* node, const Value& a, const Value& b);
    Value binaryOnInts(const BinaryExpr* node, const Value& a, const Value& b);
    Value binaryOnNumbers(const BinaryExpr* node, const Value& a, const Value& b);
    void warnDivisionByZero(const BinaryExpr* node, double dividend);
    Value binaryOnNonNumbers(const BinaryExpr* node, const Value& a, const Value& b);
    Value evalUnary(const UnaryExpr* node);
    Value evalCall(const CallExpr* node);
    /// The call itself, once the callee is known to be callable: `args` has a slot per argument.
    Value callWith(const Value& callee, const CallExpr* node, std::span<Value> args);
    /// Evaluates a call's arguments, left to right, into `args` (one slot per argument).
    void evalArguments(const CallExpr* node, std::span<Value> args) {
        for (size_t i = 0; i < node->args.size(); ++i) {
            // Constructed in place from eval's result, not assigned from a temporary: each
            // value is written once, where the call reads it.
            ::new (static_cast<void*>(&args[i])) Value(eval(node->args[i]));
            if (args[i].kind == ValueKind::None) fail(node->args[i]->range, "this argument has no value (none)");
        }
    }
    static bool arityFits(const BuiltinInfo& info, size_t count) {
        int n = static_cast<int>(count);
        return n >= info.minArgs && (info.maxArgs < 0 || n <= info.maxArgs);
    }
    /// Reports a call passing more or fewer arguments than the built-in takes.
    [[noreturn, gnu::cold, gnu::noinline]] void arityError(const BuiltinInfo& info, const CallExpr* node);
    /// For `for … in range(…)` with the built-in range: its numbers, without the list.
    std::optional<RangeSequence> rangeSequence(const Expr* iterable);
    Value evalIndex(const IndexExpr* node);
    Value evalComponent(const ComponentExpr* node);
    Value joinLists(const std::vector<Value>& a, const std::vector<Value>& b,
                    const BinaryExpr* node);
    Value evalModify(const ModifyExpr* node);
    Value evalModifierList(const ModifierListExpr* node);
    /// The modifiers of `<…>` in order, lists given by name spliced in.
    ModifierList evalModifiers(std::span<const Modifier> modifiers, SourceRange whole);
    scene::Modifier evalMove(const Modifier& modifier);
    scene::Modifier evalMatrix(const Modifier& modifier);
    Value evalList(const ListExpr* node);
    Value evalMacro(const MacroExpr* node);
    /// Compiles a Function (function_values.cpp), reading the names it uses besides its
    /// parameters now.
    Value evalFunction(const FunctionExpr* node);
    Value callFunction(uint32_t index, const CallExpr* site, std::span<const Value> args);
    Value callMacro(const Closure* closure, const CallExpr* site, std::span<const Value> args);
    /// Adds "in the macro called here" to the errors reported since `diagnosticsBefore`.
    void noteCallSite(size_t diagnosticsBefore, const CallExpr* site);
    /// What a macro call returns: what it emitted (one entity, or a group of several), else
    /// the value of its last expression statement.
    Value macroResult(const std::vector<Value>& emitted, const Value& last, const CallExpr* site);
    Value csg(BinaryOp op, const Value& left, const Value& right, const BinaryExpr* node);
    bool condition(const Expr* node, std::string_view what);
    /// Counts a loop iteration or macro call against the step limit; inline, since loops
    /// pay it every iteration, and the checks themselves only every so often.
    void step(SourceRange where) {
        if (++steps_ >= nextStepCheck_) [[unlikely]] checkSteps(where);
    }
    [[gnu::cold, gnu::noinline]] void checkSteps(SourceRange where);
    uint64_t nextCheckAfter(uint64_t steps) const;
    void keepGlobalValues();

    // objects (object_literals.cpp): each category's description from checked attributes
    Value evalObject(const ObjectExpr* node);
    Value buildEntity(ObjectBuilder& b);
    /// Merge and Inverse: entities made of other entities.
    Value buildCombination(ObjectBuilder& b);
    scene::Shape solidShape(ObjectBuilder& b);
    scene::Shape surfaceShape(ObjectBuilder& b);
    scene::Shape polygonShape(ObjectBuilder& b);
    scene::Shape prismShape(ObjectBuilder& b);
    scene::Shape sorShape(ObjectBuilder& b);
    scene::Shape latheShape(ObjectBuilder& b);
    scene::Shape sphereSweepShape(ObjectBuilder& b);
    /// The error of a Prism or Lathe with fewer `points` than `least`, or Bézier points not in
    /// fours.
    void checkPointCount(ObjectBuilder& b, scene::SplineKind kind, size_t least);
    /// The `points` of a curve in the x-y plane as (x, y): an error at a point whose z is not
    /// 0, saying `what` the points are.
    std::vector<glm::dvec2> pointsInXY(ObjectBuilder& b, std::string_view what);
    scene::Shape textShape(ObjectBuilder& b);
    scene::Shape blobShape(ObjectBuilder& b);
    scene::Shape isosurfaceShape(ObjectBuilder& b);
    scene::Shape heightFieldShape(ObjectBuilder& b);
    Value buildBlobComponent(const ObjectBuilder& b);
    Value buildSpline(ObjectBuilder& b);
    Value buildMaterial(const ObjectBuilder& b);
    Value buildCamera(ObjectBuilder& b);
    Value buildLight(const ObjectBuilder& b);
    Value buildBackground(const ObjectBuilder& b);
    Value buildFog(ObjectBuilder& b);
    Value buildMedium(ObjectBuilder& b);
    Value buildTexture(ObjectBuilder& b);
    /// Fills scene_.settings; keeps what it names for assembleScene to link, and every value
    /// out of its range in settingsProblems_ (for reportSettingsProblems).
    void buildSettings(const ObjectBuilder& b);
    /// Remembers the camera, lights and background Settings names, for linkSettings.
    void recordSettingsLinks(const ObjectBuilder& b);
    /// The image or mesh file an attribute names, found on disk (unless checkFiles is off).
    std::string findFile(const ObjectBuilder& b, std::string_view attribute, std::string_view what);
    /// A Mesh from its file or from the vertices and faces written in it (mesh_reading.cpp).
    scene::Shape meshShape(ObjectBuilder& b);
    /// Reads and checks the mesh at `path` (found by findFile) into the scene, once per
    /// evaluation.
    void readMesh(const ObjectBuilder& b, const std::string& path);
    /// readMesh's readers: of OBJ (a bad line is noted), and of PLY, STL and glTF (Assimp).
    scene::MeshData readObjMesh(const ObjectBuilder& b, const std::string& path);
    scene::MeshData readAssimpMesh(const ObjectBuilder& b, const std::string& path);
    /// The mesh data a Mesh names; null when its file was not read (files not checked).
    const scene::MeshData* meshDataOf(const scene::MeshShape& mesh) const;
    /// Why an entity that is a Mesh (or one moved) is not closed, naming an open edge ("its
    /// edge from vertex 3 (…) to vertex 4 (…) has one triangle"); "" for any other entity,
    /// a closed mesh, or a mesh not read.
    std::string openMeshReason(uint32_t entity) const;
    /// The mesh of a Mesh's vertices, faces, normals and uvs, checked.
    std::shared_ptr<const scene::MeshData> writtenMesh(ObjectBuilder& b);
    /// Counts a mesh's triangles, stored once however often it is drawn, against the limit
    /// on primitives; `where` is the attribute that made the mesh.
    void storeTriangles(const scene::MeshData& mesh, SourceRange where);
    /// Refuses a scene that stores more primitives than the limit (counted as the renderer
    /// stores them, scene/instancing.hpp), at the drawing that passes it.
    void checkStoredPrimitives();
    /// What the script may read, made from the options when first needed.
    const FileAccess& fileAccess();
    int32_t addEntity(scene::EntityDesc entity, EntityInfo info);
    /// A warning reported once per construct, however often evaluation passes it.
    void warnOnce(WarningKind kind, SourceRange where, std::string message);
    scene::SourceSpan span(SourceRange range) const;

    // the end (scene_assembly.cpp)
    void assembleScene();
    /// Puts the camera, lights and background Settings names into the scene.
    void linkSettings();
    /// Reports the Settings values buildSettings found out of their range.
    void reportSettingsProblems();
    /// Keeps only the entities, materials and textures the drawn entities reach.
    void keepReachable();
    /// Removes the entities, materials and textures not marked, renumbering references.
    void dropUnreachable(const std::vector<bool>& keepEntity, const std::vector<bool>& keepMaterial,
                         const std::vector<bool>& keepTexture, const std::vector<bool>& keepBlend);
    void reportUnused();
    /// Whether anything lights the scene: a light, ambient light or a material that glows.
    bool sceneIsLit() const;
    /// Where to say it is not: the `Settings` keyword, else the first `Scene`'s.
    SourceRange unlitSceneRange() const;
    struct SpanCacheEntry {
        SourceRange range{~0u, 0, 0};
        scene::SourceSpan span;
    };
    mutable std::array<SpanCacheEntry, 16> spanCache_{};

    Compilation& compilation_;
    const EvalOptions& options_;
    DiagnosticBag& diagnostics_;

    GlobalTable& globals_; ///< compilation_.globals
    std::vector<Value> globalValues_;
    std::vector<Value> prelude_;

    std::vector<Value> stack_; ///< frames of macros whose locals are not captured
    Value* locals_ = nullptr;
    Frame* heapFrame_ = nullptr; ///< the running macro's frame if heap-allocated
    Frame* enclosing_ = nullptr; ///< the running macro's closure environment
    uint32_t depth_ = 0;
    uint32_t nesting_ = 0;    ///< levels of NestingLevel alive
    uint32_t maxNesting_ = 0; ///< what the stack allows (maxNesting())
    uint64_t memoryUsed_ = 0; ///< bytes charged so far
    /// The innermost statement running: where limits and running out of memory are reported.
    const Node* statement_ = nullptr;
    uint64_t steps_ = 0;
    bool stopped_ = false;       ///< a limit was reached: no statement runs after the one running
    uint64_t nextStepCheck_ = 0; ///< when step() next calls checkSteps (set by the constructor)

    EmitMode emitMode_ = EmitMode::None;
    std::vector<Value>* emitted_ = nullptr;
    std::deque<std::vector<Value>> emitBuffers_; ///< per macro call depth; a deque keeps them in place

    std::deque<std::string> strings_;
    std::deque<std::vector<Value>> lists_;
    std::deque<Closure> closures_;
    std::deque<Frame> frames_;
    std::deque<ModifierList> modifierLists_;

    uint64_t randomState_ = 0;
    std::set<uint64_t> divisionsWarned_; ///< the '/' operators (file << 32 | offset) warned about
    bool animated_ = false; ///< the script reads t or clock

    // scene under construction
    scene::SceneDesc scene_;
    std::vector<EntityInfo> entityInfo_;
    std::vector<SourceRange> drawnAt_; ///< per SceneDesc::drawn entry: what drew it
    /// The triangles of the meshes made, each stored once however often it is drawn; saturating.
    uint64_t meshTriangles_ = 0;
    std::vector<bool> reachable_; ///< per entity: drawn, or part of something drawn
    std::set<std::tuple<WarningKind, uint32_t, uint32_t>> warnedOnce_;
    std::vector<scene::LightDesc> lights_;
    /// The BlobSphere and BlobCylinder values made, and where.
    struct BlobComponentValue {
        scene::BlobComponent component;
        scene::SourceSpan source;
    };
    std::vector<BlobComponentValue> blobComponents_;
    /// The Spline values made: their segments and times, and where.
    struct SplineValue {
        std::vector<scene::CurveSegmentOf<glm::dvec3>> segments;
        std::vector<double> times; ///< one more than the segments, or none: evenly 0 to 1
        scene::SourceSpan source;
    };
    std::vector<SplineValue> splines_;
    /// The Function values made, and where.
    struct FunctionValue {
        std::shared_ptr<const scene::FunctionProgram> program;
        scene::SourceSpan source;
    };
    std::vector<FunctionValue> functions_;
    std::vector<LightInfo> lightInfo_;
    std::vector<scene::CameraDesc> cameras_;
    std::vector<scene::BackgroundDesc> backgrounds_;
    std::vector<scene::FogDesc> fogs_;
    const SettingsStmt* settings_ = nullptr;
    /// What Settings names, linked into the scene by assembleScene.
    struct SettingsLinks {
        std::optional<uint32_t> camera;             ///< into cameras_
        const std::vector<Value>* lights = nullptr; ///< Light values, into lights_
        std::optional<Value> background;            ///< a Background or a color
        SourceRange backgroundRange{};
        std::optional<uint32_t> fog; ///< into fogs_
    } settingsLinks_;
    std::vector<DeferredError> settingsProblems_;

    // include bookkeeping
    std::vector<std::string> includedFiles_; ///< canonical paths, in order
    std::vector<std::string> includeStack_;  ///< canonical paths being run
    std::optional<FileAccess> fileAccess_;
};

/// The absolute folder of `path` ("." for a bare file name).
std::filesystem::path folderOf(const std::string& path);

/// "cannot apply '-' to string and vec3"
std::string operandError(std::string_view op, const Value& left, const Value& right);
/// Orders two numbers exactly, an int against a float included.
std::partial_ordering compareNumbers(const Value& a, const Value& b);
bool valuesEqual(const Value& a, const Value& b);
/// For a float given where an int is needed: "; use N" and a fix-it, when N is exact enough.
void addIntFixIt(Diagnostic& diagnostic, const Value& given, SourceRange where);

} // namespace crt::lang
