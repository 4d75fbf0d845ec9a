// Evaluates documents off the main thread, debounced, dropping analyses of stale text.
#pragma once

#include "analysis.hpp"

#include <condition_variable>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

namespace crt::lsp {

/// One background thread that runs the whole front end (evaluation included) on the latest
/// text of each document and hands the result to `publish`. A newer version of a document
/// cancels the evaluation of an older one (through the interpreter's interrupt hook), and
/// every evaluation stops at the time budget, so `while (true) {}` costs at most that.
class DiagnosticsWorker {
public:
    /// Receives the evaluation, as soon as it is done; called on the worker thread.
    using Publish = std::function<void(const std::string& uri, int64_t version, const lang::Compilation& compilation)>;
    /// Then receives the same compilation indexed, for the requests that follow.
    using Ready = std::function<void(const std::string& uri, int64_t version, std::shared_ptr<const Analysis> analysis)>;

    DiagnosticsWorker(AnalysisOptions options, std::chrono::milliseconds debounce, Publish publish, Ready ready);
    ~DiagnosticsWorker();
    DiagnosticsWorker(const DiagnosticsWorker&) = delete;
    DiagnosticsWorker& operator=(const DiagnosticsWorker&) = delete;

    /// Evaluates `text` after the debounce delay, unless a newer version comes first.
    void schedule(const std::string& uri, int64_t version, const std::string& path, std::string text);
    /// Drops pending and running work for `uri` (the document was closed).
    void forget(const std::string& uri);

private:
    struct Job {
        int64_t version;
        std::string path;
        std::string text;
        std::chrono::steady_clock::time_point due;
        uint64_t generation;
    };
    void loop();

    AnalysisOptions options_;
    std::chrono::milliseconds debounce_;
    Publish publish_;
    Ready ready_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::map<std::string, Job> pending_;
    std::map<std::string, uint64_t> generation_; ///< latest per document
    IncludeCache includes_; ///< the worker's own: the cache is for one thread
    uint64_t nextGeneration_ = 1;
    bool stop_ = false;
    std::thread thread_;
};

} // namespace crt::lsp
