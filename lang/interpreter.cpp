// Statements, variables, macro calls and includes.
#include "interpreter_impl.hpp"

#include "scene/entity_parts.hpp"

#include "builtins.hpp"
#include "large_stack.hpp"
#include "motion_evaluation.hpp"
#include "parser.hpp"
#include "povray_habits.hpp"
#include "terminal_text.hpp"
#include "value_format.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <new>
#include <sstream>

namespace crt::lang {

namespace fs = std::filesystem;

Interpreter::Interpreter(Compilation& compilation, const EvalOptions& options)
    : compilation_(compilation), options_(options), diagnostics_(compilation.diagnostics),
      globals_(compilation.globals), randomState_(options.seed) {
    prelude_.resize(preludeSize());
    for (uint32_t slot = 0; slot < preludeSlotOfT(); ++slot) {
        prelude_[slot] = Value::object(ValueKind::Builtin, ObjectType::Count, slot);
    }
    const double step = options.motionStep.value_or(0);
    prelude_[preludeSlotOfT()] = options.time || options.motionStep
                                     ? Value::number((options.time ? *options.time : options.frame) + step)
                                     : Value::integer(options.frame);
    // clock runs from clockStart to clockEnd over the frames of an animation; a single frame
    // is at clockStart.
    const double progress = options.frameCount > 1 ? (options.frame - options.firstFrame + step) /
                                                         (options.frameCount - 1)
                                                   : 0.0;
    const double clock = options.clockStart + progress * (options.clockEnd - options.clockStart);
    prelude_[preludeSlotOfClock()] = Value::number(clock);
    nextStepCheck_ = nextCheckAfter(0);
    maxNesting_ = maxNesting();
}

void Interpreter::fail(SourceRange where, std::string message) {
    diagnostics_.error(where, std::move(message));
    throw EvalError{};
}

void Interpreter::failAtLimit(SourceRange where, std::string message) {
    stopped_ = true;
    fail(where, std::move(message));
}

const std::string* Interpreter::newString(std::string text) {
    charge(sizeof(std::string) + text.capacity());
    return &strings_.emplace_back(std::move(text));
}

const std::vector<Value>* Interpreter::newList(std::vector<Value> items) {
    charge(sizeof(items) + items.capacity() * sizeof(Value));
    return &lists_.emplace_back(std::move(items));
}

void Interpreter::checkRoom(uint64_t bytes) {
    if (bytes > options_.limits.maxMemory - std::min(memoryUsed_, options_.limits.maxMemory)) {
        failAtLimit(statement_ ? statement_->range : SourceRange{},
                    fmt::format("evaluation needs more than {} MiB of memory; raise the limit with "
                                "--max-memory",
                                options_.limits.maxMemory >> 20));
    }
}

void Interpreter::charge(uint64_t bytes) {
    const SourceRange where = statement_ ? statement_->range : SourceRange{};
    checkRoom(bytes);
    memoryUsed_ += bytes;
    steps_ += bytes / kBytesPerStep;
    if (steps_ >= nextStepCheck_) checkSteps(where);
}

void Interpreter::reportOutOfMemory() {
    const SourceRange where = statement_ ? statement_->range : SourceRange{};
    diagnostics_.error(where, "out of memory while evaluating this statement");
    stopped_ = true;
}

void Interpreter::nestedTooDeep(const Node* node) {
    failAtLimit(node->range,
                fmt::format("expressions, blocks and macro calls nested deeper than {} "
                            "levels",
                            maxNesting_));
}

uint64_t Interpreter::nextRandom() {
    // SplitMix64: one stream per evaluation, so every frame sees the same numbers.
    uint64_t z = (randomState_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

std::ostream& Interpreter::printOut() { return options_.printOut ? *options_.printOut : std::cout; }

void Interpreter::print(const std::string& line) {
    printOut() << (options_.escapePrint ? terminalSafe(line) : line);
}

SourceRange Interpreter::argRange(const CallExpr* site, size_t index) const {
    return index < site->args.size() ? site->args[index]->range : site->range;
}

void Interpreter::checkSteps(SourceRange where) {
    if (steps_ > options_.limits.maxSteps) {
        failAtLimit(where, fmt::format("evaluation exceeded {} steps (loop iterations and macro "
                                       "calls); raise the limit with --max-steps",
                                       options_.limits.maxSteps));
    }
    if (options_.interrupt && options_.interrupt()) {
        failAtLimit(where, "evaluation was stopped before it finished (time budget exceeded)");
    }
    nextStepCheck_ = nextCheckAfter(steps_);
}

uint64_t Interpreter::nextCheckAfter(uint64_t steps) const {
    // Past the limit, or (with an interrupt callback) at the next 64th step: polling that
    // often keeps its cost small while a slow loop still stops in time.
    uint64_t limit = options_.limits.maxSteps == UINT64_MAX ? UINT64_MAX : options_.limits.maxSteps + 1;
    return options_.interrupt ? std::min(limit, steps + 64) : limit;
}

void Interpreter::run(bool evaluate) {
    compilation_.readsTime = resolve(compilation_.main, globals_, diagnostics_, true).readsTime;
    compilation_.resolved = true;
    if (evaluate) evaluateResolved();
}

void Interpreter::evaluateResolved() {
    if (!compilation_.resolved || diagnostics_.hasErrors()) return;
    animated_ = compilation_.readsTime;
    std::error_code error;
    const SourceFile& main = compilation_.sources.file(compilation_.main.file);
    fs::path canonical = fs::weakly_canonical(fs::absolute(main.path(), error), error);
    includedFiles_.push_back(canonical.string());
    includeStack_.push_back(canonical.string());
    globalValues_.resize(globals_.size());
    try {
        execRecovering(compilation_.main.items);
        if (!diagnostics_.hasErrors()) checkStoredPrimitives();
        // After an error, what is unused or unlit is most likely so because of it.
        if (!diagnostics_.hasErrors()) {
            assembleScene();
            reportUnused();
        }
        if (options_.keepGlobalValues) keepGlobalValues(); // str() of objects reads scene_
        if (!diagnostics_.hasErrors()) compilation_.scene = std::move(scene_);
    } catch (const EvalError&) {
        // reported already
        if (options_.keepGlobalValues) keepGlobalValues();
    } catch (const std::bad_alloc&) {
        reportOutOfMemory();
    }
}

void Interpreter::keepGlobalValues() {
    constexpr size_t kMaxText = 160; // a hover line, not a dump of a huge list
    for (uint32_t slot = 0; slot < globals_.size() && slot < globalValues_.size(); ++slot) {
        const Value& value = globalValues_[slot];
        if (value.kind == ValueKind::Unset || value.kind == ValueKind::Poisoned) continue;
        std::string text;
        if (value.kind == ValueKind::List && value.list->size() > 32) {
            text = fmt::format("a list of {} values", value.list->size());
        } else if (value.kind == ValueKind::String) {
            text = lang::quoted(std::string_view(*value.s).substr(0, kMaxText + 1));
        } else {
            appendText(text, value, kMaxText + 1);
        }
        if (text.size() > kMaxText) text = text.substr(0, kMaxText) + "…";
        compilation_.globalValues.emplace_back(globals_.entry(slot).name, std::move(text));
    }
}

// ---------------------------------------------------------------- statements

void Interpreter::execStatements(std::span<Node* const> statements) {
    const Node* enclosing = statement_;
    for (const Node* statement : statements) {
        statement_ = statement;
        exec(statement);
    }
    statement_ = enclosing;
}

Value Interpreter::exec(const Node* node) {
    NestingLevel level(*this, node);
    switch (node->kind) {
    case NodeKind::While: {
        auto* w = static_cast<const WhileStmt*>(node);
        while (condition(w->condition, "while")) {
            step(w->condition->range);
            execStatements(w->body->statements);
        }
        return Value::none();
    }
    case NodeKind::For: execFor(static_cast<const ForStmt*>(node)); return Value::none();
    case NodeKind::If: {
        auto* i = static_cast<const IfStmt*>(node);
        if (condition(i->condition, "if")) {
            execStatements(i->then->statements);
        } else if (i->otherwise) {
            exec(i->otherwise);
        }
        return Value::none();
    }
    case NodeKind::Block: execStatements(static_cast<const Block*>(node)->statements); return Value::none();
    case NodeKind::Settings: execSettings(static_cast<const SettingsStmt*>(node)); return Value::none();
    case NodeKind::Scene: execScene(static_cast<const SceneStmt*>(node)); return Value::none();
    case NodeKind::Include: execInclude(static_cast<const IncludeStmt*>(node)); return Value::none();
    case NodeKind::Error: return Value::none();
    case NodeKind::Assign: assign(static_cast<const AssignExpr*>(node)); return Value::none();
    default: {
        Value value = eval(static_cast<const Expr*>(node));
        if (emitMode_ != EmitMode::None) {
            emit(value, node);
        } else if (value.kind == ValueKind::Entity) {
            leftOutsideScene(value, node);
        }
        return value;
    }
    }
}

std::optional<RangeSequence> Interpreter::rangeSequence(const Expr* iterable) {
    if (iterable->kind != NodeKind::Call) return std::nullopt;
    const auto* call = static_cast<const CallExpr*>(iterable);
    // Reading a variable has no effect, so evaluating the callee again on the general
    // path (when it is not range) changes nothing.
    if (call->callee->kind != NodeKind::Var || call->args.size() > 3) return std::nullopt;
    Value callee = evalVar(static_cast<const VarExpr*>(call->callee));
    if (callee.kind != ValueKind::Builtin) return std::nullopt;
    const BuiltinInfo& info = builtinFunctions()[callee.index];
    if (info.name != "range") return std::nullopt;
    if (!arityFits(info, call->args.size())) arityError(info, call);
    std::array<Value, 3> storage;
    std::span<Value> args(storage.data(), call->args.size());
    evalArguments(call, args);
    BuiltinCall builtinCall{*this, call, args};
    return RangeSequence(builtinCall);
}

void Interpreter::execFor(const ForStmt* node) {
    uint64_t iterations = 0; // when known before the loop starts
    const size_t entitiesBefore = scene_.entities.size(), materialsBefore = scene_.materials.size();
    bool first = true;
    auto runBody = [&](const Value& item) {
        step(node->iterable->range);
        store(node->resolution, item);
        execStatements(node->body->statements);
        if (first && iterations > 1) {
            reserveLike(entitiesBefore, materialsBefore, iterations - 1);
        }
        first = false;
    };
    if (std::optional<RangeSequence> numbers = rangeSequence(node->iterable)) {
        iterations = numbers->sizeHint();
        for (Value item; numbers->next(item);) runBody(item);
        return;
    }
    Value iterable = eval(node->iterable);
    if (iterable.kind != ValueKind::List) {
        fail(node->iterable->range,
             fmt::format("'for' needs a list or a range, not {}", typeName(iterable)));
    }
    iterations = iterable.list->size();
    // The list is immutable, so iterating it while the body runs is safe.
    for (const Value& item : *iterable.list) runBody(item);
}

void Interpreter::reserveLike(size_t entitiesBefore, size_t materialsBefore, uint64_t remaining) {
    // Room for `remaining` more iterations like the first: the vectors are then not regrown
    // while the loop runs, each regrowth copying everything built so far into fresh memory.
    // Never past the entity limit nor 1 GB a vector: a loop that stops early or adds only
    // once wastes address space, not memory.
    auto reserveFor = [&](auto& items, size_t before) {
        using Item = typename std::remove_reference_t<decltype(items)>::value_type;
        const uint64_t cap = std::min<uint64_t>(options_.limits.maxEntities, (uint64_t{1} << 30) / sizeof(Item));
        const uint64_t added = items.size() - before;
        if (added == 0 || items.size() >= cap) return items.capacity();
        const uint64_t wanted = remaining > (cap - items.size()) / added ? cap : items.size() + added * remaining;
        items.reserve(static_cast<size_t>(wanted));
        return items.capacity();
    };
    try {
        const size_t entities = reserveFor(scene_.entities, entitiesBefore);
        entityInfo_.reserve(entities);
        reserveFor(scene_.materials, materialsBefore);
    } catch (const std::bad_alloc&) {
        // The vectors grow as they go instead.
    }
}

void Interpreter::execScene(const SceneStmt* node) {
    EmitMode savedMode = emitMode_;
    emitMode_ = EmitMode::Scene;
    execRecovering(node->statements);
    emitMode_ = savedMode;
}

void Interpreter::execRecovering(std::span<Node* const> statements) {
    const Node* enclosing = statement_;
    for (const Node* statement : statements) {
        statement_ = statement;
        try {
            exec(statement);
        } catch (const EvalError&) {
            if (stopped_) throw;
            poisonAssigned(statement);
        }
    }
    statement_ = enclosing;
}

void Interpreter::poisonAssigned(const Node* failed) {
    auto poison = [&](const AssignExpr* assign, bool always) {
        const Resolution& r = assign->resolution;
        if (r.binding != Binding::Global) return;
        Value& slot = globalValues_[r.slot];
        if (always || slot.kind == ValueKind::Unset) slot.kind = ValueKind::Poisoned;
    };
    if (failed->kind == NodeKind::Include) {
        // What the file would have defined is unknown: none of the names still unset is
        // reported again.
        for (Value& slot : globalValues_)
            if (slot.kind == ValueKind::Unset) slot.kind = ValueKind::Poisoned;
        return;
    }
    if (failed->kind == NodeKind::Assign) poison(static_cast<const AssignExpr*>(failed), true);
    // Assignments inside a failed loop or if that never ran (a macro's are its own).
    std::vector<const Node*> pending{failed};
    while (!pending.empty()) {
        const Node* node = pending.back();
        pending.pop_back();
        if (node->kind == NodeKind::Macro) continue;
        if (node->kind == NodeKind::Assign) poison(static_cast<const AssignExpr*>(node), false);
        forEachChild(const_cast<Node*>(node), [&](Node* child) { pending.push_back(child); });
    }
}

bool Interpreter::condition(const Expr* node, std::string_view what) {
    Value value = eval(node);
    if (value.kind != ValueKind::Bool) {
        fail(node->range, fmt::format("the condition of '{}' must be a bool, not {}", what,
                                      typeName(value)));
    }
    return value.b;
}

void Interpreter::leftOutsideScene(const Value& entity, const Node* statement) {
    warnOnce(WarningKind::OutsideScene, statement->range,
             fmt::format("this {} is not drawn: it is outside every Scene block; write it inside "
                         "Scene {{ }}",
                         entityTypeName(entity)));
    // Its parts need no "never drawn" warning of their own.
    std::vector<uint32_t> pending{entity.index};
    while (!pending.empty()) {
        const uint32_t index = pending.back();
        pending.pop_back();
        if (entityInfo_[index].outsideScene) continue;
        entityInfo_[index].outsideScene = true;
        scene::forEachPart(scene_.entities[index],
                           [&](int32_t part) { pending.push_back(static_cast<uint32_t>(part)); });
    }
}

void Interpreter::emit(const Value& value, const Node* where) {
    if (emitMode_ == EmitMode::Scene) {
        draw(value, where);
        return;
    }
    // In a macro body: entities and lists made only of entities are emitted.
    if (value.kind == ValueKind::Entity) {
        emitted_->push_back(value);
    } else if (value.kind == ValueKind::List) {
        std::vector<Value> flat;
        if (!flattenEntities(value, flat)) emitted_->insert(emitted_->end(), flat.begin(), flat.end());
    }
}

const Value* Interpreter::flattenEntities(const Value& list, std::vector<Value>& out) {
    // Depth-first in source order, without recursion: lists can nest deeply.
    std::vector<std::pair<const std::vector<Value>*, size_t>> stack{{list.list, 0}};
    while (!stack.empty()) {
        auto& [items, next] = stack.back();
        if (next == items->size()) {
            stack.pop_back();
            continue;
        }
        const Value& item = (*items)[next++];
        if (item.kind == ValueKind::List) {
            stack.emplace_back(item.list, 0);
        } else if (item.kind == ValueKind::Entity) {
            out.push_back(item);
        } else {
            return &item;
        }
    }
    return nullptr;
}

void Interpreter::draw(const Value& value, const Node* where) {
    switch (value.kind) {
    case ValueKind::Entity:
        scene_.drawn.push_back(static_cast<int32_t>(value.index));
        drawnAt_.push_back(where->range);
        return;
    case ValueKind::List: {
        std::vector<Value> entities;
        if (const Value* other = flattenEntities(value, entities)) {
            fail(where->range, fmt::format("cannot draw a list holding {}; only entities can be drawn",
                                           typeName(*other)));
        }
        for (const Value& entity : entities) draw(entity, where);
        return;
    }
    case ValueKind::None:
    case ValueKind::Unset: return;
    default:
        warnOnce(WarningKind::ValueNotDrawn, where->range,
                             fmt::format("this {} is not drawn; only entities are",
                                         typeName(value)));
        return;
    }
}

void Interpreter::checkStoredPrimitives() {
    const uint64_t limit = options_.limits.render.maxPrimitives;
    auto storage = std::make_shared<const scene::SceneStorage>(scene::storageOf(scene_));
    scene_.storage = storage;
    for (size_t i = 0; i < storage->storedAfter.size(); ++i) {
        if (scene::saturatingAdd(storage->storedAfter[i], meshTriangles_) <= limit) continue;
        failAtLimit(drawnAt_[i],
                    fmt::format("the scene stores more than {} primitives (copies count each time; "
                                "an entity of {} or more drawn again is stored once); raise the "
                                "limit with --max-primitives",
                                limit, scene::kMinInstancePrimitives));
    }
}

const FileAccess& Interpreter::fileAccess() {
    if (!fileAccess_) {
        fileAccess_.emplace(scriptFileAccess(folderOf(compilation_.sources.file(0).path()),
                                             options_.includes, options_.assetRoots,
                                             options_.access));
    }
    return *fileAccess_;
}

void Interpreter::execInclude(const IncludeStmt* node) {
    std::string name(node->path->value);
    const SourceFile& including = compilation_.sources.file(node->range.file);
    const fs::path folder = folderOf(including.path());
    const FoundInclude include = options_.includes.find(name, folder, fileAccess());
    const fs::path& found = include.path;
    if (!include.refusal.empty() && found.empty())
        fail(node->path->range, fmt::format("cannot include \"{}\": it {}", name, include.refusal));
    if (found.empty() && fs::path(name).is_absolute())
        fail(node->path->range, fmt::format("cannot find include file \"{}\"", name));
    if (found.empty()) {
        std::string folders;
        for (const fs::path& dir : options_.includes.folders(folder))
            folders += fmt::format("\n  {}", dir.lexically_normal().string());
        std::string_view instead = povray::includeReplacement(fs::path(name).filename().string());
        std::string hint =
            instead.empty()
                ? ""
                : fmt::format(
                      "; did you mean \"{}\"? (the standard library's, in place of POV-Ray's)",
                      instead);
        fail(node->path->range,
             fmt::format("cannot find include file \"{}\"{}; searched:{}", name, hint, folders));
    }
    std::error_code error;
    std::string canonical = fs::weakly_canonical(found, error).string();
    for (size_t i = 0; i < includeStack_.size(); ++i) {
        if (includeStack_[i] != canonical) continue;
        std::string chain;
        for (size_t j = i; j < includeStack_.size(); ++j) chain += includeStack_[j] + " -> ";
        fail(node->range, fmt::format("include cycle: {}{}", chain, canonical));
    }
    for (const std::string& done : includedFiles_) {
        if (done == canonical) return; // include-once
    }

    std::optional<std::string> text = readFile(found.string());
    if (!text) fail(node->path->range, fmt::format("cannot read include file \"{}\"", found.string()));
    // Its lines would be quoted in diagnostics: a file that is not text is refused unseen.
    if (!isScriptText(*text))
        fail(node->path->range, fmt::format("cannot include \"{}\": it is not a CRT script (it "
                                            "holds NUL bytes or invalid UTF-8)",
                                            name));

    uint32_t fileIndex = compilation_.sources.add(found.lexically_normal().string(), std::move(*text));
    size_t errorsBefore = diagnostics_.errorCount();
    Script script = parse(compilation_.sources.file(fileIndex), fileIndex, *compilation_.arena,
                          diagnostics_);
    auto failOnErrors = [&] {
        if (diagnostics_.errorCount() > errorsBefore) {
            fail(node->range, fmt::format("included file \"{}\" has errors", name));
        }
    };
    failOnErrors(); // as for the main script: no resolving or running with syntax errors
    animated_ |= resolve(script, globals_, diagnostics_, false).readsTime;
    failOnErrors();
    globalValues_.resize(globals_.size());
    includedFiles_.push_back(canonical);
    includeStack_.push_back(canonical);
    // An included file runs at the top level, whatever the caller was doing.
    EmitMode savedMode = emitMode_;
    std::vector<Value>* savedEmitted = emitted_;
    if (emitMode_ == EmitMode::Macro) emitMode_ = EmitMode::None;
    auto leave = [&] {
        emitMode_ = savedMode;
        emitted_ = savedEmitted;
        includeStack_.pop_back();
    };
    try {
        execStatements(script.items);
    } catch (const EvalError&) {
        leave();
        throw;
    }
    leave();
}

// ---------------------------------------------------------------- variables

Value Interpreter::evalVar(const VarExpr* node) {
    const Resolution& r = node->resolution;
    const Value* slot = nullptr;
    switch (r.binding) {
    case Binding::Local: slot = &locals_[r.slot]; break;
    case Binding::Global: slot = &globalValues_[r.slot]; break; // sized after every resolve
    case Binding::Builtin: return prelude_[r.slot];
    case Binding::Enclosing: {
        Frame* frame = enclosing_;
        for (uint16_t d = 1; d < r.depth; ++d) frame = frame->enclosing;
        slot = &frame->slots[r.slot];
        break;
    }
    case Binding::Parameter: // only in a Function's body, which is compiled, not evaluated
    case Binding::Unresolved: break;
    }
    if (!slot || slot->kind <= ValueKind::Poisoned) unboundVariable(node);
    return *slot;
}

void Interpreter::unboundVariable(const VarExpr* node) {
    const Resolution& r = node->resolution;
    if (r.binding == Binding::Global && globalValues_[r.slot].kind == ValueKind::Poisoned) {
        throw EvalError{}; // its error is reported where it was made
    }
    const GlobalTable::Entry* entry = globals_.find(node->name);
    if (r.binding == Binding::Local || r.binding == Binding::Enclosing || (entry && entry->assigned)) {
        fail(node->range, fmt::format("variable '{}' is read before it is assigned", node->name));
    }
    std::vector<std::string_view> names;
    for (uint32_t i = 0; i < globals_.size(); ++i) {
        if (globals_.entry(i).assigned) names.push_back(globals_.entry(i).name);
    }
    for (uint32_t i = 0; i < preludeSize(); ++i) names.push_back(preludeName(i));
    std::string suggestion = closestMatch(node->name, names);
    Diagnostic& d = diagnostics_.error(
        node->range, suggestion.empty()
                         ? fmt::format("undefined variable '{}'", node->name)
                         : fmt::format("undefined variable '{}'; did you mean '{}'?", node->name,
                                       suggestion));
    if (!suggestion.empty()) d.fixits.push_back({node->range, suggestion});
    throw EvalError{};
}

// ---------------------------------------------------------------- macros

Value Interpreter::evalMacro(const MacroExpr* node) {
    Closure& closure = closures_.emplace_back(Closure{node, heapFrame_});
    Value value;
    value.kind = ValueKind::Macro;
    value.closure = &closure;
    return value;
}

Value Interpreter::callMacro(const Closure* closure, const CallExpr* site,
                             std::span<const Value> args) {
    const MacroExpr* macro = closure->macro;
    if (args.size() != macro->params.size()) {
        fail(site->range, fmt::format("this macro takes {} argument{}, but {} {} given",
                                      macro->params.size(), macro->params.size() == 1 ? "" : "s",
                                      args.size(), args.size() == 1 ? "was" : "were"));
    }
    step(site->range);
    if (depth_ >= options_.limits.maxDepth) {
        failAtLimit(site->range,
                    fmt::format("macro calls nested deeper than {}; raise the limit with "
                                "--max-depth",
                                options_.limits.maxDepth));
    }

    // Save the caller's frame; stack frames are found again by offset after the call,
    // since the stack may grow and move.
    Value* savedLocals = locals_;
    bool savedOnStack = locals_ && !heapFrame_;
    size_t savedBase = savedOnStack ? static_cast<size_t>(locals_ - stack_.data()) : 0;
    Frame* savedHeapFrame = heapFrame_;
    Frame* savedEnclosing = enclosing_;
    EmitMode savedMode = emitMode_;
    std::vector<Value>* savedEmitted = emitted_;

    size_t base = stack_.size();
    if (macro->capturesFrame) {
        Frame& frame = frames_.emplace_back(Frame{std::vector<Value>(macro->localCount), closure->enclosing});
        heapFrame_ = &frame;
        locals_ = frame.slots.data();
    } else {
        stack_.resize(base + macro->localCount);
        heapFrame_ = nullptr;
        locals_ = stack_.data() + base;
    }
    for (size_t i = 0; i < args.size(); ++i) locals_[i] = args[i];
    enclosing_ = closure->enclosing;

    // Each call depth reuses one buffer for what its macro emits: most calls emit one
    // entity, and a fresh vector per call cost an allocation.
    if (emitBuffers_.size() <= depth_) emitBuffers_.resize(depth_ + 1);
    std::vector<Value>& emitted = emitBuffers_[depth_];
    emitted.clear();
    emitMode_ = EmitMode::Macro;
    emitted_ = &emitted;
    ++depth_;

    Value last = Value::none();
    const auto& statements = macro->body->statements;
    const Node* callingStatement = statement_;
    const size_t diagnosticsBefore = diagnostics_.items().size();
    auto leave = [&] {
        statement_ = callingStatement;
        --depth_;
        if (!macro->capturesFrame) stack_.resize(base);
        locals_ = savedOnStack ? stack_.data() + savedBase : savedLocals;
        heapFrame_ = savedHeapFrame;
        enclosing_ = savedEnclosing;
        emitMode_ = savedMode;
        emitted_ = savedEmitted;
    };
    try {
        for (size_t i = 0; i < statements.size(); ++i) {
            statement_ = statements[i];
            Value value = exec(statements[i]);
            if (i + 1 == statements.size() && isExpression(statements[i]) &&
                statements[i]->kind != NodeKind::Assign) {
                last = value;
            }
        }
    } catch (const EvalError&) {
        noteCallSite(diagnosticsBefore, site);
        leave();
        throw;
    } catch (const std::bad_alloc&) {
        reportOutOfMemory();
        noteCallSite(diagnosticsBefore, site);
        leave();
        throw EvalError{};
    }
    leave();
    return macroResult(emitted, last, site);
}

void Interpreter::noteCallSite(size_t diagnosticsBefore, const CallExpr* site) {
    // Every run-time error inside a macro gets a note at each call site of the chain,
    // innermost first, whichever code raised it.
    std::vector<Diagnostic>& items = diagnostics_.items();
    for (size_t i = diagnosticsBefore; i < items.size(); ++i) {
        if (items[i].severity == Severity::Error)
            addCallNote(items[i], {site->range, "in the macro called here"});
    }
}

Value Interpreter::macroResult(const std::vector<Value>& emitted, const Value& last, const CallExpr* site) {
    if (emitted.empty()) return last;
    if (emitted.size() == 1) return emitted.front();
    scene::GroupNode group;
    bool solid = true;
    group.members.reserve(emitted.size());
    for (const Value& member : emitted) {
        group.members.push_back(static_cast<int32_t>(member.index));
        solid = solid && scene_.entities[member.index].solid;
    }
    scene::EntityDesc entity{std::move(group), -1, solid, span(site->range)};
    int32_t index = addEntity(std::move(entity), EntityInfo{site->range, ObjectType::Count, false});
    return Value::object(ValueKind::Entity, ObjectType::Count, static_cast<uint32_t>(index));
}

// ---------------------------------------------------------------- compile

Compilation compile(std::string path, std::string text, const EvalOptions& options,
                    bool evaluate) {
    Compilation c;
    c.sources.add(std::move(path), std::move(text));
    runOnLargeStack([&] {
        c.main = parse(c.sources.file(0), 0, *c.arena, c.diagnostics, &c.comments);
        if (c.diagnostics.hasErrors()) {
            // Not evaluated; but its names are resolved on what the parser recovered, so that
            // an unknown attribute or type is reported with the syntax errors. (Its warnings
            // would be about what the broken statements hid.)
            DiagnosticBag names;
            resolve(c.main, c.globals, names, true);
            for (Diagnostic& d : names.items())
                if (d.severity == Severity::Error) c.diagnostics.add(std::move(d));
            c.diagnostics.sortByPosition(); // all of them in source order
            return;
        }
        Interpreter(c, options).run(evaluate);
    });
    if (evaluate) evaluateMotionSteps(c, options);
    return c;
}

void evaluate(Compilation& compilation, const EvalOptions& options) {
    runOnLargeStack([&] { Interpreter(compilation, options).evaluateResolved(); });
    evaluateMotionSteps(compilation, options);
}

Compilation compileFile(const std::string& path, const EvalOptions& options, bool evaluate) {
    std::optional<std::string> text = readFile(path);
    if (!text) {
        Compilation c;
        c.diagnostics.error({1u << 31, 0, 0}, fmt::format("cannot read '{}'", path));
        return c;
    }
    return compile(path, std::move(*text), options, evaluate);
}

} // namespace crt::lang
