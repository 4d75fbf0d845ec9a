// The plain-data scene description: what the renderer accepts and what the front end builds.
//
// Every field has the default of spec §5, so a default-constructed description is a valid
// (empty) scene. Indices refer to the vectors of SceneDesc; -1 means "none".
#pragma once

#include "scene/curve_outline.hpp"
#include "scene/function_program.hpp"
#include "scene/obj_mesh.hpp"
#include "scene/text_outline.hpp"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace crt::scene {

/// Where a script built an object: file index into SceneDesc::files, 1-based line/column.
struct SourceSpan {
    uint32_t file = 0;
    uint32_t line = 0;
    uint32_t column = 0;
    uint32_t endLine = 0;
    uint32_t endColumn = 0;

    bool operator==(const SourceSpan&) const = default;
};

/// A linear RGB color with alpha (alpha is carried, not used for shading).
struct Color {
    double r = 0, g = 0, b = 0, a = 1;

    bool operator==(const Color&) const = default;
};

enum class ModifierKind : uint8_t { Translate, Rotate, Scale, Matrix };

/// One modifier of `<translate v, rotate v, scale s, matrix m>`, applied about the world origin.
struct Modifier {
    ModifierKind kind = ModifierKind::Translate;
    glm::dvec3 value{0.0}; ///< a uniform scale s is stored as (s, s, s); Matrix: the offset
    /// Matrix: the linear part; its columns are where x, y and z go (POV-Ray's rows).
    glm::dmat3 linear{1.0};

    bool operator==(const Modifier&) const = default;
};

enum class TextureKind : uint8_t {
    Checker,
    Stripes,
    Noise,
    Marble,
    Wood,
    Image,
    NoiseBump,
    ImageBump,
    Gradient,
    Onion,
    Leopard,
    Radial,
    Spiral,
    Brick,
    Hexagon,
    Boxed,
    Spherical,
    Cylindrical,
    Planar,
    Quilted,
    Mandel,
    Bozo,
    Spotted,
    Granite,
    Agate,
    Wrinkles,
    Dents,
    Crackle,
    Cells,
    Slope,
    Bump,
    Ripples,
    Waves,
    FunctionPattern
};
enum class TextureMapping : uint8_t { Uv, Planar, Spherical, Cylindrical, Cubic };

/// What a pattern's value goes through before its colour map reads it (POV-Ray's wave types).
enum class Waveform : uint8_t { Ramp, Triangle, Sine, Scallop, Cubic, Poly };
inline constexpr std::string_view kWaveformNames[] = {"ramp",    "triangle", "sine",
                                                      "scallop", "cubic",    "poly"};

/// Patterns whose value picks one colour of their map by position (0, 1, 2), not by value.
inline bool isDiscretePattern(TextureKind kind) {
    return kind == TextureKind::Checker || kind == TextureKind::Stripes ||
           kind == TextureKind::Brick || kind == TextureKind::Hexagon;
}
/// How many colours a discrete pattern shows: Hexagon three, the others two.
inline size_t discreteColorCount(TextureKind kind) {
    return kind == TextureKind::Hexagon ? 3 : 2;
}
/// Textures that perturb the normal rather than give a colour.
inline bool isBumpKind(TextureKind kind) {
    return kind == TextureKind::NoiseBump || kind == TextureKind::ImageBump ||
           kind == TextureKind::Bump;
}
/// Textures that read an image file rather than a pattern.
inline bool readsImage(TextureKind kind) {
    return kind == TextureKind::Image || kind == TextureKind::ImageBump;
}
/// Patterns whose `turbulence` is their own (how their veins or rings wander, as in 2015),
/// rather than a displacement of the point.
inline bool hasOwnTurbulence(TextureKind kind) {
    return kind == TextureKind::Marble || kind == TextureKind::Wood;
}

/// One entry of a colour map: the colour at a pattern value.
struct ColorStop {
    double value = 0;
    Color color;

    bool operator==(const ColorStop&) const = default;
};

