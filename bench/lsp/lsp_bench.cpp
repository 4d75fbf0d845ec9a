// Benchmark of crt-lsp through its real protocol: a generated 5,000-line script, 200 edits;
// latency of diagnostics after a change, of completion, hover and semantic tokens, and the
// server's peak memory. Usage: lsp_bench CRT_LSP [LINES] [EDITS]
#include <nlohmann/json.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

using json = nlohmann::json;
using Clock = std::chrono::steady_clock;

namespace {

struct Server {
    pid_t pid;
    FILE* in;  ///< the server's stdin
    FILE* out; ///< the server's stdout

    void send(const json& message) {
        std::string body = message.dump();
        std::fprintf(in, "Content-Length: %zu\r\n\r\n%s", body.size(), body.c_str());
        std::fflush(in);
    }
    json receive() {
        size_t length = 0;
        char line[512];
        while (std::fgets(line, sizeof line, out)) {
            std::string header(line);
            if (header == "\r\n") break;
            if (header.rfind("Content-Length:", 0) == 0) length = std::stoul(header.substr(15));
        }
        std::string body(length, '\0');
        if (std::fread(body.data(), 1, length, out) != length) throw std::runtime_error("server closed");
        return json::parse(body);
    }
    /// Waits for the response to `id`, or the diagnostics of `version` when id < 0.
    json waitFor(int id, int version = -1) {
        while (true) {
            json m = receive();
            if (id >= 0 && m.contains("id") && m["id"] == id) return m;
            if (id < 0 && m.value("method", "") == "textDocument/publishDiagnostics" &&
                m["params"].value("version", -1) == version) {
                return m;
            }
        }
    }
};

Server start(const char* path) {
    int toServer[2], fromServer[2];
    if (pipe(toServer) || pipe(fromServer)) throw std::runtime_error("pipe");
    pid_t pid = fork();
    if (pid == 0) {
        dup2(toServer[0], 0);
        dup2(fromServer[1], 1);
        close(toServer[1]);
        close(fromServer[0]);
        execl(path, path, static_cast<char*>(nullptr));
        _exit(127);
    }
    close(toServer[0]);
    close(fromServer[1]);
    return {pid, fdopen(toServer[1], "w"), fdopen(fromServer[0], "r")};
}

/// A scene of about `lines` lines: materials, macros, loops and many objects.
std::string generate(int lines, int& editLine) {
    std::string s = "-- generated for the language server benchmark\n";
    s += "lamp = PointLight { origin -> vec3(0, 10, -10) color -> rgb(1, 1, 1) }\n"
         "Settings {\n    width -> 640 height -> 480\n    camera -> Camera { position -> vec3(0, 2, -10) pointing -> vec3(0, 0, 0) }\n"
         "    lights -> [lamp]\n}\n";
    int n = 0;
    editLine = -1;
    while (std::count(s.begin(), s.end(), '\n') < lines - 10) {
        s += fmt::format("m{0} = Material {{ color -> rgb({1}, 0.5, 0.25) reflectivity -> 0.{2} }}\n", n, (n % 10) / 10.0, n % 9);
        s += fmt::format("ring{0} = Macro (count, r) {{\n    for i in range(count) {{\n"
                         "        Sphere {{ center -> vec3(r * cos(i), {0} * 0.1, r * sin(i)) radius -> 0.2 material -> m{0} }}\n"
                         "    }}\n}}\n", n);
        s += fmt::format("p{0} = vec3({0}, 0.5, -{0}) + vec3(1, 1, 1) * 0.5\n", n);
        s += fmt::format("Scene {{\n    ring{0}(4, 2.0)\n    Box {{ cornerA -> p{0} cornerB -> p{0} + vec3(1, 1, 1) material -> m{0} }}\n}}\n", n);
        ++n;
    }
    return s;
}

double percentile(std::vector<double> values, double p) {
    std::sort(values.begin(), values.end());
    size_t index = std::min(values.size() - 1, static_cast<size_t>(p * static_cast<double>(values.size() - 1) + 0.5));
    return values[index];
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: lsp_bench CRT_LSP [LINES] [EDITS]\n");
        return 2;
    }
    int lines = argc > 2 ? std::atoi(argv[2]) : 5000;
    int edits = argc > 3 ? std::atoi(argv[3]) : 200;
    int unused = 0;
    std::string text = generate(lines, unused);
    // Lines "pN = vec3(N, 0.5, -N) ..." are edited: their 0.5 becomes another number.
    std::vector<int> editable;
    {
        int line = 0;
        size_t start = 0;
        while (start < text.size()) {
            size_t end = text.find('\n', start);
            if (text.compare(start, 1, "p") == 0) editable.push_back(line);
            start = end + 1;
            ++line;
        }
    }
    std::string uri = "file:///tmp/crt-lsp-bench/scene.crt";
    Server server = start(argv[1]);
    server.send({{"jsonrpc", "2.0"}, {"id", 0}, {"method", "initialize"}, {"params", {{"capabilities", json::object()}}}});
    server.waitFor(0);
    server.send({{"jsonrpc", "2.0"}, {"method", "initialized"}, {"params", json::object()}});
    server.send({{"jsonrpc", "2.0"}, {"method", "textDocument/didOpen"},
                 {"params", {{"textDocument", {{"uri", uri}, {"languageId", "crt"}, {"version", 1}, {"text", text}}}}}});
    json first = server.waitFor(-1, 1);
    if (!first["params"]["diagnostics"].empty()) {
        std::fprintf(stderr, "the generated script has diagnostics: %s\n", first["params"]["diagnostics"][0].dump().c_str());
        return 1;
    }

