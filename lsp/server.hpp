// The language server: JSON-RPC dispatch, the open documents and the LSP lifecycle.
#pragma once

#include "analysis.hpp"
#include "diagnostics.hpp"
#include "protocol.hpp"
#include "transport.hpp"

#include <condition_variable>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>

namespace crt::lsp {

class DiagnosticsWorker;

struct ServerOptions {
    AnalysisOptions analysis;
    std::chrono::milliseconds debounce{20}; ///< quiet time after a change before evaluating
};

class Server {
public:
    Server(Transport& transport, ServerOptions options);
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
        std::shared_ptr<const Analysis> analysis; ///< of `version`, made on demand
        int64_t analysisVersion = -1;
    };
    /// What the diagnostics worker last published for a document.
    struct Published {
        int64_t version = -1;
        std::shared_ptr<const Analysis> analysis; ///< the same, indexed (set a little later)
        std::vector<DocumentDiagnostic> diagnostics;
        GlobalValues values; ///< for hover
    };

    void readerLoop();
    void handle(const json& message);
    json dispatch(const std::string& method, const json& params);
    void notification(const std::string& method, const json& params);
    void reply(const json& id, json result);
    /// A result already serialised (semantic tokens), set by dispatch instead of its value.
    std::optional<std::string> rawResult_;
    void replyError(const json& id, ErrorCode code, const std::string& message);
    void send(const json& message);

    json initialize(const json& params);
    void didOpen(const json& params);
    void didChange(const json& params);
    void didClose(const json& params);
    void publish(const std::string& uri, int64_t version, const lang::Compilation& compilation);
    void ready(const std::string& uri, int64_t version, std::shared_ptr<const Analysis> analysis);

    Document& document(const json& params);
    const Analysis& analysisOf(Document& document);
    std::optional<Published> published(const std::string& uri);
    json location(const Location& location, const Document& document, const Analysis& analysis);

    Transport& transport_;
    ServerOptions options_;
    OffsetEncoding encoding_ = OffsetEncoding::Utf16;
    bool snippets_ = false;
    bool initialized_ = false;
    bool shutdown_ = false;
    std::map<std::string, Document> documents_;
    IncludeCache includes_;
    std::unique_ptr<DiagnosticsWorker> worker_;

    std::mutex publishedMutex_;
    std::condition_variable analysisReady_;
    std::map<std::string, Published> published_;

    // Messages read by the reader thread, handled in order by the main thread.
    std::mutex queueMutex_;
    std::condition_variable queueReady_;
    std::deque<std::optional<json>> queue_; ///< nullopt: end of input
    std::set<std::string> cancelled_;       ///< ids (as JSON text) of cancelled requests
};

} // namespace crt::lsp