struct TextureDesc {
    TextureKind kind = TextureKind::Checker;
    /// The colour map: values non-decreasing in [0, 1]. Discrete patterns use the colours
    /// by position. A 2015 texture's `a` and `b` are the stops at 0 and 1.
    std::vector<ColorStop> colors{{0, {1, 1, 1, 1}}, {1, {0, 0, 0, 1}}};
    double size = 1;
    glm::dvec3 axis{1, 0, 0};     ///< Stripes, Gradient
    int octaves = 6;              ///< the turbulence's; Noise, Marble, NoiseBump: their noise's (4)
    double turbulence = 1;        ///< Marble (1), Wood (0.1): how the veins or rings wander
    glm::dvec3 displacement{0.0}; ///< the other patterns' `turbulence`: how far points move
    double omega = 0.5;           ///< each turbulence octave's amplitude over the last's
    double lambda = 2;            ///< each turbulence octave's frequency over the last's
    double frequency = 1;         ///< the value becomes frac(value * frequency + phase)
    double phase = 0;
    Waveform waveform = Waveform::Ramp; ///< Spiral: Triangle
    double exponent = 1;                ///< the poly waveform's
    int arms = 0;                       ///< Spiral (required)
    glm::dvec3 brickSize{8, 3, 4.5};    ///< Brick
    double mortar = 0.5;                ///< Brick: the width of the joints
    double control0 = 1;                ///< Quilted: the curve of each quilt's edge
    double control1 = 1;
    int iterations = 0;        ///< Mandel (required)
    double metric = 2;         ///< Crackle: the Minkowski exponent of its distances (2: Euclid's)
    glm::dvec3 form{-1, 1, 0}; ///< Crackle: weights of the nearest three feature points' distances
    double rings = 8;          ///< Wood
    double strength = 0.5;     ///< bump textures
    std::vector<TextureDesc> pattern; ///< Bump: the one pattern whose value is the height
    std::shared_ptr<const FunctionProgram> function; ///< FunctionPattern: f(x, y, z), the value
    std::string file;          ///< Image, ImageBump: as written in the script
    std::string resolvedFile;  ///< the path found on disk, or "" if not found yet
    TextureMapping mapping = TextureMapping::Uv;
    std::vector<Modifier> modifiers;
    SourceSpan source;
};

/// A texture of `kind` with every attribute at that kind's default: where kinds differ from
/// the defaults above (their colours, Wood's turbulence, the turbulence's octaves, Spiral's
/// waveform), this is the one place that says so.
TextureDesc defaultTexture(TextureKind kind);

/// How a medium scatters light: the chance density over the angle θ between the light's
/// direction and the scattered direction.
enum class PhaseFunction : uint8_t { Isotropic, Rayleigh, HenyeyGreenstein };
/// The names of PhaseFunction's values, as scripts spell them, in its order.
inline constexpr std::string_view kPhaseNames[] = {"isotropic", "rayleigh", "henyey-greenstein"};

/// What fills a solid (smoke, dusty air, a cloud): per unit length it absorbs, scatters
/// and gives off light in proportion to its density.
struct MediumDesc {
    Color absorption{0, 0, 0, 1};
    Color scattering{0, 0, 0, 1};
    Color emission{0, 0, 0, 1};
    double density = 1; ///< a factor of the pattern's value when there is one
    std::vector<TextureDesc> densityPattern; ///< at most one: its value at a point, times density
    PhaseFunction phase = PhaseFunction::Isotropic;
    double g = 0;     ///< HenyeyGreenstein: −1 (back) to 1 (forward)
    int samples = 16; ///< steps along each ray through it
    SourceSpan source;
};

/// Everything a material is besides its color. Materials that agree on all of it share one
/// entry of SceneDesc::finishes: a generated scene of 100,000 spheres, each with its own
/// color, keeps 100,000 small materials and one finish.
struct FinishDesc {
    double reflectivity = 0;      ///< at grazing angles when reflectivityMin differs
    double reflectivityMin = -1;  ///< facing the viewer; < 0: reflectivity at every angle
    double reflectionFalloff = 1; ///< reflection = min + (max − min) (1 − cos θ)^falloff
    double transparency = 0;
    double ior = 1;
    double diffuse = 1; ///< default max(0, 1 - reflectivity - transparency)
    double specular = 0;
    double shininess = 3;
    double glossiness = 0;
    double brilliance = 1;       ///< diffuse ∝ cos^brilliance
    bool conserveEnergy = false; ///< diffuse takes what reflection and transmission leave
    bool metallic = false;
    bool fresnel = false;
    Color absorption{0, 0, 0, 1};
    Color emission{0, 0, 0, 1};
    double filter = 0;    ///< how much of what the colour's alpha lets through takes its colour
    int32_t texture = -1; ///< replaces color
    int32_t bump = -1;
    int32_t blend = -1; ///< index into SceneDesc::blends: the material is made of others
    int32_t medium = -1; ///< index into SceneDesc::media: what fills the solid

