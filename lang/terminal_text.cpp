// Escaping control characters, bidirectional overrides and invalid UTF-8.
#include "terminal_text.hpp"

#include <fmt/format.h>

namespace crt::lang {

namespace {

/// The length of the valid UTF-8 sequence at `at` and its code point; 0 if it is invalid.
size_t decodeUtf8(std::string_view text, size_t at, char32_t& code) {
    const auto byte = [&](size_t i) { return static_cast<unsigned char>(text[i]); };
    const unsigned char lead = byte(at);
    if (lead < 0x80) {
        code = lead;
        return 1;
    }
    size_t length = lead >= 0xF0 && lead <= 0xF4 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC2 && lead < 0xE0 ? 2 : 0;
    if (length == 0 || at + length > text.size()) return 0;
    code = lead & (0x7F >> length);
    for (size_t i = 1; i < length; ++i) {
        if ((byte(at + i) & 0xC0) != 0x80) return 0;
        code = (code << 6) | (byte(at + i) & 0x3F);
    }
    // Overlong forms, surrogates and values past U+10FFFF are not UTF-8.
    static constexpr char32_t kLeast[] = {0, 0, 0x80, 0x800, 0x10000};
    if (code < kLeast[length] || (code >= 0xD800 && code <= 0xDFFF) || code > 0x10FFFF) return 0;
    return length;
}

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
