// Whether an older analysis of a document still knows the names in scope at a place of the
// current text: completion then answers from it instead of analysing the text anew, as clangd
// completes with a stale preamble.
#pragma once

#include "analysis.hpp"

#include <optional>

namespace crt::lsp {

/// Where `offset` of `current` (a newer text of the document; only its tokens are read) lies
/// in the text of `older`, if the edits between the two cannot have changed the names in scope
/// there, their kinds or what completion knows of their values. That holds when the token
/// streams differ only
/// - in the text of number and string literals whose kind stays (`0.5` -> `0.7`), and
/// - in at most one name, inserted, removed or changed, that binds nothing and decides no type:
///   not before `=`, `(` or `{`, not after `for`, not among a macro's parameters (the word
///   being typed, usually).
/// Anything else (a brace, an `=`, a keyword, a literal of another kind) gives nothing: the
/// caller must analyse the current text.
std::optional<uint32_t> sameNamesAt(const Analysis& older, const Analysis& current, uint32_t offset);

} // namespace crt::lsp