    bool operator==(const FinishDesc&) const = default;
};

/// How a material made of others combines them.
enum class BlendKind : uint8_t {
    Map,    ///< MaterialMap: a pattern's value picks two neighbours and mixes them
    Layers, ///< Layered: each layer's colour alpha shows the layers under it
};

/// A material made of other materials, resolved at each point of the surface.
struct BlendDesc {
    BlendKind kind = BlendKind::Map;
    int32_t pattern = -1;       ///< Map: index into SceneDesc::textures
    std::vector<double> values; ///< Map: one a material, non-decreasing in [0, 1]
    /// Map: in the order of values; Layers: bottom first. Each comes before the material
    /// made of it in SceneDesc::materials, so that no material is made of itself.
    std::vector<int32_t> materials;

    bool operator==(const BlendDesc&) const = default;
};

/// A material: its own color, its (possibly shared) finish, and where the script built it.
struct MaterialDesc {
    Color color{0.5, 0.5, 0.5, 1};
    int32_t finish = -1; ///< index into SceneDesc::finishes; -1: the default FinishDesc
    SourceSpan source;
};

struct SphereShape { glm::dvec3 center{0.0}; double radius = 0; bool operator==(const SphereShape&) const = default; };
struct BoxShape { glm::dvec3 cornerA{0.0}; glm::dvec3 cornerB{0.0}; bool operator==(const BoxShape&) const = default; };
struct PlaneShape {
    glm::dvec3 normal{0, 1, 0}; glm::dvec3 position{0.0};
    bool operator==(const PlaneShape&) const = default;
};
struct CylinderShape {
    glm::dvec3 base{0.0}; glm::dvec3 top{0.0}; double radius = 0; bool open = false;
    bool operator==(const CylinderShape&) const = default;
};
struct ConeShape {
    glm::dvec3 base{0.0}; double baseRadius = 0; glm::dvec3 top{0.0}; double topRadius = 0; bool open = false;

    bool operator==(const ConeShape&) const = default;
};
struct TorusShape {
    glm::dvec3 center{0.0}; double major = 0; double minor = 0; glm::dvec3 axis{0, 1, 0};
    bool operator==(const TorusShape&) const = default;
};
struct DiscShape {
    glm::dvec3 center{0.0}; glm::dvec3 normal{0, 1, 0}; double radius = 0; double hole = 0;
    bool operator==(const DiscShape&) const = default;
};
struct QuadShape {
    glm::dvec3 corner{0.0}; glm::dvec3 edgeA{0.0}; glm::dvec3 edgeB{0.0};
    bool operator==(const QuadShape&) const = default;
};
struct TriangleShape {
    glm::dvec3 a{0.0}; glm::dvec3 b{0.0}; glm::dvec3 c{0.0};
    bool operator==(const TriangleShape&) const = default;
};
/// POV-Ray's polygon: points in one plane, loops closed by repeating their first point
/// (scene/polygon_loops.hpp), holes by the even-odd rule.
struct PolygonShape {
    std::vector<glm::dvec3> points;

    bool operator==(const PolygonShape&) const = default;
};
/// A triangle whose shading normal is interpolated from one at each corner, kept as the one
/// triangle of a mesh with vertex normals: so an entity stays as small as the others, and the
/// renderer draws it as it draws a mesh's triangles. Null: nothing.
struct SmoothTriangleShape {
    std::shared_ptr<const MeshData> mesh;

    bool operator==(const SmoothTriangleShape&) const = default;
};
/// The smooth triangle with corners a, b, c and normals na, nb, nc, each made unit length
/// (as POV-Ray does: each corner's direction counts alike whatever its length).
inline SmoothTriangleShape smoothTriangle(const glm::dvec3& a, const glm::dvec3& b,
                                          const glm::dvec3& c, const glm::dvec3& na,
                                          const glm::dvec3& nb, const glm::dvec3& nc) {
    auto direction = [](const glm::dvec3& n) {
        const double len = glm::length(n);
        return len > 0 && std::isfinite(len) ? n / len : n;
    };
    auto mesh = std::make_shared<MeshData>();
    mesh->positions = {a, b, c};
    mesh->normals = {direction(na), direction(nb), direction(nc)};
    mesh->triangles = {{{0, 1, 2}, {0, 1, 2}, {-1, -1, -1}}};
    return {std::move(mesh)};
}
/// POV-Ray's superellipsoid in the cube [-1, 1]³: e the exponent across z, n along it.
struct SuperellipsoidShape {
    double e = 1;
    double n = 1;

