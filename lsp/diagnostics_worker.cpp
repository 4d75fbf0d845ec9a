// The evaluation thread: debounce, cancel on newer text, time budget, publish.
#include "diagnostics_worker.hpp"

#include <ostream>

namespace crt::lsp {

DiagnosticsWorker::DiagnosticsWorker(AnalysisOptions options, std::chrono::milliseconds debounce, Publish publish,
                                     Ready ready)
    : options_(std::move(options)), debounce_(debounce), publish_(std::move(publish)), ready_(std::move(ready)),
      thread_([this] { loop(); }) {}

DiagnosticsWorker::~DiagnosticsWorker() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

void DiagnosticsWorker::schedule(const std::string& uri, int64_t version, const std::string& path, std::string text) {
    {
        std::lock_guard lock(mutex_);
        uint64_t generation = nextGeneration_++;
        generation_[uri] = generation;
        pending_[uri] = Job{version, path, std::move(text), std::chrono::steady_clock::now() + debounce_, generation};
    }
    wake_.notify_all();
}

void DiagnosticsWorker::forget(const std::string& uri) {
    std::lock_guard lock(mutex_);
    pending_.erase(uri);
    generation_[uri] = nextGeneration_++; // a running evaluation of it stops at its next poll
}

void DiagnosticsWorker::loop() {
    std::unique_lock lock(mutex_);
    while (true) {
        if (stop_) return;
        if (pending_.empty()) {
            wake_.wait(lock);
            continue;
        }
        auto next = pending_.begin();
        for (auto it = pending_.begin(); it != pending_.end(); ++it) {
            if (it->second.due < next->second.due) next = it;
        }
        if (std::chrono::steady_clock::now() < next->second.due) {
            wake_.wait_until(lock, next->second.due);
            continue;
        }
        std::string uri = next->first;
        Job job = std::move(next->second);
        pending_.erase(next);
        lock.unlock();

        auto deadline = std::chrono::steady_clock::now() + options_.timeBudget;
        std::ostream discard(nullptr); // print() must never write into the protocol stream
        lang::EvalOptions eval;
        eval.limits = options_.limits;
        eval.includeDirs = options_.includeDirs;
        eval.stdlibDir = options_.stdlibDir;
        eval.printOut = &discard;
        eval.keepGlobalValues = true;
        eval.interrupt = [&] {
            if (std::chrono::steady_clock::now() > deadline) return true;
            std::lock_guard check(mutex_);
            return stop_ || generation_[uri] != job.generation;
        };
        lang::Compilation compilation = lang::compile(job.path, std::move(job.text), eval);

        lock.lock();
        bool current = !stop_ && generation_[uri] == job.generation;
        if (!current) continue;
        lock.unlock();
        publish_(uri, job.version, compilation);
        // Indexed after publishing, so the requests after a change find the analysis ready.
        ready_(uri, job.version, analyze(std::move(compilation), options_, includes_));
        lock.lock();
    }
}

} // namespace crt::lsp
