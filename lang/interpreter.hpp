// The tree-walking interpreter (spec §3-§5): evaluates resolved scripts into a SceneDesc.
#pragma once

#include "ast.hpp"
#include "diagnostic.hpp"
#include "file_access.hpp"
#include "include_search.hpp"
#include "resolver.hpp"
#include "token.hpp"
#include "value.hpp"

#include "scene/scene_desc.hpp"

#include <cstdint>
#include <deque>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace crt::lang {

/// Limits of one evaluation (spec §4): bad or hostile scripts end in an error, not a hang.
struct Limits {
    uint64_t maxSteps = 50'000'000; ///< loop iterations plus macro calls
    uint32_t maxDepth = 1'000;      ///< nested macro calls
    /// Entities built (literals, CSG, moved entities, macro groups), drawn or not, and the
    /// length of any list.
    uint64_t maxEntities = 10'000'000;
    uint32_t maxSize = 16'384;      ///< image width and height
    /// Vertices, normals, texture coordinates or triangles of one mesh file (each on its own).
    uint64_t maxMeshSize = scene::kDefaultMaxMeshSize;
    uint64_t maxTextLength = 10'000; ///< characters of one Text
    /// The most nested calls the front end's stack (large_stack.hpp) holds: maxDepth's ceiling.
    static constexpr uint32_t kMaxSupportedDepth = 200'000;
    /// Approximate bytes of the strings, lists and entities evaluation makes (--max-memory).
    uint64_t maxMemory = uint64_t{4} << 30;
    /// What rendering may load (primitives, image pixels): the scene carries it to the
    /// renderer; evaluation already refuses an entity or a scene past maxPrimitives.
    scene::RenderLimits render;
};

struct EvalOptions {
    Limits limits;
    IncludeSearch includes;               ///< -I, CRT_PATH, the standard library
    std::vector<std::string> assetRoots;  ///< --assets; empty: the script's folder and parents
    ReadPermissions access;               ///< --allow-read, --allow-read-all (file_access.hpp)
    uint64_t seed = 0;                    ///< seeds rand()
    int frame = 0;                        ///< t with --frames: the frame's number
    int frameCount = 1;
    int firstFrame = 0;                   ///< the number of an animation's first frame
    double clockStart = 0, clockEnd = 1;  ///< clock at the first and at the last frame
    std::optional<double> time;           ///< --time T: t is this float
    /// --shutter A:B: the shutter (Settings.shutteropen, shutterclose) whatever the script says.
    std::optional<std::pair<double, double>> shutter;
    /// Set for the evaluation at a motion step (motion_evaluation.hpp): how far past the
    /// frame's t it is. t and clock move on by it (clock at its pace over the frames).
    std::optional<double> motionStep;
    std::ostream* printOut = nullptr;     ///< where print() writes; null: standard output
    /// print() shows control characters as escapes (terminal_text.hpp): for a terminal, where
    /// they would act; into a file or a pipe the script's output goes as it is.
    bool escapePrint = false;
    bool checkFiles = true;               ///< look up images and meshes on disk
    /// Polled every few thousand steps; returning true stops evaluation with an error: for a
    /// time budget, or to drop work on text that has changed since.
    std::function<bool()> interrupt;
    /// Keep a short text form of every global's final value (Compilation::globalValues), to
    /// show what a name holds.
    bool keepGlobalValues = false;
};

class Interpreter;

/// The result of running the front end on one script.
struct Compilation {
    SourceManager sources;
    DiagnosticBag diagnostics;
    std::unique_ptr<Arena> arena = std::make_unique<Arena>();
    Script main;
    std::vector<Token> comments;
    std::optional<scene::SceneDesc> scene; ///< set when evaluation finished without errors
    bool resolved = false; ///< names were resolved (the main script has no syntax errors)
    /// The global scope the resolver built, and whether the script reads t or clock: kept so
    /// that a compilation resolved by compile(..., false) can be evaluated later (evaluate()).
    GlobalTable globals;
    bool readsTime = false;
    /// With EvalOptions::keepGlobalValues: each assigned global's name and str() (shortened),
    /// as they stood when evaluation ended or stopped.
    std::vector<std::pair<std::string, std::string>> globalValues;
};

/// Parses, resolves and (unless `evaluate` is false or there are errors) evaluates the
/// script `path` with contents `text`.
Compilation compile(std::string path, std::string text, const EvalOptions& options,
                    bool evaluate = true);
/// Evaluates a compilation that compile(..., evaluate = false) parsed and resolved, as
/// compile() would have (nothing happens if it has errors): resolving and evaluating can then
/// happen at different times, evaluation only once it is wanted.
void evaluate(Compilation& compilation, const EvalOptions& options);
/// Reads `path` and compiles it; an unreadable file is an error diagnostic.
Compilation compileFile(const std::string& path, const EvalOptions& options, bool evaluate = true);

} // namespace crt::lang
