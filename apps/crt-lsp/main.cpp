// crt-lsp: the CRT language server, speaking LSP over standard input and output.
#include "include_search.hpp"
#include "server.hpp"

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

void usage(std::FILE* out) {
    std::fputs("usage: crt-lsp [-I DIR]... [--stdlib DIR] [--debounce-ms N] [--time-budget-ms N]\n"
               "The CRT language server; an editor starts it and talks LSP over stdin/stdout.\n",
               out);
}

} // namespace

int main(int argc, char** argv) {
    crt::lsp::ServerOptions options;
    options.analysis.includes.stdlibDir = crt::lang::defaultStdlibDir();
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "crt-lsp: %s needs a value\n", arg.c_str());
                std::exit(2);
            }
            return argv[++i];
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
        } else if (arg == "--stdio") {
            // what VS Code's client passes; stdio is the only transport anyway
        } else {
            std::fprintf(stderr, "crt-lsp: unknown option '%s'\n", arg.c_str());
            usage(stderr);
            return 2;
        }
    }
    std::signal(SIGPIPE, SIG_IGN); // a client that went away must not kill us mid-write
    crt::lsp::Transport transport(stdin, stdout);
    int code;
    {
        crt::lsp::Server server(transport, options);
        code = server.run();
    }
    std::fflush(stdout);
    // The reader thread may still be blocked reading standard input: leave without joining it.
    std::_Exit(code);
}
