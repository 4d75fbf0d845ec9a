// Line tables and position conversions, including UTF-16 with non-ASCII text.
#include <catch2/catch.hpp>

#include "source_file.hpp"

using namespace crt::lang;

TEST_CASE("line and column of byte offsets") {
    SourceFile file("a.crt", "ab\ncd\n\nx");
    CHECK(file.lineCount() == 4);
    CHECK(file.lineColumn(0) == LineColumn{1, 1});
    CHECK(file.lineColumn(1) == LineColumn{1, 2});
    CHECK(file.lineColumn(2) == LineColumn{1, 3}); // the newline itself
    CHECK(file.lineColumn(3) == LineColumn{2, 1});
    CHECK(file.lineColumn(6) == LineColumn{3, 1});
    CHECK(file.lineColumn(7) == LineColumn{4, 1});
    CHECK(file.lineColumn(8) == LineColumn{4, 2}); // end of file
    CHECK(file.lineColumn(1000) == LineColumn{4, 2});
    CHECK(file.lineText(2) == "cd");
    CHECK(file.lineText(3) == "");
}

TEST_CASE("columns count code points, not bytes") {
    // "é" is 2 bytes, "€" 3 bytes, "𝄞" 4 bytes (outside the BMP).
    SourceFile file("u.crt", "x = \"é€𝄞\" + y");
    size_t y = file.text().find('y');
    CHECK(file.lineColumn(static_cast<uint32_t>(y)) == LineColumn{1, 13});
    CHECK(file.offsetOf(LineColumn{1, 13}) == y);
    CHECK(codePointCount("é€𝄞") == 3);
}

TEST_CASE("UTF-16 positions for the language server") {
    SourceFile file("u.crt", "a\n\"é𝄞\" b\r\nc");
    size_t b = file.text().find('b');
    // é is one UTF-16 unit, 𝄞 two (a surrogate pair).
    CHECK(file.utf16(static_cast<uint32_t>(b)) == Utf16Position{1, 6});
    CHECK(file.offsetOf(Utf16Position{1, 6}) == b);
    CHECK(file.offsetOf(Utf16Position{2, 0}) == file.text().find('c'));
    // Past the end of a line clamps to its end; past the last line, to the end of file.
    CHECK(file.offsetOf(Utf16Position{0, 99}) == 1);
    CHECK(file.offsetOf(Utf16Position{9, 0}) == file.size());
    CHECK(file.lineText(2) == "\"é𝄞\" b");
}

TEST_CASE("UTF-8 positions") {
    SourceFile file("u.crt", "é = 1\nb");
    CHECK(file.offsetOfUtf8(0, 2) == 2);
    CHECK(file.offsetOfUtf8(1, 0) == file.text().find('b'));
    CHECK(file.offsetOfUtf8(0, 100) == 6);
}

TEST_CASE("the buffer ends with a NUL the lexer can stop on") {
    SourceFile file("e.crt", "");
    CHECK(file.size() == 0);
    CHECK(file.data()[0] == '\0');
    CHECK(file.lineCount() == 1);
    CHECK(file.lineColumn(0) == LineColumn{1, 1});
}

TEST_CASE("columns of long non-ASCII lines match counting from the line start") {
    // Long lines are counted from checkpoints: every offset must still get the column and
    // UTF-16 position of a walk from its line's start, invalid bytes, sequences cut short at
    // a line break and a byte-order mark included.
    std::string text = "\xEF\xBB\xBF";
    for (int i = 0; i < 300; ++i) text += i % 7 == 0 ? "\xC3\xA9" : i % 11 == 0 ? "\xF0\x9D\x84\x9E" : i % 13 == 0 ? "\xFF" : "ab";
    text += "\xE2\x82\n"; // cut short by the line break
    text += "short \xC3\xA9\n";
    for (int i = 0; i < 700; ++i) text += i % 5 == 0 ? "\xE2\x82\xAC" : "c";
    SourceFile file("long.crt", text);
    for (uint32_t offset = 0; offset <= file.size(); ++offset) {
        const LineColumn at = file.lineColumn(offset);
        const uint32_t start = file.lineStart(at.line);
        const uint32_t clamped = std::max(offset, start);
        uint32_t points = 0, units = 0;
        for (uint32_t i = start; i < clamped;) {
            const unsigned char lead = static_cast<unsigned char>(file.text()[i]);
            const uint32_t length = lead < 0x80 ? 1 : (lead >> 5) == 0x6 ? 2 : (lead >> 4) == 0xE ? 3 : (lead >> 3) == 0x1E ? 4 : 1;
            ++points;
            units += length == 4 ? 2 : 1;
            i += length;
        }
        INFO("offset " << offset);
        REQUIRE(at.column == points + 1);
        REQUIRE(file.utf16(offset) == Utf16Position{at.line - 1, units});
    }
}
