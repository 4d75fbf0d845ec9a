// Cylinder and cone crossings (capped and open), surface points and their error bounds.
#include "geometry_test_support.hpp"

using namespace crt::tracer;
namespace scene = crt::scene;
using namespace crt::tracer::test;

namespace {

/// A frustum in long double: axial coordinate, distance from the axis, and the surfaces.
struct ExactFrustum {
    LVec base, axis; // axis unit
    LD height, r0, r1;

    ExactFrustum(const Vec3& b, const Vec3& t, double rb, double rt) : base(b), r0(rb), r1(rt) {
        LVec a = LVec(t) - base;
        height = length(a);
        axis = (1 / height) * a;
    }
    LD z(const LVec& p) const { return dot(p - base, axis); }
    LD rho(const LVec& p) const { return length(cross(p - base, axis)); }
    LD slope() const { return (r1 - r0) / height; }
    bool inside(const LVec& p) const {
        LD zz = z(p);
        return zz >= 0 && zz <= height && rho(p) <= r0 + slope() * zz;
    }
    SurfaceFn surface(uint32_t part) const {
        ExactFrustum f = *this;
        if (part == 1) return [f](const LVec& p) { return -f.z(p); };
        if (part == 2) return [f](const LVec& p) { return f.z(p) - f.height; };
        return [f](const LVec& p) {
            LD s = f.slope();
            return (f.rho(p) - (f.r0 + s * f.z(p))) / std::sqrt(1 + s * s);
        };
    }
};

template <class G> void checkRandomLines(const char* what, uint64_t seed, bool cone) {
    Random rng(seed);
    int crossed = 0;
    for (int i = 0; i < 3000; ++i) {
        Vec3 base = rng.inBox(5);
        Vec3 top = base + rng.unit() * rng.uniform(0.1, 5);
        double rb = rng.uniform(0.05, 2), rt = cone ? (i % 3 == 0 ? 0.0 : rng.uniform(0.0, 3)) : rb;
        ExactFrustum exact(base, top, rb, rt);
        G g = [&] {
            if constexpr (std::is_same_v<G, ConeGeometry>)
                return G(scene::ConeShape{base, rb, top, rt, false});
            else
                return G(scene::CylinderShape{base, top, rb, false});
        }();
        Vec3 target = base + (top - base) * rng.uniform(-0.2, 1.2) + rng.inBox(std::max(rb, rt));
        Ray ray = rng.lineThrough(target, rng.uniform(0.1, 30));
        CrossingList list;
        g.crossLine(ray, list);
        INFO(what << " case " << i);
        checkAlternates(
            list, ray, [&](const LVec& p) { return exact.inside(p); }, true);
        crossed += list.count > 0;
        for (int k = 0; k < list.count; ++k) {
            SurfacePoint sp = g.surfaceAt(ray, list[k]);
            checkUnit(sp.normal);
            CHECK(glm::dot(sp.normal, ray.dir) * (k == 0 ? -1 : 1) >=
                  -1e-12 * glm::length(ray.dir));
            CHECK(g.bounds().contains(sp.point));
            CHECK((sp.uv.x >= 0 && sp.uv.x < 1 && sp.uv.y >= 0 && sp.uv.y <= 1));
            if (std::abs(glm::dot(sp.normal, ray.dir)) < 0.05 * glm::length(ray.dir)) continue;
            checkBoundContainsExact(sp, ray, exact.surface(list[k].part), list[k].t);
        }
    }
    CHECK(crossed > 1000);
}

} // namespace

