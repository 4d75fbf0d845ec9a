// Analyses documents off the main thread: indexes each change at once, evaluates it debounced,
// and drops the work of stale text.
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

/// One background thread that runs the whole front end on the latest text of each document.
/// A change is parsed, resolved and indexed as soon as it arrives (the thread would otherwise
/// sit idle through the debounce); the evaluation, the unbounded part, waits until the text has
/// been quiet for the debounce delay. If the index is not done by then (a slow machine, a huge
/// text), it is finished on a second thread while the evaluation runs. A newer version of a
/// document drops the preparation of an older one and cancels its evaluation (through the
/// interpreter's interrupt hook), and every evaluation stops at the time budget, so
/// `while (true) {}` costs at most that.
class DiagnosticsWorker {
public:
    /// Receives each evaluated version, indexed: its compilation holds the evaluation's
    /// diagnostics and global values. Called on the worker thread, which never touches the
    /// analysis again, so the receiver may hand it to other threads.
    using Finished = std::function<void(const std::string& uri, int64_t version, std::shared_ptr<const Analysis> analysis)>;

    DiagnosticsWorker(AnalysisOptions options, std::chrono::milliseconds debounce, Finished finished);
    ~DiagnosticsWorker();
    DiagnosticsWorker(const DiagnosticsWorker&) = delete;
    DiagnosticsWorker& operator=(const DiagnosticsWorker&) = delete;

    /// Indexes `text` now and evaluates it after the debounce delay, unless a newer version
    /// comes first.
    void schedule(const std::string& uri, int64_t version, const std::string& path, std::string text);
    /// Drops pending and running work for `uri` (the document was closed).
    void forget(const std::string& uri);

private:
    struct Job {
        int64_t version;
        std::string path;
        std::string text; ///< moved out when parsing starts
        std::chrono::steady_clock::time_point due;
        uint64_t generation;
        std::shared_ptr<Analysis> parsed; ///< parsed and resolved; not evaluated yet
        bool indexed = false;             ///< `parsed` is indexed too
    };
    void loop();
    /// Parses and resolves a job, or indexes one not due yet; false if none needs it.
    bool prepareOne(std::unique_lock<std::mutex>& lock);
    void evaluateAndFinish(const std::string& uri, Job job);
    lang::EvalOptions evalOptions() const;

    AnalysisOptions options_;
    std::chrono::milliseconds debounce_;
    Finished finished_;
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
