// Object literals and the Settings statement (spec §5): the scene description entries they
// build from their checked attributes.
#include "object_builder.hpp"
#include "scene/curve_outline.hpp"
#include "scene/polygon_loops.hpp"

#include <cmath>
#include <filesystem>
#include <tuple>
#include <glm/geometric.hpp>

namespace crt::lang {

namespace fs = std::filesystem;

namespace {

/// Where an image or mesh named "/x" is looked for: under each asset root, or without
/// --assets, in the script's folder and those above it (as the original did). This is a
/// search, not a permission: what it finds is still checked against the FileAccess, and it
/// stops below the file system's root, so that "/etc/passwd" is never "/" + "etc/passwd".
std::vector<fs::path> assetSearchFolders(const fs::path& scriptFolder,
                                         const std::vector<std::string>& assetRoots) {
    std::error_code error;
    std::vector<fs::path> folders;
    for (const std::string& root : assetRoots) folders.push_back(fs::absolute(root, error));
    if (!assetRoots.empty()) return folders;
    fs::path dir = scriptFolder.has_filename() ? scriptFolder : scriptFolder.parent_path();
    for (; dir != dir.parent_path(); dir = dir.parent_path()) folders.push_back(dir);
    return folders;
}

/// Whether a refusal of `check`, for a name looked for in `folder`, may be reported. A name
/// that leaves the folder it is looked for in (by "..", or a link) is refused whether or not
/// it exists. In the folders above the script's, which are searched but not allowed, a file
/// is named only if it is there: otherwise the search goes on.
bool reportRefusal(const FileCheck& check, const fs::path& folder, bool searchedAbove) {
    if (check.kind != FileCheck::Kind::Outside || !searchedAbove) return true;
    std::error_code error;
    if (!isUnder(check.resolved, fs::weakly_canonical(folder, error))) return true;
    return fs::exists(check.resolved, error);
}

/// Looks a file up as an image or mesh, among the files `access` allows: "/x" in the
/// assetSearchFolders, else next to the script. Empty, with `problem` saying why, when there
/// is none.
std::string findAsset(const std::string& name, std::string_view what, const std::string& scriptPath,
                      const std::vector<std::string>& assetRoots, const FileAccess& access,
                      std::string& problem) {
    const fs::path scriptFolder = folderOf(scriptPath);
    const bool rooted = name.starts_with('/');
    const std::vector<fs::path> folders =
        rooted ? assetSearchFolders(scriptFolder, assetRoots) : std::vector{scriptFolder};
    for (const fs::path& folder : folders) {
        const fs::path candidate = folder / (rooted ? name.substr(1) : name);
        const FileCheck check = access.check(candidate);
        if (check.readable()) return candidate.lexically_normal().string();
        if (check.refused() && reportRefusal(check, folder, rooted && assetRoots.empty())) {
            problem = fmt::format("{} \"{}\" {}", what, candidate.lexically_normal().string(),
                                  check.reason);
            return {};
        }
    }
    const char* where = !rooted             ? "in the script's folder"
                        : assetRoots.empty() ? "in the script's folder or those above it"
                                             : "under the asset roots (--assets)";
    problem = fmt::format("cannot find {} \"{}\" {}", what, name, where);
    if (rooted) {
        // An absolute name of the machine is read only inside the roots.
        const FileCheck check = access.check(name);
        if (check.readable()) return name;
        if (check.refused()) problem += fmt::format("; as an absolute path, it {}", check.reason);
    }
    return {};
}

/// Whether a shape has no extent, and so draws nothing.

struct ZeroSize {
    bool operator()(const scene::SphereShape& s) const { return s.radius == 0; }
    bool operator()(const scene::BoxShape& s) const {
        return s.cornerA.x == s.cornerB.x || s.cornerA.y == s.cornerB.y ||
               s.cornerA.z == s.cornerB.z;
    }
    bool operator()(const scene::CylinderShape& s) const { return s.radius == 0; }
    bool operator()(const scene::ConeShape& s) const {
        return s.baseRadius == 0 && s.topRadius == 0;
    }
    bool operator()(const scene::TorusShape& s) const { return s.minor == 0; }
    bool operator()(const scene::DiscShape& s) const { return s.radius == 0 || s.hole == s.radius; }
    bool operator()(const scene::QuadShape& s) const {
        return glm::length(glm::cross(s.edgeA, s.edgeB)) == 0;
    }
    bool operator()(const scene::TriangleShape& s) const {
        return glm::length(glm::cross(s.b - s.a, s.c - s.a)) == 0;
    }
    bool operator()(const scene::PrismShape& s) const { return s.from == s.to; }
    bool operator()(const scene::SphereSweepShape& s) const {
        return std::all_of(s.radii.begin(), s.radii.end(), [](double r) { return r == 0; });
    }
    bool operator()(const scene::BlobShape& s) const {
        return std::none_of(s.desc->components.begin(), s.desc->components.end(),
                            [](const scene::BlobComponent& c) { return c.strength > 0; });
    }
    bool operator()(const scene::TextShape& s) const {
        return s.desc->thickness == 0 || (s.desc->outline && s.desc->outline->glyphs.empty());
    }
    bool operator()(const scene::PolygonShape& s) const {
        const auto loops = scene::polygonLoops(s.points);
        return loops.empty() || glm::length(scene::newellNormal(loops.front())) == 0;
    }
    bool operator()(const scene::SmoothTriangleShape& s) const {
        if (!s.mesh) return true;
        const auto& p = s.mesh->positions;
        return glm::length(glm::cross(p[1] - p[0], p[2] - p[0])) == 0;
    }
    bool operator()(const auto&) const { return false; } // planes and meshes
};

/// A material's finish; `diffuse` defaults to what reflection and refraction leave (to 1
/// when energy is conserved at each point).
scene::FinishDesc readFinish(const ObjectBuilder& b) {
    scene::FinishDesc f;
    f.reflectivity = b.number("reflectivity", f.reflectivity);
    f.reflectivityMin = b.number("reflectivitymin", f.reflectivityMin);
    f.reflectionFalloff = b.number("reflectionfalloff", f.reflectionFalloff);
    f.transparency = b.number("transparency", f.transparency);
    f.ior = b.number("ior", f.ior);
    f.conserveEnergy = b.flag("conserveenergy", f.conserveEnergy);
    f.diffuse = b.number(
        "diffuse", f.conserveEnergy ? 1.0 : std::max(0.0, 1.0 - f.reflectivity - f.transparency));
    f.brilliance = b.number("brilliance", f.brilliance);
    f.specular = b.number("specular", f.specular);
    f.shininess = b.number("shininess", f.shininess);
    f.metallic = b.flag("metallic", f.metallic);
    f.glossiness = b.number("glossiness", f.glossiness);
    f.fresnel = b.flag("fresnel", f.fresnel);
    f.absorption = b.color("absorption", f.absorption);
    f.emission = b.color("emission", f.emission);
    f.filter = b.number("filter", f.filter);
    f.texture = b.index("texture", f.texture);
    f.bump = b.index("bump", f.bump);
    f.medium = b.index("medium", f.medium);
    if (f.filter < 0 || f.filter > 1) {
        b.in.fail(b.where("filter"), "filter must be between 0 and 1");
    }
    if (f.ior <= 0) b.in.fail(b.where("ior"), "the index of refraction must be positive");
    if (f.glossiness < 0 || f.glossiness > 1) {
        b.in.fail(b.where("glossiness"), "glossiness must be between 0 and 1");
    }
    if (f.brilliance <= 0) b.in.fail(b.where("brilliance"), "brilliance must be positive");
    if (b.get("reflectivitymin") && f.reflectivityMin < 0) {
        b.in.fail(b.where("reflectivitymin"), "reflectivitymin must not be negative");
    }
    if (f.reflectionFalloff <= 0) {
        b.in.fail(b.where("reflectionfalloff"), "reflectionfalloff must be positive");
    }
    return f;
}

/// A camera's lens shape: a name, or a number of polygon sides (checked by the builder).
void readApertureShape(const ObjectBuilder& b, scene::CameraDesc& c) {
    const Value* shape = b.get("apertureshape");
    if (!shape) return;
    if (shape->kind == ValueKind::Int) {
        c.apertureShape = scene::ApertureShape::Polygon;
        c.apertureBlades = static_cast<int>(std::min<int64_t>(shape->i, 1000));
        return;
    }
    std::string name = b.lowerText("apertureshape");
    static const std::pair<std::string_view, int> polygons[] = {
        {"triangle", 3}, {"square", 4}, {"pentagon", 5}, {"hexagon", 6}, {"octagon", 8}};
    for (auto [polygon, sides] : polygons) {
        if (name == polygon) {
            c.apertureShape = scene::ApertureShape::Polygon;
            c.apertureBlades = sides;
        }
    }
    // "circle" and "uniform" (its 2015 name) keep the default disc.
    if (name == "gaussian") c.apertureShape = scene::ApertureShape::Gaussian;
    if (name == "line") c.apertureShape = scene::ApertureShape::Line;
}

/// Attenuation terms divide the intensity: none negative, and not all zero.
void checkAttenuation(const ObjectBuilder& b, const glm::dvec3& terms) {
    if (terms.x < 0 || terms.y < 0 || terms.z < 0) {
        b.in.fail(b.where("attenuation"), "attenuation terms must not be negative");
    }
    if (terms == glm::dvec3(0.0)) {
        b.in.fail(b.where("attenuation"),
                  "attenuation needs a positive term; vec3(1, 0, 0) is no attenuation");
    }
}

/// The rays an entity literal hides it from (`shadow`, `camera`, `reflected` given false).
uint8_t hiddenFrom(const ObjectBuilder& b) {
    uint8_t hidden = 0;
    if (!b.flag("camera", true)) hidden |= scene::kHiddenFromCamera;
    if (!b.flag("shadow", true)) hidden |= scene::kHiddenFromShadows;
    if (!b.flag("reflected", true)) hidden |= scene::kHiddenFromReflections;
    return hidden;
}

/// A Background takes exactly one mode: a color, a gradient, or an image.
void checkBackgroundMode(const ObjectBuilder& b) {
    int modes = (b.get("color") ? 1 : 0) + (b.get("horizon") || b.get("sky") ? 1 : 0) +
                (b.get("image") ? 1 : 0) + (b.get("pattern") ? 1 : 0) + (b.get("layers") ? 1 : 0);
    if (modes > 1) {
        b.in.fail(b.typeRange, "a Background takes exactly one of 'color', 'horizon' + 'sky', 'image', "
                               "'pattern' or 'layers'");
    }
    if (modes == 0) {
        b.in.fail(b.typeRange,
                  "a Background needs 'color', 'horizon' + 'sky', 'image', 'pattern' or 'layers'");
    }
    if (const Value* pattern = b.get("pattern"); pattern && pattern->objectType == ObjectType::Image) {
        b.in.fail(b.where("pattern"), "a Background's pattern is read on directions, not an Image; "
                                      "for a panorama, give 'image'");
    }
    if ((b.get("horizon") != nullptr) != (b.get("sky") != nullptr)) {
        b.in.fail(b.typeRange, "a gradient Background needs both 'horizon' and 'sky'");
    }
    if (b.get("angle") && !b.get("image")) {
        b.in.fail(b.where("angle"), "'angle' only applies to an 'image' Background");
    }
}

/// An image texture's mapping, when given (checked by the builder against the choices).
void readMapping(const ObjectBuilder& b, scene::TextureDesc& t) {
    if (!b.get("mapping")) return;
    std::string mapping = b.lowerText("mapping");
    static const std::pair<std::string_view, scene::TextureMapping> mappings[] = {
        {"uv", scene::TextureMapping::Uv},
        {"planar", scene::TextureMapping::Planar},
        {"spherical", scene::TextureMapping::Spherical},
        {"cylindrical", scene::TextureMapping::Cylindrical},
        {"cubic", scene::TextureMapping::Cubic}};
    for (auto [name, kind] : mappings) {
        if (mapping == name) t.mapping = kind;
    }
}

/// A pattern's colours: its `colors` map, or a 2015 texture's `a` and `b` (the stops at 0
/// and 1). Patterns that pick colours by position need as many stops as they have colours.
void readPatternColors(const ObjectBuilder& b, scene::TextureDesc& t) {
    if (b.get("colors") && (b.get("a") || b.get("b"))) {
        b.in.fail(b.where("colors"), fmt::format("{} is given both 'colors' and '{}'; give the "
                                                 "colour map or the two colours, not both",
                                                 b.info.name, b.get("a") ? "a" : "b"));
    }
    t.colors = b.colorMap("colors", t.colors);
    if (t.colors.size() == 2) {
        t.colors[0].color = b.color("a", t.colors[0].color);
        t.colors[1].color = b.color("b", t.colors[1].color);
    }
    size_t wanted = scene::discreteColorCount(t.kind);
    if (b.get("colors") && scene::isDiscretePattern(t.kind) && t.colors.size() != wanted) {
        b.in.fail(b.where("colors"), fmt::format("{} shows {} colours, one a stop; this map has {}",
                                                 b.info.name, wanted, t.colors.size()));
    }
}

/// A Bump's pattern, copied in: the Bump stands alone however the pattern is used elsewhere.
void readBumpPattern(const ObjectBuilder& b, const std::vector<scene::TextureDesc>& textures,
                     scene::TextureDesc& t) {
    const scene::TextureDesc& pattern = textures[static_cast<size_t>(b.index("pattern", 0))];
    if (scene::readsImage(pattern.kind)) {
        b.in.fail(b.where("pattern"),
                  "a Bump reads the slope of a pattern's value, and an Image has none to read; "
                  "use ImageBump for an image");
    }
    t.pattern = {pattern};
}

/// Frequency, phase and waveform (checked by the builder against the choices).
void readWave(const ObjectBuilder& b, scene::TextureDesc& t) {
    t.frequency = b.number("frequency", t.frequency);
    t.phase = b.number("phase", t.phase);
    t.exponent = b.number("exponent", t.exponent);
    if (!b.get("waveform")) return;
    std::string waveform = b.lowerText("waveform");
    for (size_t i = 0; i < std::size(scene::kWaveformNames); ++i) {
        if (waveform == scene::kWaveformNames[i]) t.waveform = static_cast<scene::Waveform>(i);
    }
}

/// Mandel's most iterations a point: more would make a render look hung.
constexpr int64_t kMaxIterations = 100000;
constexpr int64_t kMaxArms = 1000000; ///< beyond any use; keeps the count an int

/// The attributes that only some patterns have: arms, bricks, quilts, iterations, cells
/// (Crackle) and a slope's direction.
void readPatternShape(ObjectBuilder& b, scene::TextureDesc& t) {
    int64_t arms = b.integer("arms", t.arms);
    if (arms < -kMaxArms || arms > kMaxArms) {
        b.in.fail(b.where("arms"),
                  fmt::format("arms must be between {} and {}", -kMaxArms, kMaxArms));
    }
    t.arms = static_cast<int>(arms);
    t.brickSize = b.vec("bricksize", t.brickSize);
    if (b.get("bricksize") && !(t.brickSize.x > 0 && t.brickSize.y > 0 && t.brickSize.z > 0)) {
        b.in.fail(b.where("bricksize"), "a brick's size must be positive on every axis");
    }
    t.mortar = b.number("mortar", t.mortar);
    b.nonNegative("mortar");
    t.control0 = b.number("control0", t.control0);
    t.control1 = b.number("control1", t.control1);
    int64_t iterations = b.integer("iterations", t.iterations);
    if (b.get("iterations") && (iterations < 1 || iterations > kMaxIterations)) {
        b.in.fail(b.where("iterations"),
                  fmt::format("iterations must be between 1 and {}", kMaxIterations));
    }
    t.iterations = static_cast<int>(iterations);
    t.metric = b.number("metric", t.metric);
    if (b.get("metric") && t.metric <= 0) b.in.fail(b.where("metric"), "a metric must be positive");
    t.form = b.vec("form", t.form);
    t.axis = b.vec("direction", t.axis);
    if (b.get("direction")) b.nonZeroVector("direction", "a slope needs a direction");
}

} // namespace

scene::SourceSpan Interpreter::span(SourceRange range) const {
    // Literals in a loop are converted over and over: remember recent ones.
    SpanCacheEntry& entry = spanCache_[(range.begin * 2654435761u) >> 28];
    if (entry.range == range) return entry.span;
    const SourceFile& file = compilation_.sources.file(range.file);
    LineColumn begin = file.lineColumn(range.begin);
    LineColumn end = file.lineColumn(range.end);
    entry = {range, {range.file, begin.line, begin.column, end.line, end.column}};
    return entry.span;
}

int32_t Interpreter::addEntity(scene::EntityDesc entity, EntityInfo info) {
    const Limits& limits = options_.limits;
    if (scene_.entities.size() >= limits.maxEntities) {
        failAtLimit(info.range,
                    fmt::format("the script builds more than {} entities (drawn or not); raise "
                                "the limit with --max-entities",
                                limits.maxEntities));
    }
    scene_.entities.push_back(std::move(entity));
    entityInfo_.push_back(info);
    return static_cast<int32_t>(scene_.entities.size() - 1);
}

void Interpreter::warnOnce(WarningKind kind, SourceRange where, std::string message) {
    if (warnedOnce_.emplace(kind, where.file, where.begin).second) {
        diagnostics_.warning(kind, where, std::move(message));
    }
}

std::string Interpreter::findFile(const ObjectBuilder& b, std::string_view attribute,
                                  std::string_view what) {
    std::string name = b.text(attribute, std::string());
    if (!options_.checkFiles) return std::string();
    std::string problem;
    std::string found = findAsset(name, what, compilation_.sources.file(b.range.file).path(),
                                  options_.assetRoots, fileAccess(), problem);
    if (found.empty()) fail(b.where(attribute), problem);
    return found;
}

Value Interpreter::evalObject(const ObjectExpr* node) {
    if (node->type == ObjectType::Count) {
        fail(node->typeRange, "unknown object type"); // resolver reported
    }
    const ObjectInfo& info = objectInfo(node->type);
    ObjectBuilder b{*this, info, node->range, node->typeRange};
    b.evaluate(node->attributes);
    switch (info.category) {
    case ObjectCategory::Entity: return buildEntity(b);
    case ObjectCategory::Material: return buildMaterial(b);
    case ObjectCategory::Camera: return buildCamera(b);
    case ObjectCategory::Light: return buildLight(b);
    case ObjectCategory::Background: return buildBackground(b);
    case ObjectCategory::Fog: return buildFog(b);
    case ObjectCategory::Medium: return buildMedium(b);
    case ObjectCategory::Texture: return buildTexture(b);
    case ObjectCategory::BlobComponent: return buildBlobComponent(b);
    case ObjectCategory::Spline: return buildSpline(b);
    case ObjectCategory::Settings: break; // a statement (execSettings), never a value
    }
    fail(node->typeRange, "unknown object type");
}

Value Interpreter::buildEntity(ObjectBuilder& b) {
    if (b.info.type == ObjectType::Merge || b.info.type == ObjectType::Inverse ||
        b.info.type == ObjectType::Clipped)
        return buildCombination(b);
    scene::Shape shape = b.info.solid ? solidShape(b) : surfaceShape(b);
    bool zeroSize = std::visit(ZeroSize{}, shape);
    bool solid = b.info.solid;
    if (auto* lathe = std::get_if<scene::LatheShape>(&shape))
        solid = scene::curveEnclosesSolid(scene::curveSegments(lathe->points, lathe->spline));
    if (auto* isosurface = std::get_if<scene::IsosurfaceShape>(&shape))
        solid = !isosurface->desc->open;
    // A closed mesh bounds a solid. One not read (files not checked) passes for one here; the
    // renderer, which reads it, finds it open or not.
    if (auto* mesh = std::get_if<scene::MeshShape>(&shape)) {
        const scene::MeshData* data = meshDataOf(*mesh);
        solid = !data || data->closed;
    }
    const int32_t material = b.index("material", -1);
    int32_t index = addEntity(scene::EntityDesc{std::move(shape), material, solid, span(b.range), hiddenFrom(b)},
                              EntityInfo{b.range, b.info.type, true});
    // An animated script (one reading t or clock) often starts from zero size.
    if (zeroSize && !animated_) {
        warnOnce(WarningKind::ZeroSizeEntity, b.typeRange,
                 fmt::format("this {} has zero size and draws nothing", b.info.name));
    }
    return Value::object(ValueKind::Entity, b.info.type, static_cast<uint32_t>(index));
}

Value Interpreter::buildCombination(ObjectBuilder& b) {
    const EntityInfo info{b.range, b.info.type, true};
    // A clipped entity is open where it was cut: a surface.
    const bool solid = b.info.type != ObjectType::Clipped;
    auto add = [&](scene::Shape shape) {
        return addEntity(scene::EntityDesc{std::move(shape), -1, solid, span(b.range)}, info);
    };
    int32_t index;
    if (b.info.type == ObjectType::Inverse) {
        index = add(scene::InverseNode{b.index("object", -1)});
    } else if (b.info.type == ObjectType::Clipped) {
        index = add(scene::CsgNode{scene::CsgOp::Clip, b.index("object", -1), b.index("by", -1)});
    } else {
        // A chain of merges; one object merges with itself, so that the result is a Merge still.
        const std::vector<Value>& objects = *b.get("objects")->list;
        index = static_cast<int32_t>(objects[0].index);
        for (size_t i = objects.size() > 1 ? 1 : 0; i < objects.size(); ++i)
            index = add(
                scene::CsgNode{scene::CsgOp::Merge, index, static_cast<int32_t>(objects[i].index)});
    }
    // Its own material is given to the parts without one, as `<material m>` gives it.
    if (const int32_t material = b.index("material", -1); material >= 0) {
        index = addEntity(
            scene::EntityDesc{scene::TransformNode{index, {}}, material, solid, span(b.range)},
            info);
    }
    scene_.entities[static_cast<size_t>(index)].hidden = hiddenFrom(b);
    return Value::object(ValueKind::Entity, b.info.type, static_cast<uint32_t>(index));
}

scene::Shape Interpreter::solidShape(ObjectBuilder& b) {
    switch (b.info.type) {
    case ObjectType::Sphere: {
        scene::SphereShape s;
        b.nonNegative("radius");
        s.center = b.vec("center", s.center);
        s.radius = b.number("radius", s.radius);
        return s;
    }
    case ObjectType::Box: {
        scene::BoxShape s;
        s.cornerA = b.vec("cornerA", s.cornerA);
        s.cornerB = b.vec("cornerB", s.cornerB);
        // Identical corners are a mistake, except in an animation growing a box from a point.
        if (s.cornerA == s.cornerB && !animated_) {
            fail(b.where("cornerB"), "the corners of this Box are the same point");
        }
        return s;
    }
    case ObjectType::Plane: {
        scene::PlaneShape s;
        b.nonZeroVector("normal", "a plane needs a direction");
        s.normal = b.vec("normal", s.normal);
        s.position = b.vec("position", s.position);
        return s;
    }
    case ObjectType::Cylinder: {
        scene::CylinderShape s;
        b.nonNegative("radius");
        s.base = b.vec("base", s.base);
        s.top = b.vec("top", s.top);
        if (s.base == s.top) {
            fail(b.where("top"), "the base and top of this Cylinder are the same point");
        }
        s.radius = b.number("radius", s.radius);
        s.open = b.flag("open", s.open);
        return s;
    }
    case ObjectType::Cone: {
        scene::ConeShape s;
        b.nonNegative("baseradius");
        b.nonNegative("topradius");
        s.base = b.vec("base", s.base);
        s.top = b.vec("top", s.top);
        if (s.base == s.top) {
            fail(b.where("top"), "the base and top of this Cone are the same point");
        }
        s.baseRadius = b.number("baseradius", s.baseRadius);
        s.topRadius = b.number("topradius", s.topRadius);
        s.open = b.flag("open", s.open);
        return s;
    }
    case ObjectType::Superellipsoid: {
        scene::SuperellipsoidShape s;
        for (std::string_view exponent : {"e", "n"}) {
            if (b.get(exponent) && !(b.number(exponent, 1) > 0)) {
                fail(b.where(exponent),
                     fmt::format("the exponent '{}' of a Superellipsoid must be positive",
                                 exponent));
            }
        }
        s.e = b.number("e", s.e);
        s.n = b.number("n", s.n);
        return s;
    }
    case ObjectType::Prism: return prismShape(b);
    case ObjectType::Sor: return sorShape(b);
    case ObjectType::Lathe: return latheShape(b);
    case ObjectType::SphereSweep: return sphereSweepShape(b);
    case ObjectType::Text: return textShape(b);
    case ObjectType::Blob: return blobShape(b);
    case ObjectType::Isosurface: return isosurfaceShape(b);
    case ObjectType::HeightField: return heightFieldShape(b);
    case ObjectType::Torus:
    default: {
        scene::TorusShape s;
        b.nonNegative("major");
        b.nonNegative("minor");
        b.nonZeroVector("axis", "a torus needs an axis");
        s.center = b.vec("center", s.center);
        s.major = b.number("major", s.major);
        s.minor = b.number("minor", s.minor);
        s.axis = b.vec("axis", s.axis);
        return s;
    }
    }
}

/// The points of a Polygon: at least three, each loop of at least three, all in the plane of
/// the first loop (to a relative 1e-9 of the polygon's size, far above rounding).
scene::Shape Interpreter::polygonShape(ObjectBuilder& b) {
    scene::PolygonShape s;
    for (const Value& p : *b.get("points")->list) s.points.push_back({p.v[0], p.v[1], p.v[2]});
    const auto loops = scene::polygonLoops(s.points);
    for (size_t i = 0; i < loops.size(); ++i) {
        if (loops[i].size() < 3) {
            fail(b.where("points"),
                 loops.size() == 1
                     ? fmt::format("a Polygon needs at least 3 points, not {}", loops[i].size())
                     : fmt::format("loop {} of this Polygon has {} point{}; a loop needs at least 3",
                                   i + 1, loops[i].size(), loops[i].size() == 1 ? "" : "s"));
        }
    }
    const glm::dvec3 normal = scene::newellNormal(loops.front());
    const double area = glm::length(normal);
    if (area == 0) return s; // no plane: zero size, warned as such
    double size = 0;
    for (const glm::dvec3& p : s.points)
        size = std::max(size, glm::length(p - loops.front().front()));
    for (size_t i = 0; i < s.points.size(); ++i) {
        const double off = std::abs(glm::dot(normal / area, s.points[i] - loops.front().front()));
        if (off > 1e-9 * size) {
            fail(b.whereItem("points", i),
                 fmt::format(
                     "the points of this Polygon do not lie in one plane: point {} is {:.3g} "
                     "off the plane that fits its first loop",
                     i + 1, off));
        }
    }
    return s;
}

scene::Shape Interpreter::surfaceShape(ObjectBuilder& b) {
    switch (b.info.type) {
    case ObjectType::Disc: {
        scene::DiscShape s;
        b.nonNegative("radius");
        b.nonNegative("hole");
        b.nonZeroVector("normal", "a disc needs a direction");
        s.center = b.vec("center", s.center);
        s.normal = b.vec("normal", s.normal);
        s.radius = b.number("radius", s.radius);
        s.hole = b.number("hole", s.hole);
        if (s.hole > s.radius) {
            fail(b.where("hole"), "the hole of this Disc is larger than its radius");
        }
        return s;
    }
    case ObjectType::Quad: {
        scene::QuadShape s;
        s.corner = b.vec("corner", s.corner);
        s.edgeA = b.vec("edgeA", s.edgeA);
        s.edgeB = b.vec("edgeB", s.edgeB);
        return s;
    }
    case ObjectType::Triangle: {
        scene::TriangleShape s;
        s.a = b.vec("a", s.a);
        s.b = b.vec("b", s.b);
        s.c = b.vec("c", s.c);
        return s;
    }
    case ObjectType::Polygon: return polygonShape(b);
    case ObjectType::SmoothTriangle: {
        for (std::string_view normal : {"na", "nb", "nc"})
            b.nonZeroVector(normal, "each corner needs a direction");
        const glm::dvec3 none(0.0); // all six are required
        return scene::smoothTriangle(b.vec("a", none), b.vec("b", none), b.vec("c", none),
                                     b.vec("na", none), b.vec("nb", none), b.vec("nc", none));
    }
    case ObjectType::Mesh:
    default: return meshShape(b);
    }
}

namespace {

/// A MaterialMap's or a Layered's materials, as a blend of them.
scene::BlendDesc readBlend(const ObjectBuilder& b,
                           const std::vector<scene::TextureDesc>& textures) {
    scene::BlendDesc blend;
    if (b.info.type == ObjectType::Layered) {
        blend.kind = scene::BlendKind::Layers;
        for (const Value& layer : *b.get("materials")->list) {
            blend.materials.push_back(static_cast<int32_t>(layer.index));
        }
        return blend;
    }
    blend.pattern = b.index("pattern", blend.pattern);
    if (scene::readsImage(textures[static_cast<size_t>(blend.pattern)].kind)) {
        b.in.fail(b.where("pattern"),
                  "a MaterialMap reads a pattern's value, and an Image has none to read");
    }
    for (const Value& entry : *b.get("materials")->list) {
        blend.values.push_back((*entry.list)[0].asDouble());
        blend.materials.push_back(static_cast<int32_t>((*entry.list)[1].index));
    }
    return blend;
}

} // namespace

Value Interpreter::buildMaterial(const ObjectBuilder& b) {
    scene::FinishDesc finish;
    if (b.info.type == ObjectType::Material) {
        finish = readFinish(b);
    } else {
        scene_.blends.push_back(readBlend(b, scene_.textures));
        finish.blend = static_cast<int32_t>(scene_.blends.size() - 1);
    }
    scene::MaterialDesc& m = scene_.materials.emplace_back();
    m.color = b.color("color", m.color);
    m.finish = scene_.internFinish(finish);
    m.source = span(b.range);
    return Value::object(ValueKind::Material, b.info.type,
                         static_cast<uint32_t>(scene_.materials.size() - 1));
}

Value Interpreter::buildCamera(ObjectBuilder& b) {
    scene::CameraDesc c;
    c.position = b.vec("position", c.position);
    c.pointing = b.vec("pointing", c.pointing);
    if (c.position == c.pointing) {
        fail(b.where("pointing"), "the camera points at its own position");
    }
    if (b.get("projection")) {
        const std::string projection = b.lowerText("projection");
        for (size_t i = 0; i < std::size(scene::kProjectionNames); ++i)
            if (projection == scene::kProjectionNames[i]) c.projection = static_cast<scene::Projection>(i);
    }
    c.fov = b.number("fov", c.fov);
    // A fisheye or a cylindrical panorama may take in every direction around.
    const bool allAround =
        c.projection == scene::Projection::Fisheye || c.projection == scene::Projection::Cylindrical;
    if (allAround && (c.fov <= 0 || c.fov > 360)) {
        fail(b.where("fov"), fmt::format("fov must be in (0, 360] degrees for a {} camera, not {}",
                                         scene::kProjectionNames[static_cast<int>(c.projection)], formatFloat(c.fov)));
    } else if (!allAround && (c.fov <= 0 || c.fov >= 180)) {
        fail(b.where("fov"), fmt::format("fov must be in (0, 180) degrees, not {}", formatFloat(c.fov)));
    }
    c.width = b.number("width", c.width);
    if (b.get("width") && c.width <= 0) fail(b.where("width"), "width must be positive");
    c.aperture = b.number("aperture", c.aperture);
    if (c.aperture < 0) fail(b.where("aperture"), "aperture must not be negative");
    c.focalDistance = b.number("focaldistance", glm::length(c.pointing - c.position));
    if (c.focalDistance <= 0) fail(b.where("focaldistance"), "focaldistance must be positive");
    readApertureShape(b, c);
    c.up = b.vec("up", c.up);
    b.nonZeroVector("up", "the camera needs an up direction");
    c.roll = b.number("roll", c.roll);
    c.source = span(b.range);
    cameras_.push_back(c);
    return Value::object(ValueKind::Camera, b.info.type,
                         static_cast<uint32_t>(cameras_.size() - 1));
}

Value Interpreter::buildLight(const ObjectBuilder& b) {
    ObjectType type = b.info.type;
    scene::LightDesc l;
    l.kind = type == ObjectType::PointLight      ? scene::LightKind::Point
             : type == ObjectType::ParallelLight ? scene::LightKind::Parallel
             : type == ObjectType::SpotLight     ? scene::LightKind::Spot
             : type == ObjectType::CylinderLight ? scene::LightKind::Cylinder
             : type == ObjectType::SphereLight   ? scene::LightKind::Sphere
                                                 : scene::LightKind::Area;
    l.origin = b.vec(type == ObjectType::AreaLight ? "corner" : type == ObjectType::SphereLight ? "center" : "origin",
                     l.origin);
    l.from = b.vec("from", l.from);
    l.to = b.vec("to", l.to);
    l.pointing = b.vec("pointing", l.pointing);
    l.edgeA = b.vec("edgeA", l.edgeA);
    l.edgeB = b.vec("edgeB", l.edgeB);
    l.color = b.color("color", l.color);
    l.falloff = b.number("falloff", l.falloff);
    l.attenuation = b.vec("attenuation", l.attenuation);
    checkAttenuation(b, l.attenuation);
    l.ambient = b.number("ambient", l.ambient);
    l.angle = b.number("angle", l.angle);
    l.softness = b.number("softness", l.softness);
    l.tightness = b.number("tightness", l.tightness);
    l.shadowless = b.flag("shadowless", l.shadowless);
    l.radius = b.number("radius", l.radius);
    l.visible = b.flag("visible", l.visible);
    l.circular = b.flag("circular", l.circular);
    l.orient = b.flag("orient", l.orient);
    if (type == ObjectType::ParallelLight && l.from == l.pointing) {
        fail(b.where("pointing"), "a ParallelLight needs 'from' and 'pointing' to differ");
    }
    if (type == ObjectType::SpotLight) {
        if (l.origin == l.pointing) {
            fail(b.where("pointing"), "a SpotLight needs 'origin' and 'pointing' to differ");
        }
        if (l.angle <= 0 || l.angle >= 180) {
            fail(b.where("angle"), "a SpotLight's angle must be in (0, 180) degrees");
        }
        if (l.softness < 0 || l.softness > 1) {
            fail(b.where("softness"), "softness must be between 0 and 1");
        }
        if (l.tightness < 0) fail(b.where("tightness"), "tightness must not be negative");
    }
    if (type == ObjectType::SphereLight && !(l.radius > 0))
        fail(b.where("radius"), "a SphereLight's radius must be above 0");
    if (type == ObjectType::CylinderLight && l.radius < 0)
        fail(b.where("radius"), "a CylinderLight's radius must not be negative");
    if (type == ObjectType::CylinderLight && l.from == l.to) {
        fail(b.where("to"), "a CylinderLight needs 'from' and 'to' to differ; it has no length");
    }
    if (type == ObjectType::AreaLight && glm::length(glm::cross(l.edgeA, l.edgeB)) == 0) {
        fail(b.where("edgeB"), "the edges of this AreaLight are parallel or zero; it has no area");
    }
    l.source = span(b.range);
    lights_.push_back(l);
    lightInfo_.push_back({type, b.range, false});
    return Value::object(ValueKind::Light, type, static_cast<uint32_t>(lights_.size() - 1));
}

Value Interpreter::buildBackground(const ObjectBuilder& b) {
    checkBackgroundMode(b);
    scene::BackgroundDesc bg;
    if (b.get("color")) {
        bg.kind = scene::BackgroundKind::Solid;
        bg.color = b.color("color", bg.color);
    } else if (b.get("horizon")) {
        bg.kind = scene::BackgroundKind::Gradient;
        bg.horizon = b.color("horizon", bg.horizon);
        bg.sky = b.color("sky", bg.sky);
    } else if (const Value* pattern = b.get("pattern")) {
        bg.kind = scene::BackgroundKind::Pattern;
        bg.layers.push_back(scene_.textures[pattern->index]);
    } else if (const Value* layers = b.get("layers")) {
        bg.kind = scene::BackgroundKind::Pattern;
        for (const Value& layer : *layers->list) bg.layers.push_back(scene_.textures[layer.index]);
    } else {
        bg.kind = scene::BackgroundKind::Image;
        bg.image = b.text("image", bg.image);
        bg.resolvedImage = findFile(b, "image", "image");
        bg.angle = b.number("angle", bg.angle);
    }
    bg.source = span(b.range);
    backgrounds_.push_back(std::move(bg));
    return Value::object(ValueKind::Background, b.info.type,
                         static_cast<uint32_t>(backgrounds_.size() - 1));
}

Value Interpreter::buildMedium(ObjectBuilder& b) {
    scene::MediumDesc m;
    m.absorption = b.color("absorption", m.absorption);
    m.scattering = b.color("scattering", m.scattering);
    m.emission = b.color("emission", m.emission);
    for (std::string_view name : {"absorption", "scattering", "emission"}) {
        const scene::Color c = b.color(name, {});
        if (c.r < 0 || c.g < 0 || c.b < 0) fail(b.where(name), fmt::format("a Medium's {} must not be negative", name));
    }
    if (const Value* density = b.get("density"); density && density->kind == ValueKind::Texture) {
        m.densityPattern.push_back(scene_.textures[density->index]);
    } else {
        m.density = b.number("density", m.density);
        if (m.density < 0) fail(b.where("density"), "a Medium's density must not be negative");
    }
    const std::string phase = b.lowerText("phase");
    for (size_t i = 0; i < std::size(scene::kPhaseNames); ++i)
        if (phase == scene::kPhaseNames[i]) m.phase = static_cast<scene::PhaseFunction>(i);
    m.g = b.number("g", m.g);
    if (!(m.g > -1 && m.g < 1)) fail(b.where("g"), "g must be strictly between -1 and 1");
    m.samples = static_cast<int>(std::clamp<int64_t>(b.integer("samples", m.samples), 0, 1 << 20));
    if (m.samples < scene::kMediumSamplesRange.min || m.samples > scene::kMediumSamplesRange.max)
        fail(b.where("samples"), fmt::format("a Medium's samples must be {} to {}", scene::kMediumSamplesRange.min,
                                             scene::kMediumSamplesRange.max));
    m.source = span(b.range);
    scene_.media.push_back(std::move(m));
    return Value::object(ValueKind::Medium, b.info.type, static_cast<uint32_t>(scene_.media.size() - 1));
}

Value Interpreter::buildFog(ObjectBuilder& b) {
    scene::FogDesc fog;
    fog.color = b.color("color", fog.color);
    fog.distance = b.number("distance", fog.distance);
    if (!(fog.distance > 0)) fail(b.where("distance"), "a Fog's distance must be positive");
    fog.filter = b.number("filter", fog.filter);
    if (fog.filter < 0 || fog.filter > 1) fail(b.where("filter"), "filter must be between 0 and 1");
    fog.falloff = b.number("falloff", fog.falloff);
    if (b.get("falloff") && !(fog.falloff > 0)) fail(b.where("falloff"), "a Fog's falloff must be positive");
    for (std::string_view groundOnly : {"altitude", "up"}) {
        if (b.get(groundOnly) && !b.get("falloff"))
            fail(b.where(groundOnly), fmt::format("'{}' only applies to ground fog, which 'falloff' makes", groundOnly));
    }
    fog.altitude = b.number("altitude", fog.altitude);
    b.nonZeroVector("up", "it is the direction heights are measured along");
    fog.up = glm::normalize(b.vec("up", fog.up));
    fog.turbulence = b.floatOrVec("turbulence", fog.turbulence);
    fog.turbulenceDepth = b.number("turbulencedepth", fog.turbulenceDepth);
    if (fog.turbulenceDepth < 0 || fog.turbulenceDepth > 1)
        fail(b.where("turbulencedepth"), "turbulencedepth must be between 0 and 1");
    fog.source = span(b.range);
    fogs_.push_back(fog);
    return Value::object(ValueKind::Fog, b.info.type, static_cast<uint32_t>(fogs_.size() - 1));
}

// A texture's kind is its object type's place after Checker: the two lists keep one order.
static_assert(static_cast<int>(ObjectType::FunctionPattern) - static_cast<int>(ObjectType::Checker) ==
              static_cast<int>(scene::TextureKind::FunctionPattern));

Value Interpreter::buildTexture(ObjectBuilder& b) {
    ObjectType type = b.info.type;
    scene::TextureDesc t = scene::defaultTexture(static_cast<scene::TextureKind>(
        static_cast<int>(type) - static_cast<int>(ObjectType::Checker)));
    readPatternColors(b, t);
    t.size = b.number("size", t.size);
    if (b.get("size") && t.size <= 0) fail(b.where("size"), "a texture's size must be positive");
    t.axis = b.vec("axis", t.axis);
    if (b.get("axis")) {
        b.nonZeroVector("axis", t.kind == scene::TextureKind::Stripes
                                    ? "stripes need a direction"
                                    : "a gradient needs a direction");
    }
    int64_t octaves = b.integer("octaves", t.octaves);
    if (octaves < 1 || octaves > 16) fail(b.where("octaves"), "octaves must be between 1 and 16");
    t.octaves = static_cast<int>(octaves);
    if (scene::hasOwnTurbulence(t.kind)) {
        t.turbulence = b.number("turbulence", t.turbulence);
    } else {
        t.displacement = b.floatOrVec("turbulence", t.displacement);
    }
    t.omega = b.number("omega", t.omega);
    t.lambda = b.number("lambda", t.lambda);
    readWave(b, t);
    readPatternShape(b, t);
    t.rings = b.number("rings", t.rings);
    t.strength = b.number("strength", t.strength);
    if (t.kind == scene::TextureKind::Bump) readBumpPattern(b, scene_.textures, t);
    if (t.kind == scene::TextureKind::FunctionPattern) t.function = functionProgram(b.get("function")->index);
    if (scene::readsImage(t.kind)) {
        t.file = b.text("file", t.file);
        t.resolvedFile = findFile(b, "file", "image");
        readMapping(b, t);
    }
    t.source = span(b.range);
    scene_.textures.push_back(std::move(t));
    return Value::object(ValueKind::Texture, type,
                         static_cast<uint32_t>(scene_.textures.size() - 1));
}

void Interpreter::execSettings(const SettingsStmt* node) {
    SourceRange keyword{node->range.file, node->range.begin, node->range.begin + 8};
    if (settings_) {
        Diagnostic& d =
            diagnostics_.error(node->range.begin + 8 <= node->range.end ? keyword : node->range,
                               "a second Settings block; a script has at most one");
        d.notes.push_back(
            {{settings_->range.file, settings_->range.begin, settings_->range.begin + 8},
             "the first Settings block is here"});
        throw EvalError{};
    }
    settings_ = node;
    ObjectBuilder b{*this, objectInfo(ObjectType::Settings), node->range, keyword};
    const size_t diagnosticsBefore = diagnostics_.items().size();
    bool complete = true;
    try {
        b.evaluate(node->attributes);
    } catch (const EvalError&) {
        if (stopped_) throw;
        complete = false; // the values that could be read are still checked
    }
    buildSettings(b);
    if (!settingsProblems_.empty()) complete = false;
    reportSettingsProblems();
    if (!complete) {
        diagnostics_.sortByPosition(diagnosticsBefore); // in the order written, whichever check found it
        throw EvalError{};
    }
}

void Interpreter::buildSettings(const ObjectBuilder& b) {
    auto problem = [&](std::string_view name, std::string message) {
        settingsProblems_.push_back(DeferredError{b.where(name), std::move(message)});
    };
    auto ranged = [&](std::string_view name, int absent, int64_t minimum, int64_t maximum) {
        int64_t v = b.integer(name, absent);
        if (v < minimum || v > maximum) {
            problem(name,
                    fmt::format("{} must be between {} and {}, not {}", name, minimum, maximum, v));
        }
        return static_cast<int>(v);
    };
    auto imageSize = [&](std::string_view name, int absent) {
        int64_t v = b.integer(name, absent);
        uint32_t maxSize = options_.limits.maxSize;
        if (v < 1 || v > maxSize) {
            problem(name, fmt::format("{} must be between 1 and {} pixels, not {}{}", name, maxSize,
                                      v, v > maxSize ? "; raise the limit with --max-size" : ""));
        }
        return static_cast<int>(v);
    };

    scene::SettingsDesc& s = scene_.settings;
    s.title = b.text("title", s.title);
    s.author = b.text("author", s.author);
    s.date = b.text("date", s.date);
    s.notes = b.text("notes", s.notes);
    s.width = imageSize("width", s.width);
    s.height = imageSize("height", s.height);
    if (const Value* gamma = b.get("gamma")) {
        if (gamma->kind == ValueKind::String) {
            s.srgb = true; // the builder allows only "srgb"
        } else {
            s.gamma = gamma->asDouble();
        }
    }
    auto count = [&](const char* name, int value, scene::CountRange range) {
        return ranged(name, value, range.min, range.max);
    };
    s.supersampling = count("supersampling", s.supersampling, scene::kSupersamplingRange);
    s.dofSamples = count("dofsamples", s.dofSamples, scene::kDofSamplesRange);
    s.recursionDepth = ranged("recursiondepth", s.recursionDepth, 0, 1000);
    if (b.get("reflectiondepth")) s.reflectionDepth = ranged("reflectiondepth", 0, 0, 1000);
    if (b.get("refractiondepth")) s.refractionDepth = ranged("refractiondepth", 0, 0, 1000);
    if (b.get("antialias")) {
        const std::string antialias = b.lowerText("antialias");
        for (size_t i = 0; i < std::size(scene::kAntialiasNames); ++i)
            if (antialias == scene::kAntialiasNames[i]) s.antialias = static_cast<scene::Antialias>(i);
    }
    s.aaThreshold = b.number("aathreshold", s.aaThreshold);
    if (s.aaThreshold < 0) problem("aathreshold", "aathreshold must not be negative");
    s.aaDepth = ranged("aadepth", s.aaDepth, 0, 8);
    s.shadowSamples = count("shadowsamples", s.shadowSamples, scene::kShadowSamplesRange);
    s.glossySamples = count("glossysamples", s.glossySamples, scene::kGlossySamplesRange);
    int64_t seed = b.integer("seed", static_cast<int64_t>(s.seed));
    if (seed < 0) problem("seed", "seed must not be negative");
    s.seed = static_cast<uint64_t>(seed);
    s.ambient = b.color("ambient", s.ambient);
    if (b.get("integrator")) {
        const std::string integrator = b.lowerText("integrator");
        for (size_t i = 0; i < std::size(scene::kIntegratorNames); ++i)
            if (integrator == scene::kIntegratorNames[i]) s.integrator = static_cast<scene::Integrator>(i);
    }
    s.samples = count("samples", s.samples, scene::kPathSamplesRange);
    s.bounces = count("bounces", s.bounces, scene::kBouncesRange);
    if (b.get("targeterror")) {
        s.targetError = b.number("targeterror", s.targetError);
        if (!(s.targetError > 0)) problem("targeterror", "targeterror must be above 0");
    }
    s.shutterOpen = b.number("shutteropen", s.shutterOpen);
    s.shutterClose = b.number("shutterclose", s.shutterOpen);
    if (options_.shutter) std::tie(s.shutterOpen, s.shutterClose) = *options_.shutter;
    if (!std::isfinite(s.shutterOpen) || !std::isfinite(s.shutterClose) || s.shutterClose < s.shutterOpen)
        problem(b.get("shutterclose") ? "shutterclose" : "shutteropen",
                fmt::format("the shutter must close at or after it opens, not from {} to {}", s.shutterOpen,
                            s.shutterClose));
    s.motionSteps = count("motionsteps", s.motionSteps, scene::kMotionStepsRange);
    recordSettingsLinks(b);
}

void Interpreter::recordSettingsLinks(const ObjectBuilder& b) {
    if (const Value* camera = b.get("camera")) settingsLinks_.camera = camera->index;
    if (const Value* lights = b.get("lights")) settingsLinks_.lights = lights->list;
    if (const Value* fog = b.get("fog")) settingsLinks_.fog = fog->index;
    if (const Value* background = b.get("background")) {
        settingsLinks_.background = *background;
        settingsLinks_.backgroundRange = b.where("background");
    }
}

} // namespace crt::lang
