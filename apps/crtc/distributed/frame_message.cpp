// The messages of an animation shared out by frames.
#include "frame_message.hpp"

#include <algorithm>
#include <iterator>

namespace crt::crtc::distributed {

FrameDone frameDoneOf(const tracer::RenderOutcome& outcome) {
    const tracer::RayStats& s = outcome.stats;
    FrameDone done;
    const auto summed = s.summed();
    const auto greatest = s.greatest();
    std::copy(summed.begin(), summed.end(), done.summed);
    std::copy(greatest.begin(), greatest.end(), done.greatest);
    done.buildSeconds = outcome.buildSeconds;
    done.renderSeconds = outcome.renderSeconds;
    done.primitives = outcome.primitives;
    done.drawnPrimitives = outcome.drawnPrimitives;
    done.sceneBytes = outcome.sceneBytes;
    done.peakBytes = outcome.peakBytes;
    done.bvhNodes = outcome.bvhNodes;
    done.bvhDepth = outcome.bvhDepth;
    done.ok = outcome.ok ? 1 : 0;
    return done;
}

tracer::RenderOutcome outcomeOf(const FrameDone& done) {
    tracer::RenderOutcome outcome;
    std::array<uint64_t, tracer::RayStats::kSummed> summed{};
    std::array<uint64_t, tracer::RayStats::kGreatest> greatest{};
    std::copy(std::begin(done.summed), std::end(done.summed), summed.begin());
    std::copy(std::begin(done.greatest), std::end(done.greatest), greatest.begin());
    outcome.stats = tracer::RayStats::fromCounters(summed, greatest);
    outcome.buildSeconds = done.buildSeconds;
    outcome.renderSeconds = done.renderSeconds;
    outcome.primitives = done.primitives;
    outcome.drawnPrimitives = done.drawnPrimitives;
    outcome.sceneBytes = done.sceneBytes;
    outcome.peakBytes = done.peakBytes;
    outcome.bvhNodes = done.bvhNodes;
    outcome.bvhDepth = done.bvhDepth;
    outcome.ok = done.ok != 0;
    return outcome;
}

} // namespace crt::crtc::distributed
