// Escape sequences of string literals: shared by the lexer (which reports bad ones) and the
// parser (which decodes good ones), so the two never disagree.
#include "string_escape.hpp"

#include <fmt/format.h>

namespace crt::lang {
namespace {

constexpr std::string_view kValidEscapes = "\\t \\b \\n \\r \\f \\' \\\" \\\\ or \\uXXXX";

int hexValue(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

/// The code unit of the \uXXXX at text[at], or -1 with `length` covering what was read.
int32_t readUnit(std::string_view text, size_t at, size_t& length) {
    int32_t unit = 0;
    length = 2;
    for (size_t i = at + 2; i < at + 6; ++i) {
        int digit = i < text.size() ? hexValue(text[i]) : -1;
        if (digit < 0) return -1;
        unit = unit * 16 + digit;
        ++length;
    }
    return unit;
}

bool isHigh(int32_t unit) {
    return unit >= 0xD800 && unit <= 0xDBFF;
}
bool isLow(int32_t unit) {
    return unit >= 0xDC00 && unit <= 0xDFFF;
}

Escape readUnicode(std::string_view text, size_t at) {
    Escape e;
    int32_t unit = readUnit(text, at, e.length);
    if (unit < 0) {
        // Report the characters that were meant as digits, up to the first that is not one.
        size_t shown = e.length;
        if (at + shown < text.size() &&
            std::string_view("\"\\\n\r").find(text[at + shown]) == std::string_view::npos) {
            ++shown;
        }
        while (at + shown < text.size() &&
               (static_cast<unsigned char>(text[at + shown]) & 0xC0) == 0x80) {
            ++shown;
        }
        e.length = shown;
        e.error = fmt::format("'{}' is not a unicode escape; \\u takes four hex digits, as \\u00e9",
                              text.substr(at, shown));
        return e;
    }
    if (isLow(unit)) {
        e.error = fmt::format("'\\u{:04X}' is a lone low surrogate; a surrogate pair is a high "
                              "surrogate \\uD800-\\uDBFF followed by a low one \\uDC00-\\uDFFF",
                              unit);
        return e;
    }
    if (!isHigh(unit)) {
        e.codePoint = static_cast<uint32_t>(unit);
        return e;
    }
    size_t lowLength = 0;
    int32_t low = at + 7 < text.size() && text[at + 6] == '\\' && text[at + 7] == 'u'
                      ? readUnit(text, at + 6, lowLength)
                      : -1;
    if (!isLow(low)) {
        e.error = fmt::format("'\\u{:04X}' is a lone high surrogate; a surrogate pair is a high "
                              "surrogate \\uD800-\\uDBFF followed by a low one \\uDC00-\\uDFFF",
                              unit);
        return e;
    }
    e.length += lowLength;
    e.codePoint = 0x10000 + ((static_cast<uint32_t>(unit) - 0xD800) << 10) +
                  (static_cast<uint32_t>(low) - 0xDC00);
    return e;
}

} // namespace

Escape readEscape(std::string_view text, size_t at) {
    Escape e;
    e.length = 2;
    char c = at + 1 < text.size() ? text[at + 1] : '\0';
    switch (c) {
    case 't': e.codePoint = '\t'; return e;
    case 'b': e.codePoint = '\b'; return e;
    case 'n': e.codePoint = '\n'; return e;
    case 'r': e.codePoint = '\r'; return e;
    case 'f': e.codePoint = '\f'; return e;
    case '\'': e.codePoint = '\''; return e;
    case '"': e.codePoint = '"'; return e;
    case '\\': e.codePoint = '\\'; return e;
    case 'u': return readUnicode(text, at);
    default: break;
    }
    // Name the whole character after the backslash, not one byte of it.
    while (at + e.length < text.size() &&
           (static_cast<unsigned char>(text[at + e.length]) & 0xC0) == 0x80) {
        ++e.length;
    }
    e.error = fmt::format("unknown escape sequence '{}'; use {}", text.substr(at, e.length),
                          kValidEscapes);
    return e;
}

void appendUtf8(std::string& out, uint32_t codePoint) {
    if (codePoint < 0x80) {
        out += static_cast<char>(codePoint);
    } else if (codePoint < 0x800) {
        out += static_cast<char>(0xC0 | (codePoint >> 6));
        out += static_cast<char>(0x80 | (codePoint & 0x3F));
    } else if (codePoint < 0x10000) {
        out += static_cast<char>(0xE0 | (codePoint >> 12));
        out += static_cast<char>(0x80 | ((codePoint >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (codePoint & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (codePoint >> 18));
        out += static_cast<char>(0x80 | ((codePoint >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((codePoint >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (codePoint & 0x3F));
    }
}

} // namespace crt::lang
