// The server's method table, through the protocol: every method it advertises, it answers.
#include "server.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

using namespace crt::lsp;
using namespace std::chrono_literals;

namespace {

const std::string kUri = "file:///nonexistent/crt-server-test/scene.crt";
const std::string kText = "size = 1\nball = Sphere { center -> vec3(0, 0, 0) radius -> size }\nScene { ball }\n";

/// Runs a server over in-memory streams until the end of `messages` (no `exit`: the reader
/// thread must be done with the input before the server goes away); returns what it sent.
std::vector<json> serve(const std::vector<json>& messages) {
    std::string input;
    for (json message : messages) {
        message["jsonrpc"] = "2.0";
        std::string body = message.dump();
        input += fmt::format("Content-Length: {}\r\n\r\n{}", body.size(), body);
    }
    std::FILE* in = fmemopen(input.data(), input.size(), "r");
    char* output = nullptr;
    size_t outputSize = 0;
    std::FILE* out = open_memstream(&output, &outputSize);
    REQUIRE(in);
    REQUIRE(out);
    {
        Transport transport(in, out);
        ServerOptions options;
        options.debounce = 0ms;
        options.analysis.includes.stdlibDir = CRT_SOURCE_STDLIB_DIR;
        Server server(transport, options);
        server.run();
    }
    std::fclose(in);
    std::fclose(out);
    std::string written(output, outputSize);
    std::free(output);

    std::vector<json> sent;
    for (size_t at = 0; at < written.size();) {
        size_t length = std::stoul(written.substr(at + std::string_view("Content-Length: ").size()));
        size_t body = written.find("\r\n\r\n", at) + 4;
        sent.push_back(json::parse(written.substr(body, length)));
        at = body + length;
    }
    return sent;
}

json request(int id, const std::string& method, json params) {
    return {{"id", id}, {"method", method}, {"params", std::move(params)}};
}

json notification(const std::string& method, json params) {
    return {{"method", method}, {"params", std::move(params)}};
}

const json* response(const std::vector<json>& sent, int id) {
    for (const json& message : sent) {
        if (message.contains("id") && message["id"] == id) return &message;
    }
    return nullptr;
}

json initialize(int id) { return request(id, "initialize", {{"capabilities", json::object()}}); }

json advertisedCapabilities() {
    std::vector<json> sent = serve({initialize(1)});
    const json* reply = response(sent, 1);
    REQUIRE(reply);
    return reply->at("result").at("capabilities");
}

/// The requests a server capability promises (LSP 3.17). A capability missing here fails the
/// test: whoever advertises a new one lists its methods, and the test checks they are answered.
std::vector<std::string> promisedRequests(const std::string& capability, const json& value) {
    static const std::map<std::string, std::vector<std::string>> plain{
        {"hoverProvider", {"textDocument/hover"}},
        {"completionProvider", {"textDocument/completion"}},
        {"signatureHelpProvider", {"textDocument/signatureHelp"}},
        {"definitionProvider", {"textDocument/definition"}},
        {"declarationProvider", {"textDocument/declaration"}},
        {"referencesProvider", {"textDocument/references"}},
        {"documentHighlightProvider", {"textDocument/documentHighlight"}},
        {"documentSymbolProvider", {"textDocument/documentSymbol"}},
        {"foldingRangeProvider", {"textDocument/foldingRange"}},
        {"renameProvider", {"textDocument/rename"}},
        {"documentFormattingProvider", {"textDocument/formatting"}},
        {"documentRangeFormattingProvider", {"textDocument/rangeFormatting"}},
        {"codeActionProvider", {"textDocument/codeAction"}},
        {"semanticTokensProvider", {}},
        {"positionEncoding", {}},
        {"textDocumentSync", {}}, // notifications: checked by their effects below
    };
    auto known = plain.find(capability);
    if (known == plain.end()) {
        FAIL("capability '" << capability << "' is advertised, but this test does not know its methods");
    }
    if (value == false) return {};
    std::vector<std::string> methods = known->second;
    if (!value.is_object()) return methods;
    if (value.value("resolveProvider", false)) {
        if (capability == "completionProvider") methods.push_back("completionItem/resolve");
        if (capability == "codeActionProvider") methods.push_back("codeAction/resolve");
    }
    if (capability == "renameProvider" && value.value("prepareProvider", false)) {
        methods.push_back("textDocument/prepareRename");
    }
    if (capability == "semanticTokensProvider") {
        json full = value.value("full", json(false));
        if (full != false) methods.push_back("textDocument/semanticTokens/full");
        if (full.is_object() && full.value("delta", false)) methods.push_back("textDocument/semanticTokens/full/delta");
        if (value.value("range", false)) methods.push_back("textDocument/semanticTokens/range");
    }
    return methods;
}

/// Parameters that do for any of the document requests above.
json documentParams() {
    json position{{"line", 0}, {"character", 1}};
    return {{"textDocument", {{"uri", kUri}}},
            {"position", position},
            {"range", {{"start", {{"line", 0}, {"character", 0}}}, {"end", {{"line", 1}, {"character", 0}}}}},
            {"newName", "width"},
            {"context", {{"includeDeclaration", true}, {"diagnostics", json::array()}}},
            {"options", {{"tabSize", 4}, {"insertSpaces", true}}}};
}

json didOpen() {
    return notification("textDocument/didOpen",
                        {{"textDocument", {{"uri", kUri}, {"languageId", "crt"}, {"version", 1}, {"text", kText}}}});
}

} // namespace

