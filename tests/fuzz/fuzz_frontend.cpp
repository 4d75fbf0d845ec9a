// libFuzzer target for the whole front end: lexer, parser, resolver, interpreter, diagnostics
// printing and the scene JSON dump, on arbitrary bytes as a script.
#include "lang/diagnostic_printer.hpp"
#include "lang/interpreter.hpp"
#include "scene/scene_json.hpp"

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

namespace {

// Small limits keep one input fast; each is still reached by a short script (a loop, a
// recursive macro, a range), so their errors are explored too. A higher limit only repeats
// the same code more times per input (tests/fuzz/README.md, Speed, has the costs).
constexpr uint64_t kMaxSteps = 10'000;
constexpr uint64_t kMaxEntities = 1'000;
// Diagnostics formatted per input, as many as crtc prints by default (--max-errors), and the
// last one: a megabyte of random bytes makes hundreds of thousands of them, and the rest
// would only go through the same formatting code again.
constexpr size_t kMaxFormatted = 50;

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string text(reinterpret_cast<const char*>(data), size);

    crt::lang::EvalOptions options;
    options.limits.maxSteps = kMaxSteps;
    options.limits.maxDepth = 100;
    options.limits.maxEntities = kMaxEntities;
    options.limits.maxSize = 4096;
    options.checkFiles = false;
    std::ostringstream printed; // print() output is discarded
    options.printOut = &printed;

    crt::lang::Compilation compilation = crt::lang::compile("fuzz.crt", std::move(text), options);

    // Format the first diagnostics and the last, with and without source lines and colour.
    size_t total = 0;
    const auto& diagnostics = compilation.diagnostics.items();
    for (size_t index = 0; index < diagnostics.size(); ++index) {
        if (index >= kMaxFormatted && index + 1 < diagnostics.size()) index = diagnostics.size() - 1;
        const crt::lang::Diagnostic& diagnostic = diagnostics[index];
        total += crt::lang::formatDiagnostic(compilation.sources, diagnostic).size();
        total += crt::lang::formatDiagnostic(compilation.sources, diagnostic,
                                             crt::lang::PrintOptions{true, false})
                     .size();
        total += crt::lang::formatLocation(compilation.sources, diagnostic.range).size();
    }
    if (compilation.scene) total += crt::scene::sceneToJson(*compilation.scene).size();
    // Keep the results observable so nothing above is optimised away.
    volatile size_t sink = total;
    (void)sink;
    return 0;
}
