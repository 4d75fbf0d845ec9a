// The protocol layer: positions in both encodings, URIs, semantic token encoding.
#include "protocol.hpp"

#include <catch2/catch.hpp>

using namespace crt::lsp;
using crt::lang::SourceFile;

TEST_CASE("positions convert both ways in UTF-16 and UTF-8", "[protocol]") {
    SourceFile file("a.crt", "s = \"é🌈\" + q\nx\n");
    uint32_t q = static_cast<uint32_t>(std::string_view(file.text()).find('q'));
    Positions utf16(file, OffsetEncoding::Utf16);
    Positions utf8(file, OffsetEncoding::Utf8);
    CHECK(utf16.position(q) == json{{"line", 0}, {"character", 12}});
    CHECK(utf8.position(q) == json{{"line", 0}, {"character", 15}});
    CHECK(utf16.offset(json{{"line", 0}, {"character", 12}}) == q);
    CHECK(utf8.offset(json{{"line", 0}, {"character", 15}}) == q);
    // Past the end of a line, past the end of the file.
    CHECK(utf16.offset(json{{"line", 1}, {"character", 99}}) == q + 3);
    CHECK(utf16.offset(json{{"line", 99}, {"character", 0}}) == file.size());
    CHECK_THROWS_AS(utf16.offset(json{{"line", -1}, {"character", 0}}), LspError);
    CHECK_THROWS_AS(utf16.offset(json{{"line", 0}}), LspError);
}

TEST_CASE("URIs and paths", "[protocol]") {
    CHECK(uriToPath("file:///tmp/a%20b/c.crt") == "/tmp/a b/c.crt");
    CHECK(pathToUri("/tmp/a b/é.crt") == "file:///tmp/a%20b/%C3%A9.crt");
    CHECK(uriToPath(pathToUri("/x/y z/w.crt")) == "/x/y z/w.crt");
}

TEST_CASE("semantic tokens are encoded relative to the previous one", "[protocol]") {
    SourceFile file("a.crt", "é = 1\n  b\n");
    Positions positions(file, OffsetEncoding::Utf16);
    std::vector<SemanticToken> tokens{{{0, 0, 2}, TokenType::Variable, 3},
                                      {{0, 5, 6}, TokenType::Number, 0},
                                      {{0, 9, 10}, TokenType::Variable, 0}};
    json encoded = json::parse(encodeSemanticTokens(tokens, positions));
    CHECK(encoded["data"] == json::array({0, 0, 1, 3, 3, 0, 4, 1, 7, 0, 1, 2, 1, 3, 0}));
}
