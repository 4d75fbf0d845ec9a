// The method table binding LSP messages to the features; the lifecycle rules; text synchronisation.
#include "server.hpp"

#include "code_actions.hpp"
#include "diagnostics_worker.hpp"
#include "formatter.hpp"
#include "stale_names.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <thread>
#include <utility>

#ifndef CRT_VERSION
#define CRT_VERSION "0"
#endif

namespace crt::lsp {

using namespace lang;

Server::Server(Transport& transport, ServerOptions options) : transport_(transport), options_(std::move(options)) {
    bindHandlers();
}

Server::~Server() {
    if (reader_.joinable()) reader_.join();
}

// ---------------------------------------------------------------- messages

void Server::send(const json& message) {
    transport_.write(message.dump(-1, ' ', false, json::error_handler_t::replace));
}

void Server::reply(const json& id, json result) {
    send({{"jsonrpc", "2.0"}, {"id", id}, {"result", std::move(result)}});
}

void Server::replyError(const json& id, ErrorCode code, const std::string& message) {
    send({{"jsonrpc", "2.0"}, {"id", id}, {"error", {{"code", static_cast<int>(code)}, {"message", message}}}});
}

namespace {

/// Whether `message` is a request or notification of method `name`; false for anything
/// else, a method that is not a string included.
bool isMethod(const json& message, std::string_view name) {
    if (!message.is_object()) return false;
    auto method = message.find("method");
    return method != message.end() && method->is_string() && method->get_ref<const std::string&>() == name;
}

} // namespace

void Server::readerLoop() {
    while (true) {
        Transport::Incoming in = transport_.read();
        if (in.status == Transport::Status::End) break;
        if (in.status == Transport::Status::Malformed) {
            replyError(nullptr, ErrorCode::ParseError, in.body);
            continue;
        }
        json message = json::parse(in.body, nullptr, false);
        if (message.is_discarded()) {
            replyError(nullptr, ErrorCode::ParseError, "the message is not valid JSON");
            continue;
        }
        if (isMethod(message, "$/cancelRequest")) {
            // Handled here, so a request still waiting in the queue can be skipped.
            std::lock_guard lock(queueMutex_);
            if (message.contains("params") && message["params"].is_object() && message["params"].contains("id")) {
                cancelled_.insert(message["params"]["id"].dump());
            }
            continue;
        }
        std::lock_guard lock(queueMutex_);
        queue_.push_back(std::move(message));
        queueReady_.notify_one();
    }
    std::lock_guard lock(queueMutex_);
    queue_.push_back(std::nullopt);
    queueReady_.notify_one();
}

int Server::run() {
    // After `exit` the reader may still sit in a blocking read: run() returns without it.
    reader_ = std::thread([this] { readerLoop(); });
    while (true) {
        std::optional<json> message;
        {
            std::unique_lock lock(queueMutex_);
            queueReady_.wait(lock, [&] { return !queue_.empty(); });
            message = std::move(queue_.front());
            queue_.pop_front();
        }
        if (!message) break;
        if (isMethod(*message, "exit")) {
            worker_.reset();
            return shutdown_ ? 0 : 1;
        }
        handle(*message);
    }
    worker_.reset();
    return shutdown_ ? 0 : 1;
}

void Server::handle(const json& message) {
    if (!message.is_object() || !message.contains("method") || !message["method"].is_string()) {
        // A response to a request of ours (we send none) or garbage.
        if (message.is_object() && (message.contains("result") || message.contains("error"))) return;
        json id = message.is_object() && message.contains("id") ? message["id"] : json(nullptr);
        replyError(id, ErrorCode::InvalidRequest, "not a JSON-RPC request or notification");
        return;
    }
    std::string method = message["method"];
    json params = message.contains("params") ? message["params"] : json::object();
    if (message.contains("id")) handleRequest(message["id"], method, params);
    else handleNotification(method, params);
}

void Server::handleNotification(const std::string& method, const json& params) {
    if (!initialized_ || shutdown_) return;
    auto handler = notifications_.find(method);
    if (handler == notifications_.end()) return; // $/setTrace and the like: nothing to do
    try {
        handler->second(params);
    } catch (const std::exception&) {
        // Notifications get no answer; a bad one is ignored, as LSP asks.
    }
}

void Server::handleRequest(const json& id, const std::string& method, const json& params) {
    if (!id.is_string() && !id.is_number_integer()) {
        replyError(nullptr, ErrorCode::InvalidRequest, "a request id must be a string or an integer");
        return;
    }
    if (takeCancelled(id)) {
        replyError(id, ErrorCode::RequestCancelled, "cancelled");
        return;
    }
    if (!initialized_ && method != "initialize") {
        replyError(id, ErrorCode::ServerNotInitialized, "the server is not initialized yet");
        return;
    }
    if (shutdown_) {
        replyError(id, ErrorCode::InvalidRequest, "the server is shutting down");
        return;
    }
    try {
        replyResult(id, requestHandler(method)(params));
    } catch (const LspError& e) {
        replyError(id, e.code, e.what());
    } catch (const json::exception& e) {
        replyError(id, ErrorCode::InvalidParams, fmt::format("invalid parameters: {}", e.what()));
    } catch (const std::exception& e) {
        replyError(id, ErrorCode::InternalError, e.what());
    }
    retired_.clear();
}

bool Server::takeCancelled(const json& id) {
    std::lock_guard lock(queueMutex_);
    return cancelled_.erase(id.dump()) > 0;
}

void Server::replyResult(const json& id, Result result) {
    if (const auto* serialised = std::get_if<SerialisedJson>(&result)) {
        transport_.write(fmt::format("{{\"jsonrpc\":\"2.0\",\"id\":{},\"result\":{}}}", id.dump(), serialised->text));
    } else {
        reply(id, std::move(std::get<json>(result)));
    }
}

// ---------------------------------------------------------------- the method table

void Server::bindHandlers() {
    bindRequest("initialize", &Server::onInitialize);
    bindRequest("shutdown", &Server::onShutdown);
    bindNotification("initialized", &Server::onInitialized);

    bindNotification("textDocument/didOpen", &Server::onDidOpen);
    bindNotification("textDocument/didChange", &Server::onDidChange);
    bindNotification("textDocument/didSave", &Server::onDidSave);
    bindNotification("textDocument/didClose", &Server::onDidClose);

    bindRequest("textDocument/formatting", &Server::onFormatting);
    bindRequest("textDocument/rangeFormatting", &Server::onRangeFormatting);
    bindRequest("textDocument/completion", &Server::onCompletion);
    bindRequest("textDocument/semanticTokens/full", &Server::onSemanticTokensFull);
    bindRequest("textDocument/semanticTokens/range", &Server::onSemanticTokensRange);
    bindRequest("textDocument/hover", &Server::onHover);
    bindRequest("textDocument/signatureHelp", &Server::onSignatureHelp);
    // A name is declared where it is bound: its declaration is its definition.
    bindRequest("textDocument/definition", &Server::onDefinition);
    bindRequest("textDocument/declaration", &Server::onDefinition);
    bindRequest("textDocument/references", &Server::onReferences);
    bindRequest("textDocument/documentHighlight", &Server::onDocumentHighlight);
    bindRequest("textDocument/prepareRename", &Server::onPrepareRename);
    bindRequest("textDocument/rename", &Server::onRename);
    bindRequest("textDocument/documentSymbol", &Server::onDocumentSymbol);
    bindRequest("textDocument/foldingRange", &Server::onFoldingRange);
    bindRequest("textDocument/codeAction", &Server::onCodeAction);
}

void Server::bindRequest(std::string method, json (Server::*handler)(const json&)) {
    requests_.emplace(std::move(method), [this, handler](const json& params) -> Result {
        return (this->*handler)(params);
    });
}

void Server::bindRequest(std::string method, json (Server::*handler)(Document&, const json&)) {
    requests_.emplace(std::move(method), [this, handler](const json& params) -> Result {
        return (this->*handler)(document(params), params);
    });
}

void Server::bindRequest(std::string method, json (Server::*handler)(const DocumentRequest&)) {
    requests_.emplace(std::move(method), [this, handler](const json& params) -> Result {
        return (this->*handler)(analysedRequest(params));
    });
}

void Server::bindRequest(std::string method, SerialisedJson (Server::*handler)(const DocumentRequest&)) {
    requests_.emplace(std::move(method), [this, handler](const json& params) -> Result {
        return (this->*handler)(analysedRequest(params));
    });
}

void Server::bindNotification(std::string method, void (Server::*handler)(const json&)) {
    notifications_.emplace(std::move(method), [this, handler](const json& params) { (this->*handler)(params); });
}

const Server::RequestHandler& Server::requestHandler(const std::string& method) const {
    auto handler = requests_.find(method);
    if (handler == requests_.end()) {
        throw LspError(ErrorCode::MethodNotFound, fmt::format("unknown method '{}'", method));
    }
    return handler->second;
}

// ---------------------------------------------------------------- lifecycle

json Server::onInitialize(const json& params) {
    if (initialized_) throw LspError(ErrorCode::InvalidRequest, "initialize was already received");
    readClientCapabilities(params);
    readInitializationOptions(params);
    initialized_ = true;
    worker_ = std::make_unique<DiagnosticsWorker>(
        options_.analysis, options_.debounce,
        [this](const std::string& uri, int64_t version, std::shared_ptr<const Analysis> analysis) {
            publish(uri, version, std::move(analysis));
        });
    json result{{"capabilities", serverCapabilities()},
                {"serverInfo", {{"name", "crt-lsp"}, {"version", CRT_VERSION}}}};
    if (encoding_ == OffsetEncoding::Utf8) result["offsetEncoding"] = "utf-8";
    return result;
}

void Server::readClientCapabilities(const json& params) {
    encoding_ = OffsetEncoding::Utf16;
    if (!params.is_object() || !params.contains("capabilities")) return;
    const json& caps = params["capabilities"];
    json encodings = caps.value("general", json::object()).value("positionEncodings", json::array());
    if (caps.contains("offsetEncoding") && caps["offsetEncoding"].is_array()) {
        for (const json& e : caps["offsetEncoding"]) encodings.push_back(e); // clangd's extension
    }
    for (const json& e : encodings) {
        if (e == "utf-8") encoding_ = OffsetEncoding::Utf8;
    }
    snippets_ = caps.value("textDocument", json::object())
                    .value("completion", json::object())
                    .value("completionItem", json::object())
                    .value("snippetSupport", false);
}

namespace {

/// Appends the strings of `init[key]`, if it is a list, to `out`.
void readStrings(const json& init, const char* key, std::vector<std::string>& out) {
    if (!init.contains(key) || !init[key].is_array()) return;
    for (const json& item : init[key]) {
        if (item.is_string()) out.push_back(item);
    }
}

/// Sets `out` from `init[key]` if that is a non-negative integer that fits.
template <typename T> void readCount(const json& init, const char* key, T& out) {
    if (!init.contains(key) || !init[key].is_number_unsigned()) return;
    const uint64_t value = init[key].get<uint64_t>();
    if (value <= std::numeric_limits<T>::max()) out = static_cast<T>(value);
}

} // namespace

void Server::readWorkspaceFolders(const json& params) {
    // The workspace's folders are roots of what a script may read, as the script's own is.
    std::vector<std::string>& roots = options_.analysis.access.allowRead;
    if (params.contains("workspaceFolders") && params["workspaceFolders"].is_array()) {
        for (const json& folder : params["workspaceFolders"]) {
            if (folder.is_object() && folder.contains("uri") && folder["uri"].is_string())
                roots.push_back(uriToPath(folder["uri"].get<std::string>()));
        }
    } else if (params.contains("rootUri") && params["rootUri"].is_string()) {
        roots.push_back(uriToPath(params["rootUri"].get<std::string>()));
    }
}

void Server::readInitializationOptions(const json& params) {
    if (!params.is_object()) return;
    readWorkspaceFolders(params);
    if (!params.contains("initializationOptions")) return;
    const json& init = params["initializationOptions"];
    if (!init.is_object()) return;
    AnalysisOptions& analysis = options_.analysis;
    readStrings(init, "includeDirs", analysis.includes.dirs);
    if (init.contains("stdlib") && init["stdlib"].is_string()) analysis.includes.stdlibDir = init["stdlib"];
    readStrings(init, "assetRoots", analysis.assetRoots);
    readStrings(init, "allowRead", analysis.access.allowRead);
    if (init.contains("allowReadAll") && init["allowReadAll"].is_boolean())
        analysis.access.allowAll = init["allowReadAll"].get<bool>();
    readCount(init, "maxSteps", analysis.limits.maxSteps);
    readCount(init, "maxEntities", analysis.limits.maxEntities);
    readCount(init, "maxMeshSize", analysis.limits.maxMeshSize);
    readCount(init, "maxTextLength", analysis.limits.maxTextLength);
    readCount(init, "maxPrimitives", analysis.limits.render.maxPrimitives);
    readCount(init, "maxDepth", analysis.limits.maxDepth);
    int64_t milliseconds = 0;
    readCount(init, "timeBudgetMs", milliseconds);
    if (milliseconds > 0) analysis.timeBudget = std::chrono::milliseconds(milliseconds);
    if (init.contains("maxMemory") && init["maxMemory"].is_number_unsigned() && init["maxMemory"].get<uint64_t>() > 0)
        analysis.limits.maxMemory = init["maxMemory"].get<uint64_t>() << 20; // MiB, as --max-memory
    if (init.contains("debounceMs") && init["debounceMs"].is_number_integer()) {
        options_.debounce = std::chrono::milliseconds(std::max<int64_t>(0, init["debounceMs"].get<int64_t>()));
    }
}

json Server::serverCapabilities() const {
    // Each provider here needs its methods in bindHandlers() (server_test.cpp checks).
    json tokenTypes = json::array(), tokenModifiers = json::array();
    for (std::string_view name : tokenTypeNames()) tokenTypes.push_back(name);
    for (std::string_view name : tokenModifierNames()) tokenModifiers.push_back(name);
    return {
        {"positionEncoding", encoding_ == OffsetEncoding::Utf8 ? "utf-8" : "utf-16"},
        {"textDocumentSync", {{"openClose", true}, {"change", 2}, {"save", {{"includeText", false}}}}},
        {"hoverProvider", true},
        {"completionProvider", {{"triggerCharacters", {">", "\"", "<", "{"}}, {"resolveProvider", false}}},
        {"signatureHelpProvider", {{"triggerCharacters", {"(", ","}}}},
        {"definitionProvider", true},
        {"declarationProvider", true},
        {"referencesProvider", true},
        {"documentHighlightProvider", true},
        {"documentSymbolProvider", true},
        {"foldingRangeProvider", true},
        {"renameProvider", {{"prepareProvider", true}}},
        {"documentFormattingProvider", true},
        {"documentRangeFormattingProvider", true},
        {"codeActionProvider", {{"codeActionKinds", {"quickfix"}}}},
        {"semanticTokensProvider",
         {{"legend", {{"tokenTypes", tokenTypes}, {"tokenModifiers", tokenModifiers}}}, {"full", true}, {"range", true}}},
    };
}

void Server::onInitialized(const json&) {
    // Nothing to do: the server asks the client for nothing once initialized.
}

json Server::onShutdown(const json&) {
    shutdown_ = true;
    return nullptr;
}

// ---------------------------------------------------------------- documents

void Server::onDidOpen(const json& params) {
    const json& item = member(params, "textDocument");
    std::string uri = member(item, "uri");
    Document& doc = documents_[uri];
    doc.uri = uri;
    doc.path = uriToPath(uri);
    doc.text = member(item, "text").get<std::string>();
    doc.version = item.value("version", int64_t{0});
    doc.analysis.reset();
    doc.analysisVersion = -1;
    {
        std::lock_guard lock(publishedMutex_); // of an earlier text opened under this name
        published_.erase(uri);
    }
    worker_->schedule(uri, doc.version, doc.path, doc.text);
}

void Server::onDidChange(const json& params) {
    const json& id = member(params, "textDocument");
    auto it = documents_.find(member(id, "uri").get<std::string>());
    if (it == documents_.end()) return;
    Document& doc = it->second;
    for (const json& change : member(params, "contentChanges")) {
        std::string text = member(change, "text");
        if (!change.contains("range")) {
            doc.text = std::move(text);
            continue;
        }
        SourceFile current(doc.path, doc.text);
        Positions positions(current, encoding_);
        uint32_t begin = positions.offset(member(change["range"], "start"));
        uint32_t end = positions.offset(member(change["range"], "end"));
        if (end < begin) std::swap(begin, end);
        doc.text.replace(begin, end - begin, text);
    }
    if (id.contains("version") && id["version"].is_number_integer()) doc.version = id["version"];
    else ++doc.version;
    worker_->schedule(doc.uri, doc.version, doc.path, doc.text);
}

void Server::onDidSave(const json&) {
    // Nothing to do: the text is already in sync, and saving it changes no diagnostic.
}

void Server::onDidClose(const json& params) {
    std::string uri = member(member(params, "textDocument"), "uri");
    documents_.erase(uri);
    worker_->forget(uri);
    {
        std::lock_guard lock(publishedMutex_);
        published_.erase(uri);
    }
    send({{"jsonrpc", "2.0"},
          {"method", "textDocument/publishDiagnostics"},
          {"params", {{"uri", uri}, {"diagnostics", json::array()}}}});
}

void Server::publish(const std::string& uri, int64_t version, std::shared_ptr<const Analysis> analysis) {
    // Runs on the worker thread. The diagnostics are converted before the analysis is handed
    // over: from then on only the main thread touches it (SourceFile caches its last line
    // lookup). Handing it over before sending means a request that follows the diagnostics
    // always finds the analysis of their text.
    const Compilation& c = analysis->compilation;
    std::vector<DocumentDiagnostic> diagnostics = documentDiagnostics(c);
    const SourceFile& file = c.sources.file(0);
    Positions positions(file, encoding_);
    json list = json::array();
    for (const DocumentDiagnostic& d : diagnostics) list.push_back(toJson(d, positions, uri, &file, encoding_));
    // Code actions need the texts and fix-its only, never the related files.
    for (DocumentDiagnostic& d : diagnostics) d.related.clear();
    Published replaced; // freed once the diagnostics are out: a whole analysis takes a while
    {
        std::lock_guard lock(publishedMutex_);
        replaced = std::exchange(published_[uri],
                                 Published{version, std::move(analysis),
                                           std::make_shared<const std::vector<DocumentDiagnostic>>(std::move(diagnostics))});
    }
    send({{"jsonrpc", "2.0"},
          {"method", "textDocument/publishDiagnostics"},
          {"params", {{"uri", uri}, {"version", version}, {"diagnostics", std::move(list)}}}});
}

std::optional<Server::Published> Server::published(const std::string& uri) {
    std::lock_guard lock(publishedMutex_);
    auto it = published_.find(uri);
    if (it == published_.end()) return std::nullopt;
    return it->second;
}

Server::Document& Server::document(const json& params) {
    std::string uri = member(member(params, "textDocument"), "uri");
    auto it = documents_.find(uri);
    if (it == documents_.end()) throw LspError(ErrorCode::InvalidParams, fmt::format("document is not open: {}", uri));
    return it->second;
}

Server::DocumentRequest Server::analysedRequest(const json& params) {
    Document& doc = document(params);
    const Analysis& a = analysisOf(doc);
    return {params, doc, a, Positions(a.file(), encoding_)};
}

uint32_t Server::DocumentRequest::position() const {
    return positions.offset(member(params, "position"));
}

const Analysis& Server::analysisOf(Document& doc) {
    if (doc.analysis && doc.analysisVersion == doc.version) return *doc.analysis;
    // The worker publishes an analysis together with the diagnostics of its text; before
    // they are out, parsing and resolving here (no evaluation) is quicker than waiting.
    std::optional<Published> last = published(doc.uri);
    retired_.push_back(std::move(doc.analysis)); // freed after the answer is sent
    if (last && last->version == doc.version) {
        doc.analysis = std::move(last->analysis);
    } else {
        doc.analysis = analyze(doc.path, doc.text, options_.analysis, includes_);
    }
    doc.analysisVersion = doc.version;
    return *doc.analysis;
}

std::shared_ptr<const Analysis> Server::olderAnalysis(Document& doc) {
    std::optional<Published> last = published(doc.uri);
    if (last && last->version > doc.analysisVersion) return last->analysis;
    return doc.analysis;
}

json Server::location(const Location& loc, const Document& doc, const Analysis& analysis) {
    if (loc.file == &analysis.file()) {
        return {{"uri", doc.uri}, {"range", Positions(analysis.file(), encoding_).range(loc.range)}};
    }
    std::error_code error;
    std::string path = std::filesystem::absolute(loc.file->path(), error).lexically_normal().string();
    return {{"uri", pathToUri(path)}, {"range", Positions(*loc.file, encoding_).range(loc.range)}};
}

// ---------------------------------------------------------------- requests

json Server::onFormatting(Document& doc, const json& params) {
    return formattingEdits(doc, params, false);
}

json Server::onRangeFormatting(Document& doc, const json& params) {
    return formattingEdits(doc, params, true);
}

json Server::formattingEdits(const Document& doc, const json& params, bool onlyRange) {
    // Formatting needs the text only: no analysis, so a request never waits for one.
    FormatOptions format;
    if (params.contains("options") && params["options"].is_object()) {
        format.indentWidth = static_cast<uint32_t>(std::clamp<int64_t>(params["options"].value("tabSize", 4), 1, 16));
        format.useTabs = !params["options"].value("insertSpaces", true);
    }
    SourceFile file(doc.path, doc.text);
    Positions positions(file, encoding_);
    std::optional<std::pair<uint32_t, uint32_t>> range;
    if (onlyRange) {
        // The end first: a range missing both ends has always been reported by its end.
        const json& r = member(params, "range");
        uint32_t end = positions.offset(member(r, "end"));
        uint32_t begin = positions.offset(member(r, "start"));
        range = std::make_pair(begin, end);
    }
    FormatResult result = formatSource(doc.text, format, range);
    if (!result.ok) throw LspError(ErrorCode::RequestFailed, result.error);
    json edits = json::array();
    for (const FormatEdit& e : result.edits) {
        edits.push_back({{"range", positions.range({0, e.begin, e.end})}, {"newText", e.replacement}});
    }
    return edits;
}

json Server::onCompletion(Document& doc, const json& params) {
    std::optional<Published> last = published(doc.uri);
    bool exact = (doc.analysis && doc.analysisVersion == doc.version) || (last && last->version == doc.version);
    if (!exact) {
        // As clangd completes with a stale preamble: the tokens of the current text, and the
        // names in scope from the newest finished analysis if the edits since cannot have
        // changed them, rather than parse, resolve and index the whole text for one request.
        if (std::shared_ptr<const Analysis> older = olderAnalysis(doc)) {
            if (!doc.tokens || doc.tokensVersion != doc.version) {
                doc.tokens = lexOnly(doc.path, doc.text);
                doc.tokensVersion = doc.version;
            }
            Positions positions(doc.tokens->file(), encoding_);
            uint32_t offset = positions.offset(member(params, "position"));
            if (std::optional<uint32_t> at = sameNamesAt(*older, *doc.tokens, offset)) {
                return toJson(complete(*doc.tokens, offset, *older, *at, options_.analysis), positions, snippets_);
            }
        }
    }
    const Analysis& a = analysisOf(doc);
    Positions positions(a.file(), encoding_);
    return toJson(complete(a, positions.offset(member(params, "position")), options_.analysis), positions, snippets_);
}

Server::SerialisedJson Server::onSemanticTokensFull(const DocumentRequest& request) {
    return {encodeSemanticTokens(semanticTokens(request.analysis), request.positions)};
}

Server::SerialisedJson Server::onSemanticTokensRange(const DocumentRequest& request) {
    const json& r = member(request.params, "range");
    SourceRange within{0, request.positions.offset(member(r, "start")), request.positions.offset(member(r, "end"))};
    return {encodeSemanticTokens(semanticTokens(request.analysis, within), request.positions)};
}

json Server::onHover(const DocumentRequest& request) {
    // Values come from the last evaluation, which may be of an older text: the worker
    // evaluates, requests never wait for it.
    std::optional<Published> last = published(request.document.uri);
    const GlobalValues* values = last ? &last->analysis->compilation.globalValues : nullptr;
    auto result = hover(request.analysis, request.position(), values);
    return result ? toJson(*result, request.positions) : json(nullptr);
}

json Server::onSignatureHelp(const DocumentRequest& request) {
    auto help = signatureHelp(request.analysis, request.position());
    return help ? toJson(*help) : json(nullptr);
}

json Server::onDefinition(const DocumentRequest& request) {
    json out = json::array();
    for (const Location& loc : definition(request.analysis, request.position())) {
        out.push_back(location(loc, request.document, request.analysis));
    }
    return out;
}

json Server::onReferences(const DocumentRequest& request) {
    bool declaration = request.params.value("context", json::object()).value("includeDeclaration", true);
    json out = json::array();
    for (const Location& loc : references(request.analysis, request.position(), declaration)) {
        out.push_back(location(loc, request.document, request.analysis));
    }
    return out;
}

json Server::onDocumentHighlight(const DocumentRequest& request) {
    json out = json::array();
    for (const Highlight& h : documentHighlights(request.analysis, request.position())) {
        out.push_back({{"range", request.positions.range(h.range)}, {"kind", h.write ? 3 : 2}});
    }
    return out;
}

json Server::onPrepareRename(const DocumentRequest& request) {
    RenameCheck check = prepareRename(request.analysis, request.position(), options_.analysis);
    if (!check.range) throw LspError(ErrorCode::RequestFailed, check.error);
    return {{"range", request.positions.range(*check.range)}, {"placeholder", check.placeholder}};
}

json Server::onRename(const DocumentRequest& request) {
    const json& newName = member(request.params, "newName");
    if (!newName.is_string()) throw LspError(ErrorCode::InvalidParams, "newName must be a string");
    RenameResult result = rename(request.analysis, request.position(), newName.get<std::string>(), options_.analysis);
    if (!result.error.empty()) throw LspError(ErrorCode::RequestFailed, result.error);
    json changes = json::object();
    for (const Location& loc : result.edits) {
        json l = location(loc, request.document, request.analysis);
        changes[l["uri"].get<std::string>()].push_back({{"range", l["range"]}, {"newText", newName}});
    }
    return {{"changes", changes}};
}

json Server::onDocumentSymbol(const DocumentRequest& request) {
    json out = json::array();
    for (const DocumentSymbol& s : documentSymbols(request.analysis)) out.push_back(toJson(s, request.positions));
    return out;
}

json Server::onFoldingRange(const DocumentRequest& request) {
    json out = json::array();
    for (const FoldingRange& r : foldingRanges(request.analysis)) out.push_back(toJson(r));
    return out;
}

json Server::onCodeAction(const DocumentRequest& request) {
    const Document& doc = request.document;
    const Analysis& a = request.analysis;
    const Positions& positions = request.positions;
    const json& r = member(request.params, "range");
    uint32_t begin = positions.offset(member(r, "start"));
    uint32_t end = positions.offset(member(r, "end"));
    // Fixes from the last evaluation of this very text, else from parse and resolve.
    std::optional<Published> last = published(doc.uri);
    auto diagnostics = last && last->version == doc.version
                           ? last->diagnostics
                           : std::make_shared<const std::vector<DocumentDiagnostic>>(documentDiagnostics(a.compilation));
    json out = json::array();
    for (const CodeAction& action : codeActions(*diagnostics, a.file().text(), begin, end)) {
        json edits = json::array();
        for (const TextEdit& e : action.edits) edits.push_back({{"range", positions.range(e.range)}, {"newText", e.newText}});
        const DocumentDiagnostic& d = (*diagnostics)[action.diagnostic];
        out.push_back({{"title", action.title},
                       {"kind", "quickfix"},
                       {"isPreferred", action.preferred},
                       {"diagnostics", json::array({toJson(d, positions, doc.uri, &a.file(), encoding_)})},
                       {"edit", {{"changes", {{doc.uri, edits}}}}}});
    }
    return out;
}

} // namespace crt::lsp