    bool operator==(const SuperellipsoidShape&) const = default;
};
/// POV-Ray's prism: an outline in the x-z plane (scene/curve_outline.hpp, holes by the
/// even-odd rule) swept along y from `from` to `to`; a conic sweep scales it with y, from the
/// apex at the origin (the outline is its section at y = 1). Open: without the end faces.
struct PrismShape {
    std::vector<glm::dvec2> points; ///< x and z
    double from = 0;
    double to = 1;
    SplineKind spline = SplineKind::Linear;
    bool conic = false;
    bool open = false;

    bool operator==(const PrismShape&) const = default;
};
/// POV-Ray's surface of revolution: the points are (radius, height); the radius squared is
/// a cubic of the height between each two points from the second to the last but one, with
/// slopes from their neighbours, turned about the y axis. Open: without the end faces.
struct SorShape {
    std::vector<glm::dvec2> points;
    bool open = false;

    bool operator==(const SorShape&) const = default;
};
/// POV-Ray's lathe: a curve of points (x, y) (scene/curve_outline.hpp's curveSegments)
/// turned about the y axis. A solid when the curve comes back to its first point on the
/// curve, or starts and ends on the axis; otherwise a surface.
struct LatheShape {
    std::vector<glm::dvec2> points;
    SplineKind spline = SplineKind::Linear;

    bool operator==(const LatheShape&) const = default;
};
/// POV-Ray's sphere_sweep: the solid a sphere fills as its centre moves along the curve of
/// `points` and its radius along the curve of `radii` (scene/curve_outline.hpp's
/// curveSegmentsOf, the two read alike): straight between the points (linear), a
/// Catmull-Rom spline through all but the first and last (cubic), or a uniform cubic B-spline
/// (bspline).
struct SphereSweepShape {
    std::vector<glm::dvec3> points;
    std::vector<double> radii;
    SplineKind spline = SplineKind::Linear;

    bool operator==(const SphereSweepShape&) const = default;
};
/// POV-Ray's text: the glyph outlines of scene/text_outline.hpp on the x-y plane, extruded
/// from z = 0 to `thickness`. Out of line, as an entity's shape must stay small.
struct TextDesc {
    std::string text;
    std::string font;         ///< as written in the script ("" for the default)
    std::string resolvedFont; ///< the path found on disk, or "" if not looked up
    double thickness = 0.25;
    double spacing = 1;
    /// Laid out by the front end; null when it did not read the font (checkFiles off).
    std::shared_ptr<const TextOutline> outline;
};
struct TextShape {
    std::shared_ptr<const TextDesc> desc;

    bool operator==(const TextShape&) const = default;
};
/// One of a blob's components: its field is strength · (1 − (d / radius)²)² within `radius`
/// of its centre (a sphere) or of the segment from `a` to `b` (a cylinder with round ends),
/// d being the distance; nothing farther.
struct BlobComponent {
    bool cylinder = false;
    glm::dvec3 a{0.0}, b{0.0}; ///< the centre, or the segment's ends
    double radius = 1;
    double strength = 1;
};
/// POV-Ray's blob: the solid where the components' fields add up to more than `threshold`.
struct BlobDesc {
    double threshold = 1;
    std::vector<BlobComponent> components;
};
struct BlobShape {
    std::shared_ptr<const BlobDesc> desc;

    bool operator==(const BlobShape&) const = default;
};
/// POV-Ray's isosurface: the solid where `function` of (x, y, z) is below `threshold`, within
/// the box from `boundsMin` to `boundsMax` (whose faces close it, unless `open`). Crossings are
/// found by halving the line's span in the box wherever `maxGradient` (a bound of how fast the
/// function changes per unit of length) lets the function reach the threshold, down to spans
/// of `accuracy`.
struct IsosurfaceDesc {
    std::shared_ptr<const FunctionProgram> function;
    glm::dvec3 boundsMin{-1.0}, boundsMax{1.0};
    double threshold = 0;
    double maxGradient = 1.1;
    double accuracy = 0.001;
    bool open = false;
    SourceSpan source; ///< for the renderer's warnings (a gradient above maxGradient …)
};
struct IsosurfaceShape {
    std::shared_ptr<const IsosurfaceDesc> desc;