TEST_CASE("cylinder: side and cap crossings along and across the axis") {
    CylinderGeometry g({{0, 0, 0}, {0, 2, 0}, 1, false});
    CHECK(g.solid());
    CrossingList list;
    Ray across{{-5, 1, 0}, {1, 0, 0}};
    g.crossLine(across, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].t == 4);
    CHECK(list[1].t == 6);
    CHECK(list[0].part == 0);
    SurfacePoint sp = g.surfaceAt(across, list[0]);
    CHECK(sp.normal.x == Approx(-1));
    CHECK(sp.point.x == Approx(-1));
    CHECK(sp.uv.y == Approx(0.5));

    Ray along{{0.5, -5, 0}, {0, 2, 0}};
    g.crossLine(along, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].t == 2.5);
    CHECK(list[0].part == 1);
    CHECK(list[1].t == 3.5);
    CHECK(list[1].part == 2);
    sp = g.surfaceAt(along, list[0]);
    CHECK(sp.normal == Vec3(0, -1, 0));
    CHECK(sp.point.y == 0);
    CHECK(sp.uv.y == Approx(0.5)); // half the radius out
    sp = g.surfaceAt(along, list[1]);
    CHECK(sp.normal == Vec3(0, 1, 0));

    g.crossLine({{0, 1, 0}, {0, 0, 1}}, list); // from inside
    REQUIRE(list.count == 2);
    CHECK(list[0].t == Approx(-1));
    CHECK(list[1].t == Approx(1));
    g.crossLine({{0, 3, -5}, {0, 0, 1}}, list); // above the top, parallel to the caps
    CHECK(list.count == 0);
    g.crossLine({{2, -5, 0}, {0, 1, 0}}, list); // parallel to the axis, outside
    CHECK(list.count == 0);
}

TEST_CASE("cylinder: lines on or tangent to the side never cross once") {
    CylinderGeometry g({{0, 0, 0}, {0, 0, 4}, 1, false});
    CrossingList list;
    g.crossLine({{1, 0, -3}, {0, 0, 1}}, list); // along the side itself
    CHECK(list.count % 2 == 0);
    g.crossLine({{1, -3, 2}, {0, 1, 0}}, list); // tangent across it
    CHECK(list.count % 2 == 0);
    g.crossLine({{-3, 0, 4}, {1, 0, 0}}, list); // in the top cap's plane
    CHECK(list.count % 2 == 0);
    Random rng(4);
    for (int i = 0; i < 2000; ++i) {
        double a = rng.uniform(0, 2 * kPi);
        Vec3 n(std::cos(a), std::sin(a), 0);
        Vec3 tangent = glm::normalize(Vec3(-n.y, n.x, rng.uniform(-1, 1)));
        Ray ray{n * (1 + rng.uniform(-1e-10, 1e-10)) + Vec3(0, 0, 2) - 3.0 * tangent, tangent};
        g.crossLine(ray, list);
        CHECK(list.count % 2 == 0);
        checkSorted(list);
    }
}

TEST_CASE("cylinder: open ones report only side hits and are not solid") {
    CylinderGeometry g({{0, 0, 0}, {0, 2, 0}, 1, true});
    CHECK_FALSE(g.solid());
    CrossingList list;
    g.crossLine({{-5, 1, 0}, {1, 0, 0}}, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].part == 0);
    CHECK(list[1].part == 0);
    g.crossLine({{0.5, -5, 0}, {0, 1, 0}}, list); // in through one open end, out the other
    CHECK(list.count == 0);
    g.crossLine({{0, -1, 0}, {1, 2, 0}}, list); // in through the bottom, out through the side
    REQUIRE(list.count == 1);
    CHECK(list[0].t == Approx(1));
    CHECK_FALSE(list.startsInside);
}

TEST_CASE("cylinder: zero radius or zero height draws nothing") {
    CrossingList list;
    CylinderGeometry thin({{0, 0, 0}, {0, 2, 0}, 0, false});
    thin.crossLine({{-5, 1, 0}, {1, 0, 0}}, list);
    CHECK(list.count == 0);
    thin.crossLine({{0, -5, 0}, {0, 1, 0}}, list);
    CHECK(list.count == 0);
    CylinderGeometry flat({{0, 1, 0}, {0, 1, 0}, 1, false});
    flat.crossLine({{0, -5, 0}, {0, 1, 0}}, list);
    CHECK(list.count == 0);
    CHECK(flat.bounds().empty());
}

TEST_CASE("cylinder: random lines around arbitrary axes") {
    checkRandomLines<CylinderGeometry>("cylinder", 21, false);
}

