// The language server: JSON-RPC dispatch, the open documents and the LSP lifecycle.
#pragma once

#include "analysis.hpp"
#include "diagnostics.hpp"
#include "protocol.hpp"
#include "transport.hpp"

#include <condition_variable>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <thread>
#include <string>
#include <variant>

namespace crt::lsp {

class DiagnosticsWorker;

struct ServerOptions {
    AnalysisOptions analysis;
    std::chrono::milliseconds debounce{20}; ///< quiet time after a change before evaluating
};

class Server {
public:
    Server(Transport& transport, ServerOptions options);
    /// Waits for the reader thread to see the end of the input: a server over a stream that
    /// may never end (standard input) is left to the process's exit, not destroyed.
    ~Server();
    /// Serves until `exit` or the end of input. Returns the process exit code: 0 after a
    /// shutdown request, 1 otherwise (as LSP specifies).
    int run();

private:
    struct Document {
        std::string uri;
        std::string path;
        std::string text;
        int64_t version = 0;
        std::shared_ptr<const Analysis> analysis; ///< of `analysisVersion`, the newest at hand
        int64_t analysisVersion = -1;
        std::shared_ptr<const Analysis> tokens; ///< only the tokens of `tokensVersion`
        int64_t tokensVersion = -1;
    };
    /// What the diagnostics worker last published for a document: immutable, shared by the
    /// requests that read it.
    struct Published {
        int64_t version = -1;
        std::shared_ptr<const Analysis> analysis; ///< evaluated: its global values are for hover
        std::shared_ptr<const std::vector<DocumentDiagnostic>> diagnostics; ///< for code actions
    };

    /// A request about an open document, with the analysis of its current text.
    struct DocumentRequest {
        const json& params;
        Document& document;
        const Analysis& analysis;
        Positions positions; ///< in the analysed text
        /// The offset of `params.position`.
        uint32_t position() const;
    };
    /// A result already serialised, sent as it is: a json array of a whole file's semantic
    /// tokens costs more than everything else in the request.
    struct SerialisedJson {
        std::string text;
    };
    using Result = std::variant<json, SerialisedJson>;
    using RequestHandler = std::function<Result(const json& params)>;
    using NotificationHandler = std::function<void(const json& params)>;

    // Messages: the reader thread queues them, the main thread handles them in order.
    void readerLoop();
    void handle(const json& message);
    void handleNotification(const std::string& method, const json& params);
    void handleRequest(const json& id, const std::string& method, const json& params);
    /// Whether request `id` was cancelled before it was handled (forgetting the cancellation).
    bool takeCancelled(const json& id);
    void reply(const json& id, json result);
    void replyResult(const json& id, Result result);
    void replyError(const json& id, ErrorCode code, const std::string& message);
    void send(const json& message);

    // The method table (clangd's LSPBinder): every method the server answers, bound in
    // bindHandlers(). The overloads of bindRequest() say what a handler is given.
    void bindHandlers();
    void bindRequest(std::string method, json (Server::*handler)(const json& params));
    void bindRequest(std::string method, json (Server::*handler)(Document& document, const json& params));
    void bindRequest(std::string method, json (Server::*handler)(const DocumentRequest& request));
    void bindRequest(std::string method, SerialisedJson (Server::*handler)(const DocumentRequest& request));
    void bindNotification(std::string method, void (Server::*handler)(const json& params));
    /// The handler of `method`; throws MethodNotFound when there is none.
    const RequestHandler& requestHandler(const std::string& method) const;

    // The lifecycle.
    json onInitialize(const json& params);
    void readClientCapabilities(const json& params);
    void readWorkspaceFolders(const json& params);
    void readInitializationOptions(const json& params);
    json serverCapabilities() const;
    void onInitialized(const json& params);
    json onShutdown(const json& params);

    // Text synchronisation and diagnostics.
    void onDidOpen(const json& params);
    void onDidChange(const json& params);
    void onDidSave(const json& params);
    void onDidClose(const json& params);
    void publish(const std::string& uri, int64_t version, std::shared_ptr<const Analysis> analysis);

    Document& document(const json& params);
    DocumentRequest analysedRequest(const json& params);
    const Analysis& analysisOf(Document& document);
    /// An analysis of an older version of the document, the newest at hand (or null).
    std::shared_ptr<const Analysis> olderAnalysis(Document& document);
    std::optional<Published> published(const std::string& uri);
    json location(const Location& location, const Document& document, const Analysis& analysis);

    // The features, one request each.
    json onFormatting(Document& document, const json& params);
    json onRangeFormatting(Document& document, const json& params);
    json formattingEdits(const Document& document, const json& params, bool onlyRange);
    json onCompletion(Document& document, const json& params);
    SerialisedJson onSemanticTokensFull(const DocumentRequest& request);
    SerialisedJson onSemanticTokensRange(const DocumentRequest& request);
    json onHover(const DocumentRequest& request);
    json onSignatureHelp(const DocumentRequest& request);
    json onDefinition(const DocumentRequest& request);
    json onReferences(const DocumentRequest& request);
    json onDocumentHighlight(const DocumentRequest& request);
    json onPrepareRename(const DocumentRequest& request);
    json onRename(const DocumentRequest& request);
    json onDocumentSymbol(const DocumentRequest& request);
    json onFoldingRange(const DocumentRequest& request);
    json onCodeAction(const DocumentRequest& request);

    std::map<std::string, RequestHandler, std::less<>> requests_;
    std::map<std::string, NotificationHandler, std::less<>> notifications_;

    Transport& transport_;
    ServerOptions options_;
    OffsetEncoding encoding_ = OffsetEncoding::Utf16;
    bool snippets_ = false;
    bool initialized_ = false;
    bool shutdown_ = false;
    std::map<std::string, Document> documents_;
    /// Analyses replaced while answering a request, freed once the answer is out.
    std::vector<std::shared_ptr<const Analysis>> retired_;
    IncludeCache includes_;
    std::unique_ptr<DiagnosticsWorker> worker_;

    std::mutex publishedMutex_;
    std::map<std::string, Published> published_;

    // Messages read by the reader thread, handled in order by the main thread.
    std::mutex queueMutex_;
    std::condition_variable queueReady_;
    std::deque<std::optional<json>> queue_; ///< nullopt: end of input
    std::set<std::string> cancelled_;       ///< ids (as JSON text) of cancelled requests
    std::thread reader_; ///< runs readerLoop() until the end of input, even after `exit`
};

} // namespace crt::lsp
