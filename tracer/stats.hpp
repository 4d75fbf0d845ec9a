// Counters of the work a render did, per thread and summed.
#pragma once

#include <cstdint>

namespace crt::tracer {

struct RayStats {
    uint64_t cameraRays = 0;
    uint64_t reflectionRays = 0;
    uint64_t refractionRays = 0;
    uint64_t shadowRays = 0;
    uint64_t nodesVisited = 0;      ///< BVH nodes whose box was tested
    uint64_t intersectionTests = 0; ///< primitive line-crossing queries
    uint64_t cachedFrames = 0;      ///< animation frames reused because the scene did not change

    RayStats& operator+=(const RayStats& o) {
        cameraRays += o.cameraRays;
        reflectionRays += o.reflectionRays;
        refractionRays += o.refractionRays;
        shadowRays += o.shadowRays;
        nodesVisited += o.nodesVisited;
        intersectionTests += o.intersectionTests;
        cachedFrames += o.cachedFrames;
        return *this;
    }
    uint64_t totalRays() const { return cameraRays + reflectionRays + refractionRays + shadowRays; }
};

} // namespace crt::tracer