TEST_CASE("every request the server advertises is answered", "[server]") {
    json capabilities = advertisedCapabilities();
    std::vector<std::string> methods;
    for (const auto& [capability, value] : capabilities.items()) {
        for (std::string& method : promisedRequests(capability, value)) methods.push_back(std::move(method));
    }
    REQUIRE(methods.size() >= 15);

    std::vector<json> session{initialize(1), notification("initialized", json::object()), didOpen()};
    for (size_t i = 0; i < methods.size(); ++i) session.push_back(request(100 + int(i), methods[i], documentParams()));
    std::vector<json> sent = serve(session);
    for (size_t i = 0; i < methods.size(); ++i) {
        INFO(methods[i]);
        const json* reply = response(sent, 100 + int(i));
        REQUIRE(reply);
        INFO(reply->dump());
        CHECK(reply->contains("result"));
        CHECK(!reply->contains("error"));
    }
}

TEST_CASE("the advertised text synchronisation is handled", "[server]") {
    json sync = advertisedCapabilities().at("textDocumentSync");
    REQUIRE(sync.value("openClose", false));
    REQUIRE(sync.value("change", 0) == 2); // incremental
    json rename = notification(
        "textDocument/didChange",
        {{"textDocument", {{"uri", kUri}, {"version", 2}}},
         {"contentChanges",
          {{{"range", {{"start", {{"line", 0}, {"character", 0}}}, {"end", {{"line", 0}, {"character", 4}}}}},
            {"text", "width"}}}}});
    json symbols = request(2, "textDocument/documentSymbol", {{"textDocument", {{"uri", kUri}}}});
    json close = notification("textDocument/didClose", {{"textDocument", {{"uri", kUri}}}});
    std::vector<json> sent = serve({initialize(1), notification("initialized", json::object()), didOpen(), rename,
                                    notification("textDocument/didSave", {{"textDocument", {{"uri", kUri}}}}), symbols,
                                    close, symbols});

    std::vector<const json*> answers;
    const json* cleared = nullptr; // the one publication without a version: didClose's
    for (const json& message : sent) {
        if (message.contains("id") && message["id"] == 2) answers.push_back(&message);
        if (message.value("method", "") == "textDocument/publishDiagnostics" && !message["params"].contains("version")) {
            cleared = &message;
        }
    }
    REQUIRE(answers.size() == 2);
    INFO(answers[0]->dump());
    // The edit reached the text; after didClose the document is gone, its diagnostics cleared.
    CHECK(answers[0]->at("result").at(0).at("name") == "width");
    CHECK(answers[1]->at("error").at("code") == static_cast<int>(ErrorCode::InvalidParams));
    REQUIRE(cleared);
    CHECK(cleared->at("params").at("diagnostics").empty());
}

TEST_CASE("requests and notifications are bound apart", "[server]") {
    json params = documentParams();
    std::vector<json> sent =
        serve({initialize(1), notification("initialized", json::object()),
               // A notification's name as a request, a request's name as a notification.
               request(2, "textDocument/didOpen", params), notification("textDocument/hover", params),
               notification("$/setTrace", {{"value", "off"}}), request(3, "textDocument/typeDefinition", params)});
    REQUIRE(sent.size() == 3); // initialize's answer, and one error each for 2 and 3
    CHECK(sent[1] == json{{"jsonrpc", "2.0"},
                          {"id", 2},
                          {"error", {{"code", -32601}, {"message", "unknown method 'textDocument/didOpen'"}}}});
    CHECK(sent[2] == json{{"jsonrpc", "2.0"},
                          {"id", 3},
                          {"error", {{"code", -32601}, {"message", "unknown method 'textDocument/typeDefinition'"}}}});
}