    std::vector<double> diagnostics, completion, hover, tokens;
    int id = 1;
    auto ms = [](Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); };
    for (int e = 0; e < edits; ++e) {
        int line = editable[static_cast<size_t>(e * 7) % editable.size()];
        int version = e + 2;
        // "pN = vec3(N, 0.5, ..." : replace the digit after "0." (column found in the text)
        size_t lineStart = 0;
        for (int l = 0; l < line; ++l) lineStart = text.find('\n', lineStart) + 1;
        size_t column = text.find("0.", lineStart) - lineStart + 2;
        std::string digit = std::to_string(e % 10);
        text[lineStart + column] = digit[0];
        json range{{"start", {{"line", line}, {"character", column}}}, {"end", {{"line", line}, {"character", column + 1}}}};
        auto t0 = Clock::now();
        server.send({{"jsonrpc", "2.0"}, {"method", "textDocument/didChange"},
                     {"params", {{"textDocument", {{"uri", uri}, {"version", version}}},
                                 {"contentChanges", json::array({{{"range", range}, {"text", digit}}})}}}});
        server.waitFor(-1, version);
        diagnostics.push_back(ms(Clock::now() - t0));

        auto timed = [&](const char* method, json params, std::vector<double>& into) {
            auto start = Clock::now();
            int request = id++;
            server.send({{"jsonrpc", "2.0"}, {"id", request}, {"method", method}, {"params", std::move(params)}});
            json response = server.waitFor(request);
            into.push_back(ms(Clock::now() - start));
            if (response.contains("error")) throw std::runtime_error(response.dump());
            return response;
        };
        json doc{{"uri", uri}};
        // Completion inside the Box's braces two lines further on (attributes), hover on pN.
        json c = timed("textDocument/completion", {{"textDocument", doc}, {"position", {{"line", line + 3}, {"character", 10}}}}, completion);
        if (c["result"]["items"].empty()) throw std::runtime_error("no completion items");
        json h = timed("textDocument/hover", {{"textDocument", doc}, {"position", {{"line", line}, {"character", 1}}}}, hover);
        if (h["result"].is_null()) throw std::runtime_error("no hover");
        timed("textDocument/semanticTokens/full", {{"textDocument", doc}}, tokens);
    }
    long peakKb = 0;
    {
        std::ifstream status(fmt::format("/proc/{}/status", server.pid));
        for (std::string l; std::getline(status, l);) {
            if (l.rfind("VmHWM:", 0) == 0) peakKb = std::stol(l.substr(6));
        }
    }
    server.send({{"jsonrpc", "2.0"}, {"id", id}, {"method", "shutdown"}});
    server.waitFor(id);
    server.send({{"jsonrpc", "2.0"}, {"method", "exit"}});
    int status = 0;
    waitpid(server.pid, &status, 0);

    std::printf("crt-lsp on a %d-line script, %d edits (debounce 20 ms)\n\n", static_cast<int>(std::count(text.begin(), text.end(), '\n')), edits);
    std::printf("| measure | median (ms) | p99 (ms) | goal p99 |\n| --- | --- | --- | --- |\n");
    auto row = [&](const char* name, const std::vector<double>& v, const char* goal) {
        std::printf("| %s | %.2f | %.2f | %s |\n", name, percentile(v, 0.5), percentile(v, 0.99), goal);
    };
    row("change -> diagnostics published", diagnostics, "< 50 ms");
    row("completion", completion, "< 10 ms");
    row("hover", hover, "< 10 ms");
    row("semantic tokens (full)", tokens, "—");
    std::printf("\npeak memory (VmHWM): %.1f MB (goal < 100 MB)\n", static_cast<double>(peakKb) / 1024.0);
    return 0;
}