TEST_CASE("cone: an apex, the caps and the side") {
    ConeGeometry g({{0, 0, 0}, 1, {0, 0, 2}, 0, false});
    CrossingList list;
    Ray axis{{0, 0, -1}, {0, 0, 1}};
    g.crossLine(axis, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].t == 1);
    CHECK(list[0].part == 1);
    CHECK(list[1].t == Approx(3));
    Ray across{{-5, 0, 1}, {1, 0, 0}}; // half way up: radius 0.5
    g.crossLine(across, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].t == Approx(4.5));
    CHECK(list[1].t == Approx(5.5));
    SurfacePoint sp = g.surfaceAt(across, list[0]);
    CHECK(sp.normal.x == Approx(-2 / std::sqrt(5.0)));
    CHECK(sp.normal.z == Approx(1 / std::sqrt(5.0)));
    CHECK(sp.uv.y == Approx(0.5));
    g.crossLine({{-5, 0, 2.5}, {1, 0, 0}}, list); // above the apex
    CHECK(list.count == 0);
    // Steeper than the side, through both nappes' region: still one piece of the solid.
    g.crossLine({{-0.1, 0, -3}, {0.05, 0, 1}}, list);
    CHECK(list.count == 2);
}

TEST_CASE("cone: the top may be wider than the base, and open cones have no caps") {
    ConeGeometry wide({{0, 0, 0}, 0.5, {0, 2, 0}, 1.5, false});
    CrossingList list;
    wide.crossLine({{-5, 2, 0}, {1, 0, 0}}, list); // in the top cap's plane: radius 1.5
    REQUIRE(list.count == 2);
    CHECK(list[0].t == Approx(3.5));
    wide.crossLine({{-5, 0.5, 0}, {1, 0, 0}}, list);
    REQUIRE(list.count == 2);
    SurfacePoint sp = wide.surfaceAt({{-5, 0.5, 0}, {1, 0, 0}}, list[0]);
    CHECK(sp.normal.y < 0); // the side faces down when it widens upward
    ConeGeometry open({{0, 0, 0}, 0.5, {0, 2, 0}, 1.5, true});
    CHECK_FALSE(open.solid());
    open.crossLine({{0, -5, 0}, {0, 1, 0}}, list);
    CHECK(list.count == 0);
    open.crossLine({{0, 1, 0}, {1, 0, 0}}, list);
    REQUIRE(list.count == 2);
    CHECK(list[0].t == Approx(-1));
    CHECK(list[1].t == Approx(1));
}

TEST_CASE("cone: zero radii draw nothing") {
    ConeGeometry g({{0, 0, 0}, 0, {0, 2, 0}, 0, false});
    CrossingList list;
    g.crossLine({{0, -5, 0}, {0, 1, 0}}, list);
    CHECK(list.count == 0);
    g.crossLine({{-5, 1, 0}, {1, 0, 0}}, list);
    CHECK(list.count == 0);
}

TEST_CASE("cone: random lines around arbitrary axes") {
    checkRandomLines<ConeGeometry>("cone", 22, true);
}

TEST_CASE("cylinder: a far origin keeps the crossings accurate") {
    scene::CylinderShape s{{1, 2, 3}, {2, 3, 5}, 0.5, false};
    CylinderGeometry g(s);
    ExactFrustum exact(s.base, s.top, s.radius, s.radius);
    Random rng(9);
    for (int i = 0; i < 300; ++i) {
        Ray ray = rng.lineThrough(0.5 * (s.base + s.top) + rng.inBox(0.2), 1e5);
        CrossingList list;
        g.crossLine(ray, list);
        REQUIRE(list.count == 2);
        for (int k = 0; k < 2; ++k) {
            SurfacePoint sp = g.surfaceAt(ray, list[k]);
            if (std::abs(glm::dot(sp.normal, ray.dir)) < 0.05 * glm::length(ray.dir)) continue;
            checkBoundContainsExact(sp, ray, exact.surface(list[k].part), list[k].t);
            CHECK(glm::length(sp.pointError) < 1e-9);
        }
    }
}
