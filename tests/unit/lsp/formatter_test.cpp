// The formatter (lang/formatter.hpp): golden files, idempotence, refusal, ranges.
#include "formatter.hpp"
#include "interpreter.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace crt::lang;
namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream out;
    out << in.rdbuf();
    return out.str();
}

/// Applies edits (in order, non-overlapping) to `text`.
std::string applyEdits(std::string text, const std::vector<FormatEdit>& edits) {
    for (auto it = edits.rbegin(); it != edits.rend(); ++it) text.replace(it->begin, it->end - it->begin, it->replacement);
    return text;
}

} // namespace

TEST_CASE("formatter golden files", "[formatter]") {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(CRT_FORMAT_GOLDEN_DIR)) {
        std::string name = entry.path().filename().string();
        if (!name.ends_with(".crt") || name.ends_with(".expected.crt")) continue;
        ++count;
        INFO(name);
        std::string input = slurp(entry.path());
        std::string expected = slurp(entry.path().parent_path() / (entry.path().stem().string() + ".expected.crt"));
        FormatResult result = formatSource(input);
        REQUIRE(result.ok);
        CHECK(result.text == expected);
        CHECK(applyEdits(input, result.edits) == expected);
        FormatResult again = formatSource(expected);
        REQUIRE(again.ok);
        CHECK(again.text == expected);
        CHECK(again.edits.empty());
    }
    CHECK(count > 0);
}

TEST_CASE("formatting keeps every script of the repository's meaning and is idempotent", "[formatter]") {
    fs::path root = fs::path(CRT_SOURCE_STDLIB_DIR).parent_path();
    int count = 0;
    for (const char* folder : {"stdlib", "demos", "tests/golden"}) {
        if (!fs::exists(root / folder)) continue;
        for (const auto& entry : fs::recursive_directory_iterator(root / folder)) {
            if (entry.path().extension() != ".crt") continue;
            std::string input = slurp(entry.path());
            FormatResult once = formatSource(input);
            if (!once.ok) continue; // scripts with syntax errors on purpose
            ++count;
            INFO(entry.path().string());
            FormatResult twice = formatSource(once.text);
            REQUIRE(twice.ok);
            CHECK(twice.text == once.text);
        }
    }
    CHECK(count > 20);
}

TEST_CASE("the formatter refuses scripts with syntax errors", "[formatter]") {
    FormatResult result = formatSource("x = (1 +\ny=2\n");
    CHECK_FALSE(result.ok);
    CHECK(result.error.find("syntax errors") != std::string::npos);
    CHECK(result.edits.empty());
    CHECK_FALSE(formatSource("s = \"unterminated\n").ok);
}

TEST_CASE("range formatting changes only the lines in the range", "[formatter]") {
    std::string input = "a=1\nb=2\nc=3\n";
    FormatResult result = formatSource(input, {}, std::make_pair(4u, 5u));
    REQUIRE(result.ok);
    REQUIRE(result.edits.size() == 1);
    CHECK(applyEdits(input, result.edits) == "a=1\nb = 2\nc=3\n");
}

TEST_CASE("formatting options and line endings", "[formatter]") {
    FormatOptions tabs;
    tabs.useTabs = true;
    CHECK(formatSource("Scene {\nx\n}\n", tabs).text == "Scene {\n\tx\n}\n");
    FormatOptions two;
    two.indentWidth = 2;
    CHECK(formatSource("Scene {\r\n  x  \r\n}", two).text == "Scene {\r\n  x\r\n}");
    CHECK(formatSource("\xEF\xBB\xBFx=1\n").text == "\xEF\xBB\xBFx = 1\n");
}

TEST_CASE("formatting never glues tokens into others", "[formatter]") {
    // '- -' must not become '--' (a comment), '< scale' still opens modifiers.
    FormatResult result = formatSource("x = 1 - -2\ny = - - 3\nb = Sphere { center -> vec3(0,0,0) radius -> 1 } < scale 2 >\n");
    REQUIRE(result.ok);
    CHECK(result.text == "x = 1 - -2\ny = - -3\nb = Sphere { center -> vec3(0, 0, 0) radius -> 1 } <scale 2>\n");
}
