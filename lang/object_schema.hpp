// The object types of spec §5 and their attributes: names, types, defaults and documentation.
//
// One table serves checking, documentation and completion alike.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace crt::lang {

enum class ObjectType : uint8_t {
    Settings,
    Camera,
    PointLight,
    ParallelLight,
    SpotLight,
    AreaLight,
    CylinderLight,
    SphereLight,
    Material,
    MaterialMap,
    Layered,
    Background,
    Fog,
    Medium,
    Sphere,
    Box,
    Plane,
    Cylinder,
    Cone,
    Torus,
    Superellipsoid,
    Prism,
    Sor,
    Lathe,
    SphereSweep,
    Text,
    Blob,
    Isosurface,
    HeightField,
    Merge,
    Inverse,
    Clipped,
    Disc,
    Quad,
    Triangle,
    SmoothTriangle,
    Polygon,
    Mesh,
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
    FunctionPattern,
    BlobSphere,
    BlobCylinder,
    Spline,
    Count,
};

enum class ObjectCategory : uint8_t {
    Settings,
    Camera,
    Light,
    Material,
    Background,
    Fog,
    Medium,
    Entity,
    Texture,
    BlobComponent, ///< a part of a Blob's field
    Spline,        ///< a curve through space, read with spline(s, t)
};

/// What an attribute accepts.
enum class AttrType : uint8_t {
    Float, ///< a float or an int
    Int,   ///< an int (a float is an error with a fix-it)
    Bool,
    String,
    Vec3,
    Color,
    Choice, ///< a string from `choices` (case-insensitive)
    Material,
    Camera,
    Background,        ///< a Background or a color
    Fog,               ///< a Fog
    Medium,            ///< a Medium
    FloatOrPattern,    ///< a float, or a pattern whose value is read
    LightList,         ///< a list of lights
    Texture,           ///< a pattern or Image texture
    Bump,              ///< a NoiseBump or ImageBump
    Gamma,             ///< a float > 0, or "srgb"
    Aperture,          ///< a shape name, or an int >= 3 (polygon sides)
    ColorMap,          ///< a list of [value, colour] pairs
    Turbulence,        ///< a float (the same on every axis) or a vec3
    MaterialMap,       ///< a list of [value, material] pairs
    MaterialList,      ///< a list of materials
    PatternList,       ///< a list of at least one pattern (no Image, no bump)
    Solid,             ///< an entity usable in CSG
    Entity,            ///< any entity but a mesh
    SolidList,         ///< a list of at least one such entity
    PointList,         ///< a list of vec3, every component finite
    BlobComponentList, ///< a list of at least one BlobSphere or BlobCylinder
    FloatList,         ///< a list of numbers, every one finite
    FaceList,          ///< a list of [a, b, c], three ints >= 0 each
    Function,          ///< a Function of (x, y, z)
    Box,               ///< a Box, as written (not moved)
};

struct AttributeInfo {
    std::string_view name;
    AttrType type;
    bool required;
    std::string_view defaultText; ///< as written in the spec, "" when required
    std::string_view doc;
    std::span<const std::string_view> choices = {};
};

struct ObjectInfo {
    ObjectType type;
    std::string_view name;
    ObjectCategory category;
    bool solid; ///< entities usable in CSG
    std::string_view doc;
    std::span<const AttributeInfo> attributes;
};

/// No object type has more attributes than this (Settings has the most).
inline constexpr size_t kMaxAttributes = 32;

const ObjectInfo& objectInfo(ObjectType type);
/// The object type called `name`, or ObjectType::Count.
ObjectType findObjectType(std::string_view name);
/// Index of attribute `name` in `info.attributes`, or -1 (synonyms map to their canonical).
int findAttribute(const ObjectInfo& info, std::string_view name);
std::span<const ObjectInfo> allObjectTypes();
/// The solid entity types in order, for messages: "Sphere, Box, … and Superellipsoid".
std::string solidTypeList();
/// Whether `type` is a bump texture (Bump, NoiseBump, ImageBump): one for `Material.bump`.
bool isBumpTexture(ObjectType type);
/// Whether `type` gives a colour (a pattern or Image): one for `Material.texture`.
bool isColorTexture(ObjectType type);
std::string_view attrTypeName(AttrType type);

} // namespace crt::lang
