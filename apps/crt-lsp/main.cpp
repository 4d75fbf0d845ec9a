// crt-lsp: the CRT language server, speaking LSP over standard input and output.
#include "include_search.hpp"
#include "server.hpp"

#include <algorithm>
#include <charconv>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>

namespace {

void usage(std::FILE* out) {
    std::fputs("usage: crt-lsp [-I DIR]... [--stdlib DIR] [--assets DIR]... [--allow-read DIR]...\n"
               "               [--allow-read-all] [--max-steps N] [--max-entities N] [--max-primitives N]\n"
               "               [--max-depth N] [--max-memory MIB] [--max-message-mib MIB]\n"
               "               [--debounce-ms N] [--time-budget-ms N]\n"
               "The CRT language server; an editor starts it and talks LSP over stdin/stdout.\n",
               out);
}

/// `text` as a count for `option`; ends the program (status 2) if it is not one.
template <typename T> T count(const std::string& option, const std::string& text) {
    T value{};
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) {
        std::fprintf(stderr, "crt-lsp: %s needs a non-negative integer\n", option.c_str());
        std::exit(2);
    }
    return value;
}

/// Which files scripts may read and how far they are evaluated: true if `arg` is one of these.
bool evaluationOption(const std::string& arg, const std::function<std::string()>& value,
                      crt::lsp::AnalysisOptions& analysis) {
    crt::lang::Limits& limits = analysis.limits;
    if (arg == "--assets") analysis.assetRoots.push_back(value());
    else if (arg == "--allow-read") analysis.access.allowRead.push_back(value());
    else if (arg == "--allow-read-all") analysis.access.allowAll = true;
    else if (arg == "--max-steps") limits.maxSteps = count<uint64_t>(arg, value());
    else if (arg == "--max-entities") limits.maxEntities = count<uint64_t>(arg, value());
    else if (arg == "--max-mesh-size") limits.maxMeshSize = count<uint64_t>(arg, value());
    else if (arg == "--max-text-length")
        limits.maxTextLength = count<uint64_t>(arg, value());
    else if (arg == "--max-primitives") limits.render.maxPrimitives = count<uint64_t>(arg, value());
    else if (arg == "--max-depth") limits.maxDepth = count<uint32_t>(arg, value());
    else return false;
    return true;
}

} // namespace

int main(int argc, char** argv) {
    crt::lsp::ServerOptions options;
    size_t maxMessageBytes = crt::lsp::Transport::kDefaultMaxMessageBytes;
    options.analysis.includes.stdlibDir = crt::lang::defaultStdlibDir();
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        std::function<std::string()> value = [&]() -> std::string {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "crt-lsp: %s needs a value\n", arg.c_str());
                std::exit(2);
            }
            return argv[++i];
        };
        auto positive = [&](const std::string& text) -> uint64_t {
            char* end = nullptr;
            const unsigned long long number = std::strtoull(text.c_str(), &end, 10);
            if (text.empty() || *end != '\0' || number == 0 || number > (uint64_t{1} << 40) || text[0] == '-') {
                std::fprintf(stderr, "crt-lsp: %s needs a positive number of MiB, not '%s'\n", arg.c_str(), text.c_str());
                std::exit(2);
            }
            return number;
        };
        if (arg == "--help" || arg == "-h") {
            usage(stdout);
            return 0;
        } else if (arg == "--version") {
            std::printf("crt-lsp %s\n", CRT_VERSION);
            return 0;
        } else if (arg == "-I") {
            options.analysis.includes.dirs.push_back(value());
        } else if (arg == "--stdlib") {
            options.analysis.includes.stdlibDir = value();
        } else if (arg == "--debounce-ms") {
            options.debounce = std::chrono::milliseconds(std::atoi(value().c_str()));
        } else if (arg == "--time-budget-ms") {
            options.analysis.timeBudget = std::chrono::milliseconds(std::atoi(value().c_str()));
        } else if (evaluationOption(arg, value, options.analysis)) {
        } else if (arg == "--max-memory") {
            options.analysis.limits.maxMemory = positive(value()) << 20;
        } else if (arg == "--max-message-mib") {
            maxMessageBytes = positive(value()) << 20;
        } else if (arg == "--stdio") {
            // what VS Code's client passes; stdio is the only transport anyway
        } else {
            std::fprintf(stderr, "crt-lsp: unknown option '%s'\n", arg.c_str());
            usage(stderr);
            return 2;
        }
    }
    std::signal(SIGPIPE, SIG_IGN); // a client that went away must not kill us mid-write
    crt::lsp::Transport transport(stdin, stdout, maxMessageBytes);
    crt::lsp::Server server(transport, options);
    const int code = server.run();
    std::fflush(stdout);
    // The reader thread may still be blocked reading standard input: leave without destroying
    // the server, whose destructor would wait for it.
    std::_Exit(code);
}
