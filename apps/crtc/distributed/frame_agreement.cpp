// Every rank evaluates the frame; the ranks check that they built the same scene.
#include "frame_agreement.hpp"

#include "frame_hash.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <exception>
#include <fstream>
#include <functional>
#include <iostream>

namespace crt::crtc::distributed {

namespace {

/// On rank 0: receives the messages of the `failures` other ranks that could not evaluate, and
/// prints them if rank 0 evaluated the frame (else they repeat, as a rule, what it printed).
void reportFailures(MpiSession& session, int frame, uint64_t failures, bool print) {
    for (uint64_t i = 0; i < failures; ++i) {
        int source = 0;
        const std::vector<char> text = session.receiveFromAny(kEvaluationTag, source);
        if (print)
            std::cerr << fmt::format("crtc: {} cannot evaluate frame {}:\n{}", session.describe(source),
                                 frame, std::string(text.begin(), text.end()));
    }
}

/// The message for ranks that evaluated different scenes: `what` is "frame 3", "the script".
void reportDifferentScenes(const std::string& what) {
    std::cerr << fmt::format(
        "crtc: the processes of the MPI job evaluated different scenes for {}: the script, a "
        "file it includes, an image or mesh it reads (compared by size and modification time) "
        "or crtc itself differs between the machines; give each the same files (copied with "
        "their times, e.g. rsync -a) and the same crtc\n",
        what);
}

} // namespace

bool sameScriptOnEveryRank(MpiSession& session, const Options& options) {
    std::ifstream file(options.script, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    const std::string identity = fmt::format("{}\n{}\n{}", CRT_VERSION, options.script, text);
    const uint64_t hash = std::hash<std::string>{}(identity) ^ identity.size();
    const auto [least, greatest] = session.rangeOverRanks(hash);
    if (least != greatest && session.root()) reportDifferentScenes("the script");
    return least == greatest;
}

bool evaluateOnThisRank(int rank, const CompileFrame& compileFrame, int frame,
                        lang::Compilation& c, std::string& why) {
    const char* failing = std::getenv(kTestFailRankVariable);
    if (failing && std::to_string(rank) == failing) {
        why = fmt::format("crtc: evaluation failed on purpose ({}={})\n", kTestFailRankVariable, rank);
        return false;
    }
    try {
        if (compileFrame(frame, c) && c.scene) return true;
    } catch (const std::exception& e) {
        why = fmt::format("crtc: {}\n", e.what());
    }
    return false;
}

bool evaluateOnEveryRank(MpiSession& session, const Options& options,
                         const CompileFrame& compileFrame, int frame, lang::Compilation& c,
                         CapturedErrors* captured) {
    std::string why;
    const bool ok = evaluateOnThisRank(session.rank(), compileFrame, frame, c, why);
    if (captured) {
        why = captured->take() + why;
    } else if (!why.empty()) {
        std::cerr << why;
    }
    const uint64_t failures = session.sumOverRanks(ok ? 0 : 1);
    const uint64_t hash = ok ? frameHash(c, *c.scene, options, tracer::Tile{}) : 0;
    const auto [least, greatest] = session.rangeOverRanks(hash);
    // After the reductions, which every rank reaches: rank 0 is then waiting for these.
    if (!ok && !session.root()) session.send(0, kEvaluationTag, why.data(), why.size());
    if (session.root() && failures > 0)
        reportFailures(session, frame, ok ? failures : failures - 1, ok);
    if (failures > 0) return false;
    if (least != greatest && session.root()) reportDifferentScenes(fmt::format("frame {}", frame));
    return least == greatest;
}

} // namespace crt::crtc::distributed
