// The prelude: built-in functions and the predefined names t and clock (spec §4).
#pragma once

#include "value.hpp"

#include <optional>
#include <span>
#include <string_view>

namespace crt::lang {

class Interpreter;
struct CallExpr;

/// What a built-in sees of its call.
struct BuiltinCall {
    Interpreter& interpreter;
    const CallExpr* site;
    std::span<const Value> args;
};

using BuiltinFunction = Value (*)(BuiltinCall& call);

struct BuiltinInfo {
    std::string_view name;
    int minArgs;
    int maxArgs; ///< -1: any number
    std::string_view signature;
    std::string_view doc;
    BuiltinFunction function;
};

std::span<const BuiltinInfo> builtinFunctions();

using UnaryMath = double (*)(double);
/// For a one-argument math built-in (sin, cos, tan, exp, atan, radians, degrees): the
/// function on numbers, whose result the built-in returns unless it is a NaN (a domain
/// error, or a NaN argument). Null for every other built-in. Calls with a number use it and
/// skip the general path; anything else goes through BuiltinInfo::function.
UnaryMath unaryMath(uint32_t index);

/// The numbers range(...) yields, one at a time: `for … in range(…)` runs through them
/// without building the list. The constructor checks the arguments as range() does.
class RangeSequence {
public:
    explicit RangeSequence(BuiltinCall& call);
    /// Stores the next number in `item`; false after the last.
    bool next(Value& item);
    /// The number of items if known in advance (integer ranges), else 0.
    uint64_t sizeHint() const;

private:
    bool ints_ = true;
    int64_t intStart_ = 0, intStep_ = 1;
    uint64_t count_ = 0;
    double start_ = 0, stop_ = 0, stride_ = 1;
    uint64_t index_ = 0;
};

/// Prelude slots: the functions in table order, then t, then clock.
uint32_t preludeSize();
uint32_t preludeSlotOfT();
uint32_t preludeSlotOfClock();
/// The prelude slot called `name`, if any.
std::optional<uint32_t> findPreludeSlot(std::string_view name);
std::string_view preludeName(uint32_t slot);

} // namespace crt::lang
