// What a POV-Ray user writes out of habit, and how CRT says it: the hints diagnostics give.
#pragma once

#include "object_schema.hpp"

#include <optional>
#include <string_view>

namespace crt::lang::povray {

/// What to say where `i++` broke a statement (CRT has no increment operator).
inline constexpr std::string_view kNoIncrement = "CRT has no '++': write 'i += 1'";

/// For `#word`, a POV-Ray directive: how CRT writes it ("" for a word POV-Ray does not have).
std::string_view directiveHint(std::string_view word);
/// Whether the rest of the line after `#word` is no CRT (a condition, a macro's head), so
/// that reading on would only add errors.
bool directiveLineIsForeign(std::string_view word);

/// For `word {`, where `word` is a POV-Ray block that is no CRT type (light_source, union,
/// texture, global_settings …): how CRT writes it, or "".
std::string_view blockHint(std::string_view word);

/// A POV-Ray name for one of an object's attributes: CRT's name for it, if it is only spelled
/// otherwise, and what to say.
struct AttributeHint {
    std::string_view crtName; ///< "" where there is no one attribute to rename it to
    std::string_view note;
};
/// For the unknown attribute `name` of an object of `category`, or nullopt.
std::optional<AttributeHint> attributeHint(ObjectCategory category, std::string_view name);

/// For an include file of POV-Ray's (`colors.inc`), the standard library file that takes its
/// place, or "".
std::string_view includeReplacement(std::string_view file);

} // namespace crt::lang::povray