    bool operator==(const IsosurfaceShape&) const = default;
};
/// POV-Ray's height field: heights in [0, 1] over the unit square of the x-z plane, from an
/// image's grey levels (its first row at z = 1, as POV-Ray has it) or a function of (x, 0, z)
/// sampled on a grid; two triangles a cell. Smooth: normals interpolated from the corners'.
struct HeightFieldDesc {
    std::string image;         ///< as written in the script ("" for a function)
    std::string resolvedImage; ///< the path found on disk, or "" if not looked up
    std::shared_ptr<const FunctionProgram> function;
    int resolution = 100; ///< a function's samples along x, and as many along z
    bool smooth = false;
};
struct HeightFieldShape {
    std::shared_ptr<const HeightFieldDesc> desc;

    bool operator==(const HeightFieldShape&) const = default;
};
struct MeshShape {
    std::string file;         ///< as written in the script ("" for a mesh written in it)
    std::string resolvedFile; ///< the path found on disk, or "" if not found
    /// A mesh written in the script (its vertices, faces …, POV-Ray's mesh2): its index in
    /// SceneDesc::writtenMeshes; -1 for a file.
    int32_t written = -1;

    bool operator==(const MeshShape&) const = default;
};

/// Merge: a union without the surfaces that lie inside it (POV-Ray's merge, for glass).
/// Clip: the left entity's surfaces where they are inside the right solid (POV-Ray's
/// clipped_by), a surface however closed the left one is.
enum class CsgOp : uint8_t { Union, Difference, Intersection, Merge, Clip };
/// A CSG combination of two entities (each a solid or a group of solids; a Clip's left one
/// may be a surface).
struct CsgNode {
    CsgOp op = CsgOp::Union; int32_t left = -1; int32_t right = -1;
    bool operator==(const CsgNode&) const = default;
};
/// The complement of a solid: everything outside it, bounded by its surface facing inward.
struct InverseNode {
    int32_t child = -1;

    bool operator==(const InverseNode&) const = default;
};
/// An entity moved by modifiers (and maybe given a material: EntityDesc::material).
struct TransformNode {
    int32_t child = -1; std::vector<Modifier> modifiers;
    bool operator==(const TransformNode&) const = default;
};
/// What a macro emitting several entities returns: drawn as its members; in CSG, their union.
struct GroupNode { std::vector<int32_t> members; bool operator==(const GroupNode&) const = default; };

using Shape = std::variant<SphereShape, BoxShape, PlaneShape, CylinderShape, ConeShape, TorusShape,
                           DiscShape, QuadShape, TriangleShape, SmoothTriangleShape, PolygonShape,
                           SuperellipsoidShape, PrismShape, SorShape, LatheShape, SphereSweepShape, TextShape,
                           BlobShape, IsosurfaceShape, HeightFieldShape, MeshShape, CsgNode, TransformNode, GroupNode, InverseNode>;
// One per entity, and a generated scene has millions: a shape with more data keeps it out of
// line (as a smooth triangle and a polygon do).
static_assert(sizeof(Shape) <= 80, "keep every shape small");

/// The name of a CSG operation as scripts and the scene JSON spell its result: "Union" …
inline const char* csgOpName(CsgOp op) {
    switch (op) {
    case CsgOp::Union: return "Union";
    case CsgOp::Difference: return "Difference";
    case CsgOp::Intersection: return "Intersection";
    case CsgOp::Merge: return "Merge";
    case CsgOp::Clip: return "Clipped";
    }
    return "?";
}

/// The rays an entity is hidden from (bits of EntityDesc::hidden): it is still there for
/// the others. An entity is hidden from what it or anything above it is hidden from.
enum HiddenFrom : uint8_t {
    kHiddenFromCamera = 1,      ///< the camera's rays and those that pass see-through surfaces
    kHiddenFromShadows = 2,     ///< shadow rays: it casts no shadow
    kHiddenFromReflections = 4, ///< reflected and refracted rays
};

/// A node of the entity graph. Nodes may be shared (an entity drawn twice is one node).
struct EntityDesc {
    Shape shape;
    /// Index into materials; -1: none of its own. A transform node's material is given to
    /// the parts below it that have none (the nearest such node's); a part that ends with
    /// none is drawn with the default material. CSG and group nodes have none.
    int32_t material = -1;
    bool solid = true;     ///< usable as a CSG operand (and inside/outside is defined)
    SourceSpan source;
    uint8_t hidden = 0; ///< HiddenFrom bits

