// The isosurface primitive: POV-Ray's, the solid where a compiled Function is below a
// threshold, within a box.
#pragma once

#include "scene/scene_desc.hpp"
#include "tracer/geometry/box.hpp"
#include "tracer/geometry/mapping_axis.hpp"

#include <atomic>
#include <memory>
#include <string>

namespace crt::tracer {

/// What the searches along lines met that the user should hear of, summed over every line
/// and thread (so, like the image, it does not depend on how the work was shared).
struct IsosurfaceFindings {
    /// The steepest change of the function per unit of length seen between two samples.
    std::atomic<double> steepestGradient{0};
    /// Lines whose search stopped at the evaluation limit.
    std::atomic<uint64_t> searchesCutShort{0};
};

/// The solid where f(x, y, z) < threshold inside the bounds box (scene::IsosurfaceDesc), closed
/// by the box's faces unless open (then a surface). Along a line clipped to the box, a span
/// whose ends are too far from the threshold for the function to reach it (at most
/// maxGradient per unit of length) holds no crossing; the others are halved down to spans of
/// `accuracy`, and a span whose ends lie on the two sides holds a crossing, found by the
/// Illinois method. The normal is the gradient by central differences. Part 0 is the
/// isosurface, 1 + k the box's face k (BoxGeometry's parts).
class IsosurfaceGeometry {
  public:
    explicit IsosurfaceGeometry(const scene::IsosurfaceShape& shape,
                                uint64_t maxEvaluations = scene::RenderLimits{}.maxIsosurfaceEvaluations);

    Bounds3 bounds() const { return box_.bounds(); }
    void crossLine(const Ray& ray, CrossingList& out) const;
    /// Visits the crossings with tMin < t < tMax in order, until the visitor returns false
    /// (then false): the search kept to that window, for the renderer's queries, which need
    /// no more (crossLine searches the whole line).
    bool crossingsIn(const Ray& ray, double tMin, double tMax, CrossingVisitor visit) const;
    SurfacePoint surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv = true) const;
    bool solid() const { return !desc_->open; }
    MappingAxis mappingAxis() const { return {Vec3(0.0), Vec3(0, 1, 0)}; }

    /// f − threshold at p: below 0 inside.
    double valueAt(const Vec3& p) const { return desc_->function->at(p.x, p.y, p.z) - desc_->threshold; }
    const scene::IsosurfaceDesc& desc() const { return *desc_; }
    const IsosurfaceFindings& findings() const { return *findings_; }
    /// The warnings the findings call for ("" for none): a gradient steeper than maxgradient
    /// (parts may be missing), one far gentler (the render could be faster), searches cut short.
    std::string warnings(const std::string& where) const;

  private:
    /// Halves the span from ta to tb (the function's values there ga and gb) as the class
    /// says, visiting each crossing of the surface (part 0) in order until the visitor returns
    /// false; false then.
    bool search(const Ray& ray, double ta, double tb, double ga, double gb, CrossingVisitor visit) const;
    /// The crossing between ta and tb, whose values ga and gb lie on the two sides.
    double rootBetween(const Ray& ray, double ta, double tb, double ga, double gb, uint64_t& evaluations) const;

    std::shared_ptr<const scene::IsosurfaceDesc> desc_;
    BoxGeometry box_;
    uint64_t maxEvaluations_;
    std::shared_ptr<IsosurfaceFindings> findings_;
};

} // namespace crt::tracer
