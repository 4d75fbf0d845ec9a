// The escape sequences of string literals (spec §1): Java's, as the original CRT read them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace crt::lang {

/// One escape sequence read from a string literal's text.
struct Escape {
    size_t length = 0;      ///< bytes of the sequence, backslash included (at least 1)
    uint32_t codePoint = 0; ///< what it stands for, when `error` is empty
    std::string error;      ///< why the sequence is invalid; empty when it is valid
};

/// Reads the escape sequence at text[at] (a backslash): \t \b \n \r \f \' \" \\ or \uXXXX, a
/// UTF-16 code unit; a high surrogate must be followed by a \u low surrogate, and the pair
/// is one code point. The caller handles a backslash at the end of the text or line.
Escape readEscape(std::string_view text, size_t at);

/// Appends the UTF-8 encoding of `codePoint` (at most U+10FFFF, not a surrogate).
void appendUtf8(std::string& out, uint32_t codePoint);

} // namespace crt::lang
