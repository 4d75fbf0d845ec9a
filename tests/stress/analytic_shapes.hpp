// Independent nearest hits of a ray with each primitive, for the stress tests' expectations.
//
// Written from the shapes' definitions (docs/rendering.md, spec §6), not from the renderer's
// code, and only used away from rounding-sized margins (see stress::coverage): the camera is
// always outside solids, so the nearest hit is where the ray enters.
#pragma once

#include "stress_util.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace crt::tracer::stress {

struct SurfaceHit {
    double t = 0;
    DVec3 normal{0.0}; ///< unit; outward for solids, the shape's own normal for sheets
};

/// Completes unit `w` to an orthonormal frame (any one: the tests only need some frame).
inline void completeFrame(DVec3 w, DVec3& u, DVec3& v) {
    DVec3 helper = std::abs(w.x) < 0.6 ? DVec3(1, 0, 0) : DVec3(0, 1, 0);
    u = glm::normalize(glm::cross(helper, w));
    v = glm::cross(w, u);
}

inline std::optional<SurfaceHit> sphereHit(const TestRay& ray, DVec3 center, double radius) {
    // From the closest approach to the centre, which keeps tangent rays accurate.
    DVec3 f = ray.origin - center;
    double b = glm::dot(f, ray.dir);
    DVec3 closest = f - b * ray.dir;
    double h = radius * radius - glm::dot(closest, closest);
    if (h < 0) return std::nullopt;
    double t = -b - std::sqrt(h);
    if (t <= 0) return std::nullopt;
    return SurfaceHit{t, glm::normalize(ray.at(t) - center)};
}

inline std::optional<SurfaceHit> planeHit(const TestRay& ray, DVec3 normal, DVec3 point) {
    DVec3 n = glm::normalize(normal);
    double along = glm::dot(ray.dir, n);
    if (along == 0) return std::nullopt;
    double t = glm::dot(point - ray.origin, n) / along;
    if (!(t > 0) || !std::isfinite(t)) return std::nullopt;
    return SurfaceHit{t, n};
}

inline std::optional<SurfaceHit> boxHit(const TestRay& ray, DVec3 lo, DVec3 hi) {
    double enter = -std::numeric_limits<double>::infinity();
    double exit = std::numeric_limits<double>::infinity();
    DVec3 normal(0.0);
    for (int a = 0; a < 3; ++a) {
        if (ray.dir[a] == 0) {
            if (ray.origin[a] < lo[a] || ray.origin[a] > hi[a]) return std::nullopt;
            continue;
        }
        double t0 = (lo[a] - ray.origin[a]) / ray.dir[a], t1 = (hi[a] - ray.origin[a]) / ray.dir[a];
        double sign = -1;
        if (t0 > t1) std::swap(t0, t1), sign = 1;
        if (t0 > enter) {
            enter = t0;
            normal = DVec3(0.0);
            normal[a] = sign;
        }
        exit = std::min(exit, t1);
    }
    if (!(enter <= exit) || !(enter > 0)) return std::nullopt;
    return SurfaceHit{enter, normal};
}

