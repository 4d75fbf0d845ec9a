// One dispatch from a texture's kind to its pattern.
#include "tracer/patterns/pattern.hpp"

#include "tracer/patterns/pattern_functions.hpp"
#include "tracer/patterns/turbulence.hpp"
#include "tracer/patterns/waveform.hpp"

namespace crt::tracer {

namespace {

using Kind = scene::TextureKind;

double continuousValue(const scene::TextureDesc& d, const Vec3& p, const Vec3& normal) {
    switch (d.kind) {
    case Kind::Noise: return patterns::noise(p, d);
    case Kind::Marble: return patterns::marble(p, d);
    case Kind::Wood: return patterns::wood(p, d);
    case Kind::Gradient: return patterns::gradient(p, d.axis);
    case Kind::Onion: return patterns::onion(p);
    case Kind::Leopard: return patterns::leopard(p);
    case Kind::Radial: return patterns::radial(p);
    case Kind::Spiral: return patterns::spiral(p, d.arms);
    case Kind::Boxed: return patterns::boxed(p);
    case Kind::Spherical: return patterns::spherical(p);
    case Kind::Cylindrical: return patterns::cylindrical(p);
    case Kind::Planar: return patterns::planar(p);
    case Kind::Quilted: return patterns::quilted(p, d.control0, d.control1);
    case Kind::Mandel: return patterns::mandel(p, d.iterations);
    case Kind::Bozo:
    case Kind::Spotted: return patterns::bozo(p);
    case Kind::Granite: return patterns::granite(p);
    case Kind::Agate: return patterns::agate(p);
    case Kind::Wrinkles: return patterns::wrinkles(p);
    case Kind::Dents: return patterns::dents(p);
    case Kind::Crackle: return patterns::crackle(p, d.metric, d.form);
    case Kind::Cells: return patterns::cells(p);
    case Kind::Slope: return patterns::slope(normal, d.axis);
    case Kind::Ripples: return patterns::ripples(p, d.frequency, d.phase);
    case Kind::Waves: return patterns::waves(p, d.frequency, d.phase);
    case Kind::FunctionPattern: return patterns::function(p, *d.function);
    default: return 0;
    }
}

double discreteValue(const scene::TextureDesc& d, const Vec3& p) {
    switch (d.kind) {
    case Kind::Checker: return patterns::checker(p, d.size);
    case Kind::Stripes: return patterns::stripes(p, d.axis, d.size);
    case Kind::Brick: return patterns::brick(p, d.brickSize, d.mortar);
    case Kind::Hexagon: return patterns::hexagon(p);
    default: return 0;
    }
}

} // namespace

double patternValue(const scene::TextureDesc& desc, const Vec3& point, const Vec3& normal) {
    bool turbulent = !scene::hasOwnTurbulence(desc.kind) && desc.displacement != Vec3(0.0);
    Vec3 p = turbulent ? turbulentPoint(point, desc) : point;
    if (scene::isDiscretePattern(desc.kind)) return discreteValue(desc, p);
    return shapeValue(continuousValue(desc, p, normal), desc);
}

} // namespace crt::tracer
