// libFuzzer target for the language server's message loop: arbitrary bytes as what an editor
// sends on standard input. They go through the Content-Length framing, the JSON parser and
// the dispatch to every method, analyses and evaluations included; the replies are discarded.
#include "server.hpp"

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

namespace {

crt::lsp::ServerOptions fuzzOptions() {
    crt::lsp::ServerOptions options;
    options.debounce = std::chrono::milliseconds(0);
    // Small limits keep one input fast; the front end's own target explores deep evaluations.
    // They are those of fuzz_frontend: each is still reached by a short script, and a higher
    // one only repeats the same code more times per input, on the evaluation thread beside
    // the main one.
    crt::lang::Limits& limits = options.analysis.limits;
    limits.maxSteps = 10'000;
    limits.maxDepth = 100;
    limits.maxEntities = 1'000;
    limits.maxSize = 4096;
    limits.maxMemory = uint64_t{256} << 20;
    // An evaluation that outlasts this is stopped, as in an editor; the limits above end
    // most long before it.
    options.analysis.timeBudget = std::chrono::milliseconds(100);
    options.analysis.includes.stdlibDir = CRT_SOURCE_STDLIB_DIR;
    return options;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0; // fmemopen needs at least one byte; an empty input is just the end
    static std::FILE* const discard = std::fopen("/dev/null", "w");
    std::string input(reinterpret_cast<const char*>(data), size);
    std::FILE* in = fmemopen(input.data(), input.size(), "r");
    if (!in || !discard) std::abort();
    {
        // Small messages: a frame announcing more than this is refused at once.
        crt::lsp::Transport transport(in, discard, size_t{1} << 20);
        crt::lsp::Server server(transport, fuzzOptions());
        server.run();
    } // the server's destructor waits until its reader has seen the end of the input
    std::fclose(in);
    return 0;
}