/// A capped cylinder or cone (frustum) from `base` (radius r0) to `top` (radius r1).
inline std::optional<SurfaceHit> axialHit(const TestRay& ray, DVec3 base, DVec3 top, double r0,
                                          double r1) {
    DVec3 axis = top - base, w = glm::normalize(axis), u, v;
    completeFrame(w, u, v);
    double h = glm::length(axis), k = (r1 - r0) / h;
    DVec3 rel = ray.origin - base;
    // Recentred at the closest approach to the axis' middle, so tangent rays stay accurate.
    DVec3 o(glm::dot(rel, u), glm::dot(rel, v), glm::dot(rel, w));
    DVec3 d(glm::dot(ray.dir, u), glm::dot(ray.dir, v), glm::dot(ray.dir, w));
    double tc = -glm::dot(o - DVec3(0, 0, 0.5 * h), d);
    DVec3 q = o + tc * d;
    // x² + y² ≤ (r0 + k·z)² along the line: a·s² + 2·b·s + c ≤ 0.
    double rz = r0 + k * q.z, kd = k * d.z;
    double a = d.x * d.x + d.y * d.y - kd * kd, b = q.x * d.x + q.y * d.y - rz * kd;
    double c = q.x * q.x + q.y * q.y - rz * rz;
    constexpr double inf = std::numeric_limits<double>::infinity();
    std::vector<std::array<double, 2>> pieces;
    double disc = b * b - a * c;
    if (a > 0) {
        if (disc < 0) return std::nullopt;
        pieces.push_back({(-b - std::sqrt(disc)) / a, (-b + std::sqrt(disc)) / a});
    } else if (a < 0) {
        if (disc < 0) {
            pieces.push_back({-inf, inf});
        } else {
            double s0 = (-b + std::sqrt(disc)) / a, s1 = (-b - std::sqrt(disc)) / a;
            pieces.push_back({-inf, std::min(s0, s1)});
            pieces.push_back({std::max(s0, s1), inf});
        }
    } else {
        return std::nullopt; // parallel to a generatrix: not a case the tests aim at
    }
    if (d.z == 0) return std::nullopt; // the tests never look exactly across the axis
    double z0 = -q.z / d.z, z1 = (h - q.z) / d.z;
    std::array<double, 2> slab{std::min(z0, z1), std::max(z0, z1)};
    std::optional<SurfaceHit> best;
    for (const auto& piece : pieces) {
        double lo = std::max(piece[0], slab[0]), hi = std::min(piece[1], slab[1]);
        if (!(lo <= hi) || !(tc + lo > 0) || (best && best->t <= tc + lo)) continue;
        DVec3 p = q + lo * d;
        DVec3 n;
        if (piece[0] >= slab[0]) { // through the side
            double rho = std::sqrt(p.x * p.x + p.y * p.y);
            n = (p.x / rho) * u + (p.y / rho) * v - k * w;
        } else { // through a cap
            n = d.z > 0 ? -w : w;
        }
        best = SurfaceHit{tc + lo, glm::normalize(n)};
    }
    return best;
}

/// A torus around `axis` through `center`; the crossings are sign changes of the tube's own
/// equation (ρ − R)² + z² − r², sampled along the line and refined.
inline std::optional<SurfaceHit> torusHit(const TestRay& ray, DVec3 center, double major,
                                          double minor, DVec3 axis) {
    DVec3 w = glm::normalize(axis), u, v;
    completeFrame(w, u, v);
    DVec3 rel = ray.origin - center;
    double tc = -glm::dot(rel, ray.dir);
    double ox = glm::dot(rel, u), oy = glm::dot(rel, v), oz = glm::dot(rel, w);
    double dx = glm::dot(ray.dir, u), dy = glm::dot(ray.dir, v), dz = glm::dot(ray.dir, w);
    double R = major, r = minor;
    auto f = [&](double t) {
        double x = ox + t * dx, y = oy + t * dy, z = oz + t * dz;
        double rho = std::sqrt(x * x + y * y);
        return (rho - R) * (rho - R) + z * z - r * r;
    };
    double cx = ox + tc * dx, cy = oy + tc * dy, cz = oz + tc * dz;
    double bound = (R + r) * (R + r) - (cx * cx + cy * cy + cz * cz);
    if (bound < 0) return std::nullopt;
    double half = std::sqrt(bound);
    auto bisect = [&](double lo, double hi) { // f(lo) ≥ 0 > f(hi), down to adjacent doubles
        for (int i = 0; i < 200; ++i) {
            double mid = 0.5 * (lo + hi);
            if (!(mid > lo && mid < hi)) break;
            (f(mid) < 0 ? hi : lo) = mid;
        }
        return hi;
    };
    // The lowest point of a dip by golden-section search: near it f is quadratic, so locating
    // it to 1e-9 of a step leaves f off by far less than the coverage probes' margin.
    auto lowest = [&](double lo, double hi) {
        const double g = 0.6180339887498948482;
        double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo), f1 = f(m1), f2 = f(m2);
        for (double width = (hi - lo) * 1e-9; hi - lo > width && m1 < m2;) {
            if (f1 < f2) {
                hi = m2, m2 = m1, f2 = f1, m1 = hi - g * (hi - lo), f1 = f(m1);
            } else {
                lo = m1, m1 = m2, f1 = f2, m2 = lo + g * (hi - lo), f2 = f(m2);
            }
        }
        return f1 < f2 ? m1 : m2;
    };
    // f is the squared distance to the tube's centre circle minus r², and that distance
    // changes by at most |Δs| along the line: a dip between samples can reach the tube only
    // if the distance at the lowest sample is within one step of r.
    auto reachable = [&](double value, double step) {
        return std::sqrt(value + r * r) - step <= r;
    };
    constexpr int kSteps = 64;
    double step = 2 * half / kSteps, prev2 = 0, prev = f(tc - half);
    std::optional<double> t;
    for (int i = 1; i <= kSteps && !t; ++i) {
        double s = tc - half + i * step, value = f(s);
        if (value < 0) {
            t = bisect(s - step, s);
        } else if (i >= 2 && prev <= prev2 && prev <= value && reachable(prev, step)) {
            // A dip between samples: a nearly tangent ray may cross the tube within it.
            double bottom = lowest(s - 2 * step, s);
            if (f(bottom) < 0) t = bisect(s - 2 * step, bottom);
        }
        prev2 = prev;
        prev = value;
    }
    if (!t || !(*t > 0)) return std::nullopt;
    DVec3 p = ray.at(*t) - center;
    DVec3 radial = glm::normalize(p - glm::dot(p, w) * w);
    DVec3 n = p - major * radial;
    return SurfaceHit{*t, glm::normalize(n)};
}

