// How diagnostics quote their source line: the caret under the range's start.
#include <catch2/catch.hpp>

#include "diagnostic_printer.hpp"
#include "interpreter.hpp"

#include <string>

using namespace crt::lang;

namespace {

/// The first diagnostic `text` gets from checking, as crtc prints it (no colour).
std::string firstDiagnostic(const std::string& text) {
    EvalOptions options;
    options.checkFiles = false;
    const Compilation compilation = compile("bom.crt", text, options);
    REQUIRE_FALSE(compilation.diagnostics.items().empty());
    return formatDiagnostic(compilation.sources, compilation.diagnostics.items().front());
}

} // namespace

TEST_CASE("a range at the start of a file with a byte-order mark is shown at its first column") {
    // The warning that nothing is drawn points at the start of the file, inside the mark.
    const std::string mark = "\xEF\xBB\xBF";
    CHECK(firstDiagnostic(mark + "-- short\n") ==
          "bom.crt:1:1: warning: the script draws nothing; only the background will be rendered\n"
          "    -- short\n"
          "    ^\n");
    // A line long enough to be shown as a window around the caret.
    const std::string comment = "-- " + std::string(300, 'a');
    CHECK(firstDiagnostic(mark + comment + "\n") ==
          "bom.crt:1:1: warning: the script draws nothing; only the background will be rendered\n"
          "    " + comment.substr(0, 120) + "...\n"
          "    ^\n");
}
