// Text from scripts and file names made safe to print on a terminal.
//
// A script's bytes reach crtc's standard error in diagnostics (the source line, names and
// strings quoted in messages). Printed raw, an escape sequence could move the cursor, retitle
// the window or hide text, and a bidirectional override could make the line read otherwise
// than it is. So every such byte is shown as an escape instead.
#pragma once

#include <string>
#include <string_view>

namespace crt::lang {

/// `text` with C0 and C1 control characters (except a line feed, and a tab unless
/// `escapeTab`), DEL, the bidirectional controls U+202A-U+202E and U+2066-U+2069 and every
/// byte of invalid UTF-8 escaped: `\x1b`, `\u202e`. Printable text, UTF-8 included, is kept.
std::string terminalSafe(std::string_view text, bool escapeTab = false);

/// How many bytes of `text` starting at `at` form one character as terminalSafe sees it (1
/// for an invalid byte), and what terminalSafe prints for it.
std::string_view nextCharacter(std::string_view text, size_t at, std::string& shown);

/// Whether `text` is valid UTF-8 without NUL bytes: text a CRT script can be.
bool isScriptText(std::string_view text);

} // namespace crt::lang
