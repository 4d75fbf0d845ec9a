// The built-in functions of spec §4 and str().
#include "builtins.hpp"

#include "interpreter_impl.hpp"
#include "value_format.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <optional>
#include <ostream>
#include <utility>

namespace crt::lang {

namespace {

/// The text of a value that is not a list nor an object, or nothing for those.
std::optional<std::string> plainText(const Value& value) {
    switch (value.kind) {
    case ValueKind::Unset:
    case ValueKind::Poisoned:
    case ValueKind::None: return "none";
    case ValueKind::Int: return fmt::format("{}", value.i);
    case ValueKind::Float: return formatFloat(value.f);
    case ValueKind::Bool: return value.b ? "true" : "false";
    case ValueKind::String: return *value.s;
    case ValueKind::Vec3:
        return fmt::format("vec3({}, {}, {})", formatFloat(value.v[0]), formatFloat(value.v[1]),
                           formatFloat(value.v[2]));
    case ValueKind::Color:
        if (value.v[3] == 1.0) {
            return fmt::format("rgb({}, {}, {})", formatFloat(value.v[0]), formatFloat(value.v[1]),
                               formatFloat(value.v[2]));
        }
        return fmt::format("rgba({}, {}, {}, {})", formatFloat(value.v[0]), formatFloat(value.v[1]),
                           formatFloat(value.v[2]), formatFloat(value.v[3]));
    default: return std::nullopt;
    }
}

} // namespace

std::string Interpreter::entityTypeName(const Value& entity) const {
    if (entity.objectType != ObjectType::Count) return typeName(entity);
    // A moved CSG result or group is named after what was moved.
    const scene::Shape* moved = &scene_.entities[entity.index].shape;
    while (auto* transform = std::get_if<scene::TransformNode>(moved)) {
        moved = &scene_.entities[static_cast<size_t>(transform->child)].shape;
    }
    if (auto* csg = std::get_if<scene::CsgNode>(moved)) return scene::csgOpName(csg->op);
    if (std::holds_alternative<scene::InverseNode>(*moved)) return "Inverse";
    return std::holds_alternative<scene::GroupNode>(*moved) ? "Group" : typeName(entity);
}

std::string Interpreter::objectText(const Value& value) const {
    switch (value.kind) {
    case ValueKind::Macro: {
        LineColumn at = compilation_.sources.file(value.closure->macro->range.file)
                            .lineColumn(value.closure->macro->range.begin);
        return fmt::format("<macro {}:{}>", at.line, at.column);
    }
    case ValueKind::Builtin: return fmt::format("<function {}>", builtinFunctions()[value.index].name);
    case ValueKind::Function: {
        const scene::SourceSpan& where = functions_[value.index].source;
        return fmt::format("<Function {}:{}>", where.line, where.column);
    }
    case ValueKind::Modifiers: {
        const SourceRange& written = value.modifiers->range;
        LineColumn at = compilation_.sources.file(written.file).lineColumn(written.begin);
        return fmt::format("<modifiers {}:{}>", at.line, at.column);
    }
    default: break;
    }
    // Objects: their type and where they were made.
    scene::SourceSpan where;
    std::string type = typeName(value);
    switch (value.kind) {
    case ValueKind::Entity:
        where = scene_.entities[value.index].source;
        type = entityTypeName(value);
        break;
    case ValueKind::Material: where = scene_.materials[value.index].source; break;
    case ValueKind::Texture: where = scene_.textures[value.index].source; break;
    case ValueKind::Light: where = lights_[value.index].source; break;
    case ValueKind::Camera: where = cameras_[value.index].source; break;
    case ValueKind::Background: where = backgrounds_[value.index].source; break;
    case ValueKind::Fog: where = fogs_[value.index].source; break;
    case ValueKind::Medium: where = scene_.media[value.index].source; break;
    case ValueKind::BlobComponent: where = blobComponents_[value.index].source; break;
    case ValueKind::Spline: where = splines_[value.index].source; break;
    default: break;
    }
    return fmt::format("<{} {}:{}>", type, where.line, where.column);
}

bool Interpreter::appendText(std::string& out, const Value& value, size_t maxBytes,
                             const std::function<void()>& onItems) const {
    // Without recursion, and appending in place: lists nest as deep as a loop makes them, and
    // building each item's text apart made nesting quadratic.
    std::vector<std::pair<const std::vector<Value>*, size_t>> open;
    auto appendItem = [&](const Value& item, bool inList) {
        if (item.kind == ValueKind::List) {
            out += '[';
            open.emplace_back(item.list, 0);
        } else if (item.kind == ValueKind::String && inList) {
            out += lang::quoted(*item.s);
        } else if (std::optional<std::string> text = plainText(item)) {
            out += *text;
        } else {
            out += objectText(item);
        }
    };
    appendItem(value, false);
    size_t items = 0;
    while (!open.empty() && out.size() <= maxBytes) {
        if (++items % kTextItemsPerCall == 0 && onItems) onItems();
        auto& [items, next] = open.back();
        if (next == items->size()) {
            out += ']';
            open.pop_back();
            continue;
        }
        if (next > 0) out += ", ";
        appendItem((*items)[next++], true);
    }
    return out.size() <= maxBytes;
}

std::string Interpreter::str(const Value& value) {
    // The text of a list holding a list many times grows exponentially with the nesting:
    // each item written counts against the step limit (and the time budget), and the
    // string, which may double as it grows, against the memory limit.
    std::string out;
    const uint64_t room = options_.limits.maxMemory - std::min(memoryUsed_, options_.limits.maxMemory);
    const size_t maxBytes = static_cast<size_t>(std::min<uint64_t>(room / 2, SIZE_MAX));
    auto countWork = [&] {
        steps_ += kTextItemsPerCall; // an item's text takes about as long as a loop iteration
        if (steps_ >= nextStepCheck_) checkSteps(statement_ ? statement_->range : SourceRange{});
    };
    if (!appendText(out, value, maxBytes, countWork)) checkRoom(room + 1);
    return out;
}

namespace {

[[noreturn]] void argError(BuiltinCall& call, size_t index, std::string_view wanted) {
    call.interpreter.fail(call.interpreter.argRange(call.site, index),
                          fmt::format("argument {} must be {}, not {}", index + 1, wanted,
                                      typeName(call.args[index])));
}

double number(BuiltinCall& call, size_t index) {
    const Value& v = call.args[index];
    if (!v.isNumber()) argError(call, index, "a number");
    return v.asDouble();
}

bool allInts(BuiltinCall& call) {
    for (const Value& v : call.args) {
        if (v.kind != ValueKind::Int) return false;
    }
    return true;
}

/// A float result, checked for a domain error (a NaN from finite arguments).
Value checked(BuiltinCall& call, double result, std::string_view name) {
    if (std::isnan(result)) {
        bool argsFinite = true;
        for (const Value& v : call.args) argsFinite = argsFinite && !(v.isNumber() && std::isnan(v.asDouble()));
        if (argsFinite) {
            call.interpreter.fail(call.site->range, fmt::format("{}: argument out of its domain", name));
        }
    }
    return Value::number(result);
}

Value toInt(BuiltinCall& call, double x) {
    if (!std::isfinite(x) || x >= 9.2233720368547758e18 || x < -9.2233720368547758e18) {
        call.interpreter.fail(call.site->range, fmt::format("{} does not fit in an int", formatFloat(x)));
    }
    return Value::integer(static_cast<int64_t>(x));
}

glm::dvec3 vector(BuiltinCall& call, size_t index) {
    const Value& v = call.args[index];
    if (v.kind != ValueKind::Vec3) argError(call, index, "a vec3");
    return {v.v[0], v.v[1], v.v[2]};
}

Value fromVector(glm::dvec3 v) { return Value::vec3(v.x, v.y, v.z); }

// The one-argument math built-ins, listed once: each gets its function on numbers (m_name,
// what unaryMath() returns) and its built-in (b_name).
#define CRT_MATH1_BUILTINS(X)                                                                  \
    X(sin, std::sin(x))                                                                        \
    X(cos, std::cos(x))                                                                        \
    X(tan, std::tan(x))                                                                        \
    X(exp, std::exp(x))                                                                        \
    X(radians, x * std::numbers::pi / 180.0)                                                   \
    X(degrees, x * 180.0 / std::numbers::pi)                                                   \
    X(atan, std::atan(x))

#define MATH1(name, expr)                                                                      \
    double m_##name(double x) { return (expr); }                                               \
    Value b_##name(BuiltinCall& call) { return checked(call, m_##name(number(call, 0)), #name); }
CRT_MATH1_BUILTINS(MATH1)
#undef MATH1

Value b_vec3(BuiltinCall& call) {
    double x = number(call, 0), y = number(call, 1), z = number(call, 2);
    return Value::vec3(x, y, z);
}
Value b_rgb(BuiltinCall& call) {
    double r = number(call, 0), g = number(call, 1), b = number(call, 2);
    return Value::color(r, g, b);
}
Value b_rgba(BuiltinCall& call) {
    double r = number(call, 0), g = number(call, 1), b = number(call, 2), a = number(call, 3);
    return Value::color(r, g, b, a);
}

Value b_asin(BuiltinCall& call) {
    double x = number(call, 0);
    if (x < -1 || x > 1) call.interpreter.fail(call.site->range, "asin: argument must be in [-1, 1]");
    return Value::number(std::asin(x));
}
Value b_acos(BuiltinCall& call) {
    double x = number(call, 0);
    if (x < -1 || x > 1) call.interpreter.fail(call.site->range, "acos: argument must be in [-1, 1]");
    return Value::number(std::acos(x));
}
Value b_sqrt(BuiltinCall& call) {
    double x = number(call, 0);
    if (x < 0) call.interpreter.fail(call.site->range, "sqrt of a negative number");
    return Value::number(std::sqrt(x));
}
Value b_log(BuiltinCall& call) {
    double x = number(call, 0);
    if (x <= 0) call.interpreter.fail(call.site->range, "log of a number that is not positive");
    return Value::number(std::log(x));
}
Value b_atan2(BuiltinCall& call) {
    double y = number(call, 0);
    return Value::number(std::atan2(y, number(call, 1)));
}
Value b_pow(BuiltinCall& call) {
    double x = number(call, 0);
    return checked(call, std::pow(x, number(call, 1)), "pow");
}

Value b_rand(BuiltinCall& call) {
    double a = number(call, 0);
    double b = number(call, 1);
    double u = static_cast<double>(call.interpreter.nextRandom() >> 11) * 0x1.0p-53;
    return Value::number(std::min(a, b) + u * std::abs(b - a));
}

Value b_abs(BuiltinCall& call) {
    if (call.args[0].kind == ValueKind::Int) {
        if (call.args[0].i == std::numeric_limits<int64_t>::min()) {
            call.interpreter.fail(call.site->range, "integer overflow in abs");
        }
        return Value::integer(std::abs(call.args[0].i));
    }
    return Value::number(std::abs(number(call, 0)));
}

Value minMax(BuiltinCall& call, bool wantMax) {
    for (size_t i = 0; i < call.args.size(); ++i) number(call, i);
    if (allInts(call)) {
        int64_t best = call.args[0].i;
        for (const Value& v : call.args) best = wantMax ? std::max(best, v.i) : std::min(best, v.i);
        return Value::integer(best);
    }
    double best = call.args[0].asDouble();
    for (const Value& v : call.args) best = wantMax ? std::max(best, v.asDouble()) : std::min(best, v.asDouble());
    return Value::number(best);
}
Value b_min(BuiltinCall& call) { return minMax(call, false); }
Value b_max(BuiltinCall& call) { return minMax(call, true); }

Value b_clamp(BuiltinCall& call) {
    double x = number(call, 0);
    double lo = number(call, 1);
    double hi = number(call, 2);
    if (lo > hi) call.interpreter.fail(call.site->range, "clamp: the lower bound is above the upper bound");
    if (allInts(call)) return Value::integer(std::clamp(call.args[0].i, call.args[1].i, call.args[2].i));
    return Value::number(std::clamp(x, lo, hi));
}

Value b_floor(BuiltinCall& call) { return toInt(call, std::floor(number(call, 0))); }
Value b_ceil(BuiltinCall& call) { return toInt(call, std::ceil(number(call, 0))); }
Value b_round(BuiltinCall& call) { return toInt(call, std::round(number(call, 0))); }

Value b_mix(BuiltinCall& call) {
    double t = number(call, 2);
    const Value& a = call.args[0];
    const Value& b = call.args[1];
    if (a.isNumber() && b.isNumber()) return Value::number(a.asDouble() + (b.asDouble() - a.asDouble()) * t);
    if ((a.kind == ValueKind::Vec3 || a.kind == ValueKind::Color) && a.kind == b.kind) {
        Value r = a;
        for (int k = 0; k < 4; ++k) r.v[k] = a.v[k] + (b.v[k] - a.v[k]) * t;
        return r;
    }
    call.interpreter.fail(call.site->range,
                          fmt::format("mix needs two numbers, two vec3 or two colours, not {} and {}",
                                      typeName(a), typeName(b)));
}

Value b_length(BuiltinCall& call) { return Value::number(glm::length(vector(call, 0))); }
Value b_normalize(BuiltinCall& call) {
    glm::dvec3 v = vector(call, 0);
    double length = glm::length(v);
    if (length == 0 || !std::isfinite(length)) call.interpreter.fail(call.site->range, "normalize of a zero vector");
    return fromVector(v / length);
}
// Arguments are read one statement at a time, so the first bad one is the one reported.
Value b_dot(BuiltinCall& call) {
    glm::dvec3 a = vector(call, 0);
    return Value::number(glm::dot(a, vector(call, 1)));
}
Value b_cross(BuiltinCall& call) {
    glm::dvec3 a = vector(call, 0);
    return fromVector(glm::cross(a, vector(call, 1)));
}

Value b_len(BuiltinCall& call) {
    const Value& v = call.args[0];
    if (v.kind == ValueKind::List) return Value::integer(static_cast<int64_t>(v.list->size()));
    if (v.kind == ValueKind::String) return Value::integer(codePointCount(*v.s));
    argError(call, 0, "a list or a string");
}

Value b_range(BuiltinCall& call) {
    RangeSequence sequence(call);
    std::vector<Value> items;
    items.reserve(static_cast<size_t>(sequence.sizeHint()));
    for (Value item; sequence.next(item);) items.push_back(item);
    return Value::listOf(call.interpreter.newList(std::move(items)));
}

Value b_str(BuiltinCall& call) {
    return Value::string(call.interpreter.newString(call.interpreter.str(call.args[0])));
}

Value b_print(BuiltinCall& call) {
    std::string line;
    for (size_t i = 0; i < call.args.size(); ++i) {
        if (i) line += ' ';
        line += call.interpreter.str(call.args[i]);
    }
    line += '\n';
    call.interpreter.print(line);
    return Value::none();
}

Value b_spline(BuiltinCall& call) {
    const Value& s = call.args[0];
    if (s.kind != ValueKind::Spline) argError(call, 0, "a Spline");
    return fromVector(call.interpreter.splineAt(s.index, number(call, 1)));
}

constexpr BuiltinInfo kBuiltins[] = {
    {"vec3", 3, 3, "vec3(x, y, z)", "A 3D vector.", b_vec3},
    {"rgb", 3, 3, "rgb(r, g, b)", "A linear colour; components may exceed 1.", b_rgb},
    {"rgba", 4, 4, "rgba(r, g, b, a)", "A linear colour with alpha.", b_rgba},
    {"sin", 1, 1, "sin(x)", "Sine of x radians.", b_sin},
    {"cos", 1, 1, "cos(x)", "Cosine of x radians.", b_cos},
    {"tan", 1, 1, "tan(x)", "Tangent of x radians.", b_tan},
    {"rand", 2, 2, "rand(a, b)", "A deterministic random float in [min(a,b), max(a,b)).", b_rand},
    {"asin", 1, 1, "asin(x)", "Arc sine, radians; x in [-1, 1].", b_asin},
    {"acos", 1, 1, "acos(x)", "Arc cosine, radians; x in [-1, 1].", b_acos},
    {"atan", 1, 1, "atan(x)", "Arc tangent, radians.", b_atan},
    {"atan2", 2, 2, "atan2(y, x)", "Angle of the point (x, y), radians.", b_atan2},
    {"sqrt", 1, 1, "sqrt(x)", "Square root; x >= 0.", b_sqrt},
    {"pow", 2, 2, "pow(x, y)", "x to the power y.", b_pow},
    {"exp", 1, 1, "exp(x)", "e to the power x.", b_exp},
    {"log", 1, 1, "log(x)", "Natural logarithm; x > 0.", b_log},
    {"abs", 1, 1, "abs(x)", "Absolute value (an int for an int).", b_abs},
    {"floor", 1, 1, "floor(x)", "Largest int <= x.", b_floor},
    {"ceil", 1, 1, "ceil(x)", "Smallest int >= x.", b_ceil},
    {"round", 1, 1, "round(x)", "Nearest int, halves away from zero.", b_round},
    {"min", 1, -1, "min(a, b, ...)", "Smallest argument (an int if all are ints).", b_min},
    {"max", 1, -1, "max(a, b, ...)", "Largest argument (an int if all are ints).", b_max},
    {"clamp", 3, 3, "clamp(x, lo, hi)", "x limited to [lo, hi].", b_clamp},
    {"mix", 3, 3, "mix(a, b, t)", "a + (b - a) * t, for numbers, vec3 or colours.", b_mix},
    {"radians", 1, 1, "radians(degrees)", "Degrees to radians.", b_radians},
    {"spline", 2, 2, "spline(s, t)",
     "The point of Spline s at t, between its first and last times (0 and 1 by default); "
     "clamped to its ends outside them.",
     b_spline},
    {"degrees", 1, 1, "degrees(radians)", "Radians to degrees.", b_degrees},
    {"length", 1, 1, "length(v)", "Length of a vec3.", b_length},
    {"normalize", 1, 1, "normalize(v)", "v scaled to length 1; v must not be zero.", b_normalize},
    {"dot", 2, 2, "dot(a, b)", "Dot product of two vec3.", b_dot},
    {"cross", 2, 2, "cross(a, b)", "Cross product of two vec3.", b_cross},
    {"len", 1, 1, "len(x)", "Length of a list or a string.", b_len},
    {"range", 1, 3, "range(n) | range(a, b) | range(a, b, step)",
     "The list a, a+step, ... below b (above b for a negative step).", b_range},
    {"str", 1, 1, "str(x)", "x as text.", b_str},
    {"print", 0, -1, "print(a, b, ...)",
     "Writes its arguments, separated by spaces, to standard output.", b_print},
};

constexpr uint32_t kFunctionCount = static_cast<uint32_t>(std::size(kBuiltins));

/// The one-argument math built-ins by name, for unaryMath().
#define MATH1_ENTRY(name, expr) {#name, m_##name},
constexpr std::pair<std::string_view, UnaryMath> kUnaryMath[] = {CRT_MATH1_BUILTINS(MATH1_ENTRY)};
#undef MATH1_ENTRY
#undef CRT_MATH1_BUILTINS

/// unaryMath() per built-in index, matched by name when compiled.
constexpr std::array<UnaryMath, kFunctionCount> kUnaryMathByIndex = [] {
    std::array<UnaryMath, kFunctionCount> table{};
    for (uint32_t i = 0; i < kFunctionCount; ++i) {
        for (const auto& [name, function] : kUnaryMath) {
            if (kBuiltins[i].name == name) table[i] = function;
        }
    }
    return table;
}();

} // namespace

RangeSequence::RangeSequence(BuiltinCall& call) {
    for (size_t i = 0; i < call.args.size(); ++i) number(call, i);
    ints_ = allInts(call);
    const auto& args = call.args;
    const size_t n = args.size();
    start_ = n == 1 ? 0.0 : args[0].asDouble();
    stop_ = n == 1 ? args[0].asDouble() : args[1].asDouble();
    stride_ = n == 3 ? args[2].asDouble() : 1.0;
    if (stride_ == 0) call.interpreter.fail(call.interpreter.argRange(call.site, 2), "range: the step must not be zero");
    const uint64_t limit = call.interpreter.limits().maxEntities;
    if (ints_) {
        const int64_t a = n == 1 ? 0 : args[0].i;
        const int64_t b = n == 1 ? args[0].i : args[1].i;
        const int64_t s = n == 3 ? args[2].i : 1;
        // Counted first, so an oversized range fails before anything runs.
        __int128 count = s > 0 ? (b > a ? (static_cast<__int128>(b) - a + s - 1) / s : 0)
                               : (a > b ? (static_cast<__int128>(a) - b + (-static_cast<__int128>(s)) - 1) / -static_cast<__int128>(s) : 0);
        if (count > static_cast<__int128>(limit)) {
            call.interpreter.fail(call.site->range,
                                  fmt::format("range has {} items, more than the limit of {}; raise it "
                                              "with --max-entities",
                                              static_cast<uint64_t>(count), limit));
        }
        intStart_ = a;
        intStep_ = s;
        count_ = static_cast<uint64_t>(count);
        return;
    }
    if (!std::isfinite(start_) || !std::isfinite(stop_) || !std::isfinite(stride_)) {
        call.interpreter.fail(call.site->range, "range: the bounds and step must be finite");
    }
    if (std::ceil((stop_ - start_) / stride_) > static_cast<double>(limit)) {
        call.interpreter.fail(call.site->range,
                              fmt::format("range has more than {} items; raise the limit with "
                                          "--max-entities",
                                          limit));
    }
}

uint64_t RangeSequence::sizeHint() const {
    return ints_ ? count_ : 0;
}

bool RangeSequence::next(Value& item) {
    if (ints_) {
        if (index_ == count_) return false;
        // a + i·s stays between a and b, so it fits, but i·s alone may not.
        item = Value::integer(static_cast<int64_t>(intStart_ + static_cast<__int128>(index_) * intStep_));
        ++index_;
        return true;
    }
    double value = start_ + static_cast<double>(index_) * stride_;
    if (stride_ > 0 ? value >= stop_ : value <= stop_) return false;
    item = Value::number(value);
    ++index_;
    return true;
}

std::span<const BuiltinInfo> builtinFunctions() { return kBuiltins; }

UnaryMath unaryMath(uint32_t index) { return index < kFunctionCount ? kUnaryMathByIndex[index] : nullptr; }
uint32_t preludeSize() { return kFunctionCount + 2; }
uint32_t preludeSlotOfT() { return kFunctionCount; }
uint32_t preludeSlotOfClock() { return kFunctionCount + 1; }

std::optional<uint32_t> findPreludeSlot(std::string_view name) {
    for (uint32_t i = 0; i < kFunctionCount; ++i) {
        if (kBuiltins[i].name == name) return i;
    }
    if (name == "t") return preludeSlotOfT();
    if (name == "clock") return preludeSlotOfClock();
    return std::nullopt;
}

std::string_view preludeName(uint32_t slot) {
    if (slot < kFunctionCount) return kBuiltins[slot].name;
    return slot == preludeSlotOfT() ? "t" : "clock";
}

} // namespace crt::lang
