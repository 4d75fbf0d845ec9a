// The messages of an animation shared out by frames.
#include "frame_message.hpp"

namespace crt::crtc::distributed {

FrameDone frameDoneOf(const tracer::RenderOutcome& outcome) {
    const tracer::RayStats& s = outcome.stats;
    FrameDone done;
    const uint64_t rays[7] = {s.cameraRays,   s.reflectionRays,    s.refractionRays, s.shadowRays,
                              s.nodesVisited, s.intersectionTests, s.cachedFrames};
    std::memcpy(done.rays, rays, sizeof rays);
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
    const uint64_t* r = done.rays;
    outcome.stats = tracer::RayStats{r[0], r[1], r[2], r[3], r[4], r[5], r[6]};
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
