// The analysis thread: an evaluated, indexed analysis per quiet version; newer text wins.
#include "annotations.hpp"
#include "diagnostics_worker.hpp"

#include <algorithm>
#include <condition_variable>
#include <mutex>

using namespace crt::lsp;
using namespace crt::lsp::test;
using namespace std::chrono_literals;

namespace {

/// Collects what the worker finishes, for the test thread to wait on.
struct Finished {
    std::mutex mutex;
    std::condition_variable changed;
    std::vector<std::pair<int64_t, std::shared_ptr<const Analysis>>> analyses;

    DiagnosticsWorker::Finished callback() {
        return [this](const std::string&, int64_t version, std::shared_ptr<const Analysis> analysis) {
            std::lock_guard lock(mutex);
            analyses.emplace_back(version, std::move(analysis));
            changed.notify_all();
        };
    }
    bool waitFor(size_t count) {
        std::unique_lock lock(mutex);
        return changed.wait_for(lock, 10s, [&] { return analyses.size() >= count; });
    }
};

bool hasMessage(const crt::lang::Compilation& c, std::string_view text) {
    for (const auto& d : c.diagnostics.items()) {
        if (d.message.find(text) != std::string::npos) return true;
    }
    return false;
}

const std::string kScript = "size = 2\n"
                            "corner = vec3(0, 0, 0)\n"
                            "Scene { Box { cornerA -> corner cornerB -> corner } }\n";

} // namespace

TEST_CASE("a resolved compilation evaluated later says what compile() says", "[worker]") {
    crt::lang::EvalOptions options;
    options.keepGlobalValues = true;
    crt::lang::Compilation whole = crt::lang::compile("w.crt", kScript, options);
    crt::lang::Compilation later = crt::lang::compile("w.crt", kScript, options, false);
    CHECK(later.globalValues.empty());
    crt::lang::evaluate(later, options);
    REQUIRE(whole.diagnostics.items().size() == later.diagnostics.items().size());
    for (size_t i = 0; i < whole.diagnostics.items().size(); ++i) {
        CHECK(whole.diagnostics.items()[i].message == later.diagnostics.items()[i].message);
        CHECK(whole.diagnostics.items()[i].range == later.diagnostics.items()[i].range);
    }
    CHECK(hasMessage(later, "same point"));
    CHECK(later.globalValues == whole.globalValues);
    CHECK(!later.globalValues.empty());
}

TEST_CASE("the worker hands over each quiet version evaluated and indexed", "[worker]") {
    Finished finished;
    DiagnosticsWorker worker(testOptions(), 10ms, finished.callback());
    worker.schedule("file:///w.crt", 1, "/tmp/w.crt", kScript);
    REQUIRE(finished.waitFor(1));
    std::lock_guard lock(finished.mutex);
    REQUIRE(finished.analyses.size() == 1);
    const auto& [version, analysis] = finished.analyses[0];
    CHECK(version == 1);
    // Evaluated: runtime errors and global values are there.
    CHECK(hasMessage(analysis->compilation, "same point"));
    CHECK(analysis->compilation.globalValues.size() == 2);
    // Indexed: tokens, names and their uses.
    CHECK(!analysis->tokens.empty());
    const Symbol* corner = analysis->lookup("corner", 0);
    REQUIRE(corner);
    CHECK(corner->definition.has_value());
    const auto& symbols = analysis->symbols; // a structured binding: clang 14 cannot capture one
    auto uses = std::count_if(analysis->occurrences.begin(), analysis->occurrences.end(), [&](const Occurrence& o) {
        return &symbols[o.symbol] == corner;
    });
    CHECK(uses == 3);
}

TEST_CASE("a newer version replaces one still waiting for the debounce", "[worker]") {
    Finished finished;
    DiagnosticsWorker worker(testOptions(), 200ms, finished.callback());
    worker.schedule("file:///w.crt", 1, "/tmp/w.crt", kScript);
    worker.schedule("file:///w.crt", 2, "/tmp/w.crt", "x = 1\nScene { }\n");
    REQUIRE(finished.waitFor(1));
    std::this_thread::sleep_for(300ms); // version 1 must never come
    std::lock_guard lock(finished.mutex);
    REQUIRE(finished.analyses.size() == 1);
    CHECK(finished.analyses[0].first == 2);
    CHECK(finished.analyses[0].second->lookup("x", 0) != nullptr);
}

TEST_CASE("a closed document is never handed over", "[worker]") {
    Finished finished;
    {
        DiagnosticsWorker worker(testOptions(), 100ms, finished.callback());
        worker.schedule("file:///w.crt", 1, "/tmp/w.crt", kScript);
        worker.forget("file:///w.crt");
        std::this_thread::sleep_for(250ms);
    }
    CHECK(finished.analyses.empty());
}
