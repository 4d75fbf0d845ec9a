// The analysis thread: index at once, evaluate after the debounce, cancel on newer text.
#include "diagnostics_worker.hpp"

#include <cstdio>
#include <future>
#include <new>
#include <ostream>

namespace crt::lsp {

DiagnosticsWorker::DiagnosticsWorker(AnalysisOptions options, std::chrono::milliseconds debounce, Finished finished)
    : options_(std::move(options)), debounce_(debounce), finished_(std::move(finished)), thread_([this] { loop(); }) {}

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
        pending_[uri] = Job{version, path, std::move(text), std::chrono::steady_clock::now() + debounce_,
                           generation, nullptr, false};
    }
    wake_.notify_all();
}

void DiagnosticsWorker::forget(const std::string& uri) {
    std::lock_guard lock(mutex_);
    pending_.erase(uri);
    generation_[uri] = nextGeneration_++; // a running evaluation of it stops at its next poll
}

lang::EvalOptions DiagnosticsWorker::evalOptions() const {
    lang::EvalOptions eval = lsp::evalOptions(options_);
    eval.keepGlobalValues = true;
    return eval;
}

bool DiagnosticsWorker::prepareOne(std::unique_lock<std::mutex>& lock) {
    // Indexing waits no longer than the debounce: past it, it runs beside the evaluation.
    auto now = std::chrono::steady_clock::now();
    auto job = pending_.begin();
    while (job != pending_.end() && job->second.parsed && (job->second.indexed || job->second.due <= now)) ++job;
    if (job == pending_.end()) return false;
    std::string uri = job->first;
    uint64_t generation = job->second.generation;
    std::shared_ptr<Analysis> analysis = job->second.parsed; // kept alive if the job is replaced
    try {
        if (!analysis) {
            std::string path = job->second.path;
            std::string text = std::move(job->second.text);
            lock.unlock();
            analysis = std::make_shared<Analysis>();
            analysis->compilation = lang::compile(path, std::move(text), evalOptions(), false);
        } else {
            lock.unlock();
            index(*analysis, analysis->file(), options_, includes_);
        }
    } catch (const std::bad_alloc&) {
        // Evaluation reports this as a diagnostic; a document too big to parse or index in
        // the memory there is has this version dropped, and the server goes on.
        std::fputs("crt-lsp: out of memory analysing a document; that version is skipped\n", stderr);
        lock.lock();
        auto dropped = pending_.find(uri);
        if (dropped != pending_.end() && dropped->second.generation == generation) pending_.erase(dropped);
        return true;
    }
    lock.lock();
    auto again = pending_.find(uri);
    // Else a newer version replaced the job (it is prepared next) or the document closed.
    if (again != pending_.end() && again->second.generation == generation) {
        if (again->second.parsed) again->second.indexed = true;
        again->second.parsed = std::move(analysis);
    }
    return true;
}

void DiagnosticsWorker::evaluateAndFinish(const std::string& uri, Job job) {
    Analysis& analysis = *job.parsed;
    std::future<void> indexing;
    if (!job.indexed) {
        // Taken before the evaluation starts: it may add files to the compilation.
        const lang::SourceFile& file = analysis.file();
        indexing = std::async(std::launch::async, [&] { index(analysis, file, options_, includes_); });
    }
    auto deadline = std::chrono::steady_clock::now() + options_.timeBudget;
    std::ostream discard(nullptr); // print() must never write into the protocol stream
    lang::EvalOptions eval = evalOptions();
    eval.printOut = &discard;
    eval.interrupt = [&] {
        if (std::chrono::steady_clock::now() > deadline) return true;
        std::lock_guard check(mutex_);
        return stop_ || generation_[uri] != job.generation;
    };
    lang::evaluate(analysis.compilation, eval);
    if (indexing.valid()) indexing.get();
    {
        std::lock_guard lock(mutex_);
        if (stop_ || generation_[uri] != job.generation) return;
    }
    finished_(uri, job.version, std::move(job.parsed));
}

void DiagnosticsWorker::loop() {
    std::unique_lock lock(mutex_);
    while (true) {
        if (stop_) return;
        // Parse and index what has not been, before any evaluation falls due: that takes
        // them off the path from the end of the debounce to the diagnostics.
        if (prepareOne(lock)) continue;
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
        evaluateAndFinish(uri, std::move(job));
        lock.lock();
    }
}

} // namespace crt::lsp
