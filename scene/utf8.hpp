// Reading UTF-8 one character at a time: for the front end's terminal-safe text and for
// the characters a Text lays out.
#pragma once

#include <cstddef>
#include <string_view>

namespace crt::scene {

/// The length of the valid UTF-8 sequence at `at` and its code point; 0 if it is invalid
/// (overlong forms, surrogates and values past U+10FFFF are not UTF-8).
size_t decodeUtf8(std::string_view text, size_t at, char32_t& code);

} // namespace crt::scene
