// libFuzzer target for the whole front end: lexer, parser, resolver, interpreter, diagnostics
// printing and the scene JSON dump, on arbitrary bytes as a script.
#include "lang/diagnostic_printer.hpp"
#include "lang/interpreter.hpp"
#include "scene/scene_json.hpp"

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string text(reinterpret_cast<const char*>(data), size);

    crt::lang::EvalOptions options;
    options.limits.maxSteps = 100'000;
    options.limits.maxDepth = 100;
    options.limits.maxEntities = 100'000;
    options.limits.maxSize = 4096;
    options.checkFiles = false;
    std::ostringstream printed; // print() output is discarded
    options.printOut = &printed;

    crt::lang::Compilation compilation = crt::lang::compile("fuzz.crt", std::move(text), options);

    // Format every diagnostic, with and without source lines and colour.
    size_t total = 0;
    for (const crt::lang::Diagnostic& diagnostic : compilation.diagnostics.items()) {
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
