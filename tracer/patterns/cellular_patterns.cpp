// Cellular patterns: a random feature point or a random value in each unit cube of space.
#include "tracer/patterns/pattern_functions.hpp"

#include <array>
#include <cmath>
#include <cstdint>

namespace crt::tracer::patterns {

namespace {

/// A well-mixed 32-bit hash of a cube's integer corner and a salt (a Murmur3-style finaliser).
uint32_t cubeHash(int64_t x, int64_t y, int64_t z, uint32_t salt) {
    uint64_t h = static_cast<uint64_t>(x) * 0x9E3779B97F4A7C15ull ^
                 static_cast<uint64_t>(y) * 0xC2B2AE3D27D4EB4Full ^
                 static_cast<uint64_t>(z) * 0x165667B19E3779F9ull ^ salt;
    h ^= h >> 33;
    h *= 0xFF51AFD7ED558CCDull;
    h ^= h >> 33;
    h *= 0xC4CEB9FE1A85EC53ull;
    h ^= h >> 33;
    return static_cast<uint32_t>(h);
}

double unitRandom(int64_t x, int64_t y, int64_t z, uint32_t salt) {
    return cubeHash(x, y, z, salt) * (1.0 / 4294967296.0);
}

double distance(const Vec3& d, double metric) {
    if (metric == 2) return std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    if (metric == 1) return std::abs(d.x) + std::abs(d.y) + std::abs(d.z);
    return std::pow(std::pow(std::abs(d.x), metric) + std::pow(std::abs(d.y), metric) +
                        std::pow(std::abs(d.z), metric),
                    1 / metric);
}

} // namespace

double crackle(const Vec3& p, double metric, const Vec3& form) {
    // The three nearest feature points, one at a random place in each unit cube, among the
    // 27 cubes around p (Worley's cellular noise, POV-Ray's crackle).
    int64_t cx = static_cast<int64_t>(std::floor(p.x)), cy = static_cast<int64_t>(std::floor(p.y)),
            cz = static_cast<int64_t>(std::floor(p.z));
    std::array<double, 3> nearest{1e30, 1e30, 1e30};
    for (int64_t x = cx - 1; x <= cx + 1; ++x) {
        for (int64_t y = cy - 1; y <= cy + 1; ++y) {
            for (int64_t z = cz - 1; z <= cz + 1; ++z) {
                Vec3 feature(static_cast<double>(x) + unitRandom(x, y, z, 1),
                             static_cast<double>(y) + unitRandom(x, y, z, 2),
                             static_cast<double>(z) + unitRandom(x, y, z, 3));
                double d = distance(feature - p, metric);
                if (d < nearest[2]) {
                    nearest[2] = d;
                    if (nearest[2] < nearest[1]) std::swap(nearest[1], nearest[2]);
                    if (nearest[1] < nearest[0]) std::swap(nearest[0], nearest[1]);
                }
            }
        }
    }
    return form.x * nearest[0] + form.y * nearest[1] + form.z * nearest[2];
}

double cells(const Vec3& p) {
    return unitRandom(static_cast<int64_t>(std::floor(p.x + 1e-10)),
                      static_cast<int64_t>(std::floor(p.y + 1e-10)),
                      static_cast<int64_t>(std::floor(p.z + 1e-10)), 0);
}

} // namespace crt::tracer::patterns
