// Script bytes made safe for a terminal, and what counts as script text.
#include <catch2/catch.hpp>

#include "terminal_text.hpp"

using namespace crt::lang;

TEST_CASE("printable text, UTF-8 included, is kept", "[terminal]") {
    CHECK(terminalSafe("plain text\n\tindented") == "plain text\n\tindented");
    CHECK(terminalSafe("caf\xc3\xa9 \xe2\x88\x9a \xf0\x9f\x8c\x88") == "caf\xc3\xa9 \xe2\x88\x9a \xf0\x9f\x8c\x88");
    CHECK(terminalSafe("a\tb", true) == "a\\x09b");
}

TEST_CASE("controls, bidirectional overrides and invalid UTF-8 are escaped", "[terminal]") {
    CHECK(terminalSafe("\x1b[2J\a\r") == "\\x1b[2J\\x07\\x0d");
    CHECK(terminalSafe("\x7f") == "\\x7f");
    CHECK(terminalSafe("\xc2\x9b") == "\\x9b"); // C1 CSI written as UTF-8
    CHECK(terminalSafe("\xe2\x80\xae" "abc\xe2\x81\xa6") == "\\u202eabc\\u2066");
    CHECK(terminalSafe("\xff\xc3") == "\\xff\\xc3");        // a stray byte, a cut sequence
    CHECK(terminalSafe("\xc0\xaf") == "\\xc0\\xaf");        // an overlong '/'
    CHECK(terminalSafe("\xed\xa0\x80") == "\\xed\\xa0\\x80"); // a surrogate
}

TEST_CASE("script text is UTF-8 without NUL", "[terminal]") {
    CHECK(isScriptText("x = \"caf\xc3\xa9\"\n"));
    CHECK(isScriptText(""));
    CHECK_FALSE(isScriptText(std::string("a\0b", 3)));
    CHECK_FALSE(isScriptText("\x7f" "ELF\x02\x01\x01\xff"));
}