    bool operator==(const EntityDesc&) const = default;
};

enum class LightKind : uint8_t { Point, Parallel, Spot, Area, Cylinder, Sphere };

/// Lights that shine from a region rather than a point: shading takes shadowsamples of them.
inline bool isExtendedLight(LightKind kind) {
    return kind == LightKind::Area || kind == LightKind::Cylinder || kind == LightKind::Sphere;
}

struct LightDesc {
    LightKind kind = LightKind::Point;
    glm::dvec3 origin{0.0};   ///< Point, Spot, Sphere (its centre); Area: corner
    glm::dvec3 from{0.0};     ///< Parallel; Cylinder: one end of the segment
    glm::dvec3 to{0.0};       ///< Cylinder: the other end
    glm::dvec3 pointing{0.0}; ///< Parallel, Spot
    glm::dvec3 edgeA{0.0};    ///< Area
    glm::dvec3 edgeB{0.0};    ///< Area
    Color color{1, 1, 1, 1};
    double falloff = 0;
    /// Point, Spot, Area: 1 / (c0 + c1·d + c2·d²) with d the distance to the light
    glm::dvec3 attenuation{1, 0, 0};
    double ambient = 0;
    double angle = 30;     ///< Spot: full cone, degrees
    double softness = 0.2; ///< Spot
    double tightness = 0;  ///< Spot: intensity × cos^tightness of the angle from the axis
    bool shadowless = false; ///< lights without shadow rays: nothing stands in its way
    double radius = 0;       ///< Sphere; Cylinder: the tube's, as it is seen when visible
    /// Area, Cylinder, Sphere: seen by camera and reflected rays, as its colour
    bool visible = false;
    bool circular = false;   ///< Area: the ellipse inscribed in the parallelogram
    /// Area: turned about its centre to face each lit point, its edges keeping their lengths
    bool orient = false;
    SourceSpan source;
};

enum class Projection : uint8_t { Pinhole, Spherical, Orthographic, Fisheye, Cylindrical };
/// The names of Projection's values, as scripts spell them, in its order.
inline constexpr std::string_view kProjectionNames[] = {"pinhole", "spherical", "orthographic", "fisheye",
                                                        "cylindrical"};
enum class ApertureShape : uint8_t { Circle, Polygon, Gaussian, Line };

struct CameraDesc {
    glm::dvec3 position{0, 0, -1};
    glm::dvec3 pointing{0, 0, 0};
    double fov = 60; ///< vertical, degrees; fisheye: across its circle; cylindrical: horizontal
    /// orthographic: the view's width in scene units; 0: the pinhole view's width at `pointing`
    double width = 0;
    double aperture = 0;
    double focalDistance = 1; ///< default: distance from position to pointing
    ApertureShape apertureShape = ApertureShape::Circle;
    int apertureBlades = 0; ///< polygon sides
    glm::dvec3 up{0, 1, 0};
    double roll = 0; ///< degrees
    Projection projection = Projection::Pinhole;
    SourceSpan source;

    bool operator==(const CameraDesc&) const = default;
};

enum class BackgroundKind : uint8_t { Solid, Gradient, Image, Pattern };

struct BackgroundDesc {
    BackgroundKind kind = BackgroundKind::Solid;
    Color color{1, 1, 1, 1};
    Color horizon{1, 1, 1, 1};
    Color sky{1, 1, 1, 1};
    std::string image;         ///< as written in the script
    std::string resolvedImage; ///< the path found on disk, or "" if not found
    double angle = 0;          ///< yaw, radians
    /// Pattern: read on the ray's unit direction, bottom first; each one's colour alpha shows
    /// those under it, and black shows under them all (POV-Ray's sky_sphere).
    std::vector<TextureDesc> layers;
    SourceSpan source;
};