inline std::optional<SurfaceHit> discHit(const TestRay& ray, DVec3 center, DVec3 normal,
                                         double radius) {
    auto hit = planeHit(ray, normal, center);
    if (!hit) return std::nullopt;
    DVec3 rel = ray.at(hit->t) - center;
    rel -= glm::dot(rel, hit->normal) * hit->normal;
    if (glm::dot(rel, rel) > radius * radius) return std::nullopt;
    return hit;
}

/// The parallelogram corner + α·edgeA + β·edgeB, 0 ≤ α, β ≤ 1.
inline std::optional<SurfaceHit> quadHit(const TestRay& ray, DVec3 corner, DVec3 edgeA,
                                         DVec3 edgeB) {
    DVec3 n = glm::cross(edgeA, edgeB);
    auto hit = planeHit(ray, n, corner);
    if (!hit) return std::nullopt;
    DVec3 rel = ray.at(hit->t) - corner;
    double nn = glm::dot(n, n);
    double alpha = glm::dot(glm::cross(rel, edgeB), n) / nn;
    double beta = glm::dot(glm::cross(edgeA, rel), n) / nn;
    if (alpha < 0 || alpha > 1 || beta < 0 || beta > 1) return std::nullopt;
    return hit;
}

/// Möller–Trumbore (a different algorithm from the renderer's watertight one, on purpose).
inline std::optional<SurfaceHit> triangleHit(const TestRay& ray, DVec3 a, DVec3 b, DVec3 c) {
    DVec3 e1 = b - a, e2 = c - a;
    DVec3 p = glm::cross(ray.dir, e2);
    double det = glm::dot(e1, p);
    if (det == 0) return std::nullopt;
    DVec3 s = ray.origin - a;
    double beta = glm::dot(s, p) / det;
    DVec3 q = glm::cross(s, e1);
    double gamma = glm::dot(ray.dir, q) / det;
    if (beta < 0 || gamma < 0 || beta + gamma > 1) return std::nullopt;
    double t = glm::dot(e2, q) / det;
    if (!(t > 0)) return std::nullopt;
    return SurfaceHit{t, glm::normalize(glm::cross(e1, e2))};
}

/// A convex solid as the intersection of half-spaces n·(x − p) ≤ 0 (outward unit n): the
/// silhouette of a closed convex mesh without looking at its edges at all.
struct HalfSpace {
    DVec3 normal;
    DVec3 point;
};

inline std::optional<SurfaceHit> convexHit(const TestRay& ray,
                                           const std::vector<HalfSpace>& faces) {
    double enter = -std::numeric_limits<double>::infinity();
    double exit = std::numeric_limits<double>::infinity();
    DVec3 normal(0.0);
    for (const HalfSpace& h : faces) {
        double along = glm::dot(h.normal, ray.dir);
        double height = glm::dot(h.normal, ray.origin - h.point);
        if (along == 0) {
            if (height > 0) return std::nullopt;
            continue;
        }
        double t = -height / along;
        if (along < 0 && t > enter) enter = t, normal = h.normal;
        if (along > 0) exit = std::min(exit, t);
    }
    if (!(enter <= exit) || !(enter > 0)) return std::nullopt;
    return SurfaceHit{enter, normal};
}

} // namespace crt::tracer::stress
