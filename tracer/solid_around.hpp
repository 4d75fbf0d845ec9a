// Which solid a camera stands in: a camera inside a room full of haze, or under water, sees
// through what fills it from its first step, as a ray that had entered the solid would.
#pragma once

#include "tracer/lights.hpp"
#include "tracer/material_mix.hpp"
#include "tracer/render_scene.hpp"

#include <limits>

namespace crt::tracer {

/// The last answer of solidAround, kept per thread: a camera without an aperture, standing
/// still, asks about one point all render long.
struct SolidAroundCache {
    static constexpr double kUnasked = std::numeric_limits<double>::quiet_NaN();
    Vec3 point{kUnasked};
    double time = kUnasked;
    int32_t material = -1;
};

/// Whether material `m` fills the solids it bounds: a medium, or absorption.
inline bool fillsSolid(const ShadingMaterial& m) { return m.medium >= 0 || rgb(m.absorption) != Vec3(0.0); }

/// Whether some material fills the solids it bounds (a medium, or absorption), which is
/// what rays inside a solid are tracked for. Blends are not counted.
bool fillsSolids(const RenderScene& scene, const MaterialMixer& mixer);

/// The material filling the solid around `point` at `time`, or -1 when the point is in no
/// filled solid. Surfaces hidden from the camera (when `hides`) do not count, as camera
/// rays cross them as if they were not there. The crossings of one fixed line through the
/// point decide, so the answer depends on the point alone: the solid whose first crossing
/// after the point leaves it is around it (the nearest, where several are: the innermost).
/// Its search is not counted in the ray statistics, which then stay the same whatever the
/// number of threads (each asks once).
int32_t solidAround(const RenderScene& scene, const MaterialMixer& mixer, bool hides, const Vec3& point,
                    double time, QueryScratch& scratch, SolidAroundCache& cache);

} // namespace crt::tracer