/// Fog over the whole scene, between a ray's origin and what it meets outside every solid:
/// what is behind is seen by exp(−∫density/distance), and the fog's colour fills the rest.
struct FogDesc {
    Color color{0, 0, 0, 1}; ///< alpha a: at least 1 − a of what is behind is always seen
    double distance = 1;     ///< where a constant fog lets 1/e through
    double filter = 0;       ///< how much of what is behind takes the fog's colour
    /// Ground fog when above 0: density 1 up to `altitude` along `up`, and 1/(1 + h²) at
    /// h·falloff above it (POV-Ray's fog_type 2, with fog_offset and fog_alt); 0: density 1
    /// everywhere.
    double falloff = 0;
    double altitude = 0;
    glm::dvec3 up{0, 1, 0}; ///< unit length
    /// How the fog thins and thickens: the point's scale before noise is read; 0: evenly.
    glm::dvec3 turbulence{0.0};
    double turbulenceDepth = 0.5; ///< how much of the depth the noise may take away
    SourceSpan source;
};

/// Stratified: one jittered sample in each cell of the supersampling grid.
enum class Antialias : uint8_t { Grid, Adaptive, ShowAdaptive, Stratified };
/// The names of Antialias's values, as scripts and the command line spell them, in its order.
inline constexpr std::string_view kAntialiasNames[] = {"grid", "adaptive", "showadaptive",
                                                       "stratified"};

/// How light is carried: Whitted's first bounce (spec §6), or path tracing (docs/rendering.md).
enum class Integrator : uint8_t { Whitted, Path };
/// The names of Integrator's values, as scripts and the command line spell them, in its order.
inline constexpr std::string_view kIntegratorNames[] = {"whitted", "path"};

