// Escaping control characters, bidirectional overrides and invalid UTF-8.
#include "terminal_text.hpp"

#include "scene/utf8.hpp"

#include <fmt/format.h>

namespace crt::lang {

using scene::decodeUtf8;

namespace {

bool isBidiControl(char32_t code) {
    return (code >= 0x202A && code <= 0x202E) || (code >= 0x2066 && code <= 0x2069);
}

} // namespace

std::string_view nextCharacter(std::string_view text, size_t at, std::string& shown) {
    char32_t code = 0;
    const size_t length = decodeUtf8(text, at, code);
    if (length == 0) {
        shown = fmt::format("\\x{:02x}", static_cast<unsigned char>(text[at]));
        return text.substr(at, 1);
    }
    if (code < 0x20 || (code >= 0x7F && code < 0xA0)) shown = fmt::format("\\x{:02x}", uint32_t(code));
    else if (isBidiControl(code)) shown = fmt::format("\\u{:04x}", uint32_t(code));
    else shown.assign(text.substr(at, length));
    return text.substr(at, length);
}

std::string terminalSafe(std::string_view text, bool escapeTab) {
    std::string out, shown;
    out.reserve(text.size());
    for (size_t at = 0; at < text.size();) {
        const char c = text[at];
        if (c == '\n' || (c == '\t' && !escapeTab) || (c >= 0x20 && c < 0x7F)) {
            out += c;
            ++at;
            continue;
        }
        at += nextCharacter(text, at, shown).size();
        out += shown;
    }
    return out;
}

bool isScriptText(std::string_view text) {
    char32_t code = 0;
    for (size_t at = 0; at < text.size();) {
        const size_t length = decodeUtf8(text, at, code);
        if (length == 0 || code == 0) return false;
        at += length;
    }
    return true;
}

} // namespace crt::lang
