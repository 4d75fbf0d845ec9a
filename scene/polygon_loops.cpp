// A polygon's points as POV-Ray reads them (see polygon_loops.hpp).
#include "scene/polygon_loops.hpp"

namespace crt::scene {

std::vector<std::vector<glm::dvec3>> polygonLoops(std::span<const glm::dvec3> points) {
    std::vector<std::vector<glm::dvec3>> loops;
    std::vector<glm::dvec3> loop;
    for (const glm::dvec3& p : points) {
        if (!loop.empty() && p == loop.front()) {
            loops.push_back(std::move(loop));
            loop.clear();
            continue;
        }
        loop.push_back(p);
    }
    if (!loop.empty()) loops.push_back(std::move(loop));
    return loops;
}

glm::dvec3 newellNormal(std::span<const glm::dvec3> loop) {
    glm::dvec3 n(0.0);
    for (size_t i = 0; i < loop.size(); ++i) {
        const glm::dvec3& a = loop[i];
        const glm::dvec3& b = loop[(i + 1) % loop.size()];
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
    }
    return n;
}

} // namespace crt::scene
