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
    void publish(const std::string& uri, int64_t version, std::shared_ptr<const Analysis> analysis);

    Document& document(const json& params);
    const Analysis& analysisOf(Document& document);
    /// An analysis of an older version of the document, the newest at hand (or null).
    std::shared_ptr<const Analysis> olderAnalysis(Document& document);
    json completion(Document& document, const json& params);
    std::optional<Published> published(const std::string& uri);
    json location(const Location& location, const Document& document, const Analysis& analysis);

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
};

} // namespace crt::lsp
