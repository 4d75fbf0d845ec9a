// Closed outlines of straight edges in a plane, and which points they enclose.
#include "tracer/geometry/outline.hpp"

namespace crt::tracer {

Outline::Outline(const std::vector<std::vector<Vec2>>& loops) {
    for (const std::vector<Vec2>& loop : loops) {
        if (loop.size() < 3) continue;
        for (size_t i = 0; i < loop.size(); ++i)
            edges_.push_back({loop[i], loop[(i + 1) % loop.size()]});
    }
}

bool Outline::contains(const Vec2& p) const {
    // Crossings of the ray from p toward +x. Each edge counts its lower end and not its upper
    // one, so a ray through a vertex counts the two edges meeting there once between them.
    bool inside = false;
    for (const Edge& e : edges_) {
        if ((e.a.y > p.y) == (e.b.y > p.y)) continue;
        const double x = e.a.x + (p.y - e.a.y) * (e.b.x - e.a.x) / (e.b.y - e.a.y);
        if (p.x < x) inside = !inside;
    }
    return inside;
}

} // namespace crt::tracer