/// The counts a setting of samples may take, whether a script or the command line sets it.
struct CountRange {
    int min, max;
};
inline constexpr CountRange kSupersamplingRange{1, 64};
inline constexpr CountRange kDofSamplesRange{1, 100'000};
inline constexpr CountRange kShadowSamplesRange{1, 4096};
inline constexpr CountRange kGlossySamplesRange{1, 4096};
inline constexpr CountRange kPathSamplesRange{1, 1'000'000};
inline constexpr CountRange kBouncesRange{0, 1000};
inline constexpr CountRange kMediumSamplesRange{1, 4096};
inline constexpr CountRange kMotionStepsRange{2, 64};

struct SettingsDesc {
    std::string title, author, date, notes;
    int width = 800;
    int height = 600;
    double gamma = 1.0;
    bool srgb = false; ///< gamma -> "srgb"
    int supersampling = 1;
    int dofSamples = 1;
    int recursionDepth = 3;
    int reflectionDepth = -1; ///< reflections a path may take; -1: recursionDepth
    int refractionDepth = -1; ///< refractions a path may take; -1: recursionDepth
    Antialias antialias = Antialias::Grid;
    double aaThreshold = 0.1;
    int aaDepth = 2;
    int shadowSamples = 16;
    int glossySamples = 16;
    uint64_t seed = 0;
    Color ambient{0, 0, 0, 1};
    Integrator integrator = Integrator::Whitted;
    int samples = 64; ///< path: paths a pixel (the most, with targetError)
    int bounces = 8;  ///< path: surfaces a path may bounce off
    /// path: a pixel stops taking paths once the relative standard error of its mean is below
    /// this (after kMinAdaptiveSamples); 0: every pixel takes `samples`.
    double targetError = 0;
    static constexpr int kMinAdaptiveSamples = 16;
    /// The shutter, in units of t from the frame's t: open while shutterOpen < shutterClose,
    /// and then the script is evaluated `motionSteps` times across it (motion blur).
    double shutterOpen = 0, shutterClose = 0;
    int motionSteps = 2;

    bool shutterIsOpen() const { return shutterOpen < shutterClose; }

    int reflectionLimit() const { return reflectionDepth < 0 ? recursionDepth : reflectionDepth; }
    int refractionLimit() const { return refractionDepth < 0 ? recursionDepth : refractionDepth; }
    /// Bounces of either kind a path may take: the larger limit, so that recursiondepth alone
    /// bounds the whole path as it always has, and an explicit larger limit is reachable.
    int bounceLimit() const { return std::max(reflectionLimit(), refractionLimit()); }
};

/// The file to open for an image or mesh: where the front end found it, else the name as
/// written (then opening it reports the missing file).
inline const std::string& fileToOpen(const std::string& resolved, const std::string& written) {
    return resolved.empty() ? written : resolved;
}

/// How much rendering a scene may load: chosen outside the script (crtc's --max-primitives,
/// --max-image-pixels), carried with the description so that every renderer of it sees them.
struct RenderLimits {
    /// Primitives stored, as the renderer stores them (instancing.hpp: an entity of 16 or
    /// more drawn again is stored once, each drawing one more), and a mesh's triangles. A
    /// render peaks at about 300 bytes a primitive (1,000,000 spheres: 300 MB), so the
    /// default, ~1.5 GB, fits in the default evaluation budget (Limits::maxMemory, 4 GiB) and
    /// is far above a hand-made scene.
    uint64_t maxPrimitives = 5'000'000;
    /// The most maxPrimitives may be: what the renderer can number (about 13 GB of spheres).
    static constexpr uint64_t kMostPrimitives = (uint64_t{1} << 27) - 1;
    /// Pixels of one image a texture or background reads (width × height from its header).
    uint64_t maxImagePixels = 100'000'000;
    /// Evaluations of an isosurface's function along one line before the search gives up
    /// (what it found so far is kept, and the render warns).
    uint64_t maxIsosurfaceEvaluations = 100'000;
};

/// How the scene moves while the shutter is open: what changes between the script's
/// evaluations at the motion steps, evenly spaced from the shutter's opening to its closing.
/// Between two steps each value goes linearly from one to the other.
struct MotionDesc {
    /// Each transform node that moves, by its entity: its modifiers at every step (the same
    /// kinds in the same order, their values differing).
    std::map<int32_t, std::vector<std::vector<Modifier>>> transforms;
    /// The camera at every step; empty when it stays where SceneDesc::camera has it.
    std::vector<CameraDesc> cameras;

    bool empty() const { return transforms.empty() && cameras.empty(); }
};

struct SceneStorage; // scene/instancing.hpp

/// The evaluated scene.
struct SceneDesc {
    static constexpr int kSchemaVersion = 3;

    std::vector<std::string> files; ///< script paths, indexed by SourceSpan::file
    SettingsDesc settings;
    CameraDesc camera;
    std::vector<LightDesc> lights; ///< the lights of Settings.lights, in order
    BackgroundDesc background;
    std::optional<FogDesc> fog;
    MotionDesc motion; ///< empty unless the shutter is open and something moves
    std::vector<MaterialDesc> materials;
    std::vector<FinishDesc> finishes; ///< shared by materials
    std::vector<TextureDesc> textures;
    std::vector<BlendDesc> blends; ///< of the materials made of others
    std::vector<MediumDesc> media; ///< what materials fill their solids with
    std::vector<EntityDesc> entities;
    std::vector<int32_t> drawn; ///< roots: entities drawn by Scene blocks, in order
    /// The meshes the front end read, by MeshShape::resolvedFile: the renderer draws what was
    /// checked, and reads the file of a mesh not here (a description built otherwise). Kept
    /// beside the entities, not in them, so that every entity stays as small as it was.
    std::map<std::string, std::shared_ptr<const MeshData>> meshes;
    /// The meshes the script wrote, by MeshShape::written.
    std::vector<std::shared_ptr<const MeshData>> writtenMeshes;
    double time = 0;            ///< t of this evaluation
    int frame = 0;
    int frameCount = 1;
    RenderLimits limits; ///< not part of the script: from the evaluation's options
    /// storageOf(*this), kept by the front end, which counts it when it has finished the
    /// description (its limit on what a scene stores), so that the renderer does not count a
    /// million entities again. Null in a description made otherwise: the renderer counts then.
    std::shared_ptr<const SceneStorage> storage;

    /// The finish of `material`.
    const FinishDesc& finishOf(const MaterialDesc& material) const {
        static const FinishDesc kDefault;
        return material.finish < 0 ? kDefault : finishes[static_cast<size_t>(material.finish)];
    }
    /// The index in finishes for `finish`: -1 for the default one, the last one added if
    /// equal (materials built in a loop), else a new entry.
    int32_t internFinish(const FinishDesc& finish) {
        if (finish == FinishDesc{}) return -1;
        if (finishes.empty() || !(finishes.back() == finish)) finishes.push_back(finish);
        return static_cast<int32_t>(finishes.size() - 1);
    }
};

/// "file:line:col" of a source span of `scene` ("" when the span is unknown).
inline std::string spanLocation(const SceneDesc& scene, const SourceSpan& span) {
    if (span.line == 0 || span.file >= scene.files.size()) return "";
    return scene.files[span.file] + ":" + std::to_string(span.line) + ":" + std::to_string(span.column);
}

} // namespace crt::scene
