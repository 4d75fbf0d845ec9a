// The blob primitive: POV-Ray's, the solid where a sum of smooth fields passes a threshold.
#pragma once

#include "scene/scene_desc.hpp"
#include "tracer/geometry/geometry_math.hpp"
#include "tracer/geometry/mapping_axis.hpp"

#include <memory>
#include <vector>

namespace crt::tracer {

/// The solid where the field of scene::BlobDesc's components exceeds the threshold (> 0).
/// Along a line each component's field is a quartic in t between the points where the line
/// enters and leaves its reach (a cylinder's in three pieces: its body and its two round
/// ends), so between consecutive such points the sum is one quartic, whose sign changes are
/// the crossings. No UV (as POV-Ray's).
class BlobGeometry {
  public:
    explicit BlobGeometry(const scene::BlobShape& desc);

    Bounds3 bounds() const { return bounds_; }
    void crossLine(const Ray& ray, CrossingList& out) const;
    SurfacePoint surfaceAt(const Ray& ray, const Crossing& crossing, bool wantUv = true) const;
    bool solid() const { return true; }
    MappingAxis mappingAxis() const { return {Vec3(0.0), Vec3(0, 1, 0)}; }

    /// The field at a point; also its gradient, and a bound of its rounding error.
    double fieldAt(const Vec3& p, Vec3* gradient = nullptr, double* error = nullptr) const;

  private:
    struct Piece;
    struct Component {
        Vec3 a, b, axis;    ///< centre (or base), top, and top − base (zero for a sphere)
        double axisLength2; ///< |axis|², 0 for a sphere
        double radius2, strength;
    };
    /// Where the line is within reach of the point c: false if nowhere.
    static bool pointReach(const Ray& ray, const Vec3& c, double r2, Piece& piece);
    /// The field of the piece's component at x, a point the piece holds.
    double pieceField(const Piece& p, const Vec3& x) const;
    /// Appends the pieces of component i the line passes (blob.cpp's Piece).
    void addPieces(const Ray& ray, uint32_t i, std::vector<Piece>& pieces) const;
    /// Appends the crossings between ta and tb, where the same pieces are in reach.
    void crossSpan(const Ray& ray, double ta, double tb, double gapA, double gapB,
                   const std::vector<Piece>& pieces, CrossingList& out) const;

    std::shared_ptr<const std::vector<Component>> components_;
    double threshold_ = 1;
    Bounds3 bounds_;
};

} // namespace crt::tracer
