// Object literals (spec §5): attribute checks and the scene description entries they build.
#include "interpreter_impl.hpp"

#include "value_format.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <filesystem>

namespace crt::lang {

namespace fs = std::filesystem;

namespace {

bool equalsIgnoringCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

bool isTextureType(ObjectType type) {
    return type >= ObjectType::Checker && type <= ObjectType::Image;
}

bool isBumpType(ObjectType type) {
    return type == ObjectType::NoiseBump || type == ObjectType::ImageBump;
}

scene::Color toColor(const Value& v) { return {v.v[0], v.v[1], v.v[2], v.v[3]}; }
glm::dvec3 toVec(const Value& v) { return {v.v[0], v.v[1], v.v[2]}; }

} // namespace

/// A short list of attribute slots, kept on the stack.
struct SmallSlots {
    std::array<uint8_t, kMaxAttributes> items;
    uint8_t count = 0;
    void push_back(uint8_t slot) { items[count++] = slot; }
    const uint8_t* begin() const { return items.data(); }
    const uint8_t* end() const { return items.data() + count; }
};

/// Checks the attributes of one object literal and reads them with their defaults.
struct ObjectBuilder {
    ObjectBuilder(Interpreter& interpreter, const ObjectInfo& objectInfo, SourceRange whole,
                  SourceRange type)
        : in(interpreter), info(objectInfo), range(whole), typeRange(type) {}

    Interpreter& in;
    const ObjectInfo& info;
    SourceRange range;     ///< the whole literal
    SourceRange typeRange; ///< its type name
    /// Storage for the given attributes' values; a slot is valid where `given` is set.
    /// Left uninitialised: building an object must not pay for clearing every slot.
    union RawValue {
        Value value;
        RawValue() {}
    };
    std::array<RawValue, kMaxAttributes> values;
    std::array<const Attribute*, kMaxAttributes> given{};
    SmallSlots givenSlots; ///< the slots in `given` that are set

    void evaluate(std::span<const Attribute> attributes) {
        for (const Attribute& a : attributes) {
            Value v = in.eval(a.value);
            if (a.slot < 0) continue; // reported by the resolver
            check(a, v);
            new (&values[static_cast<size_t>(a.slot)].value) Value(v);
            if (!given[static_cast<size_t>(a.slot)]) givenSlots.push_back(static_cast<uint8_t>(a.slot));
            given[static_cast<size_t>(a.slot)] = &a;
        }
        for (size_t i = 0; i < info.attributes.size(); ++i) {
            if (info.attributes[i].required && !given[i]) {
                Diagnostic& d = in.diagnostics_.error(
                    typeRange, fmt::format("{} is missing its required attribute '{}'", info.name,
                                           info.attributes[i].name));
                uint32_t closing = range.end > range.begin ? range.end - 1 : range.end;
                d.fixits.push_back({{range.file, closing, closing},
                                    fmt::format("{} -> {} ", info.attributes[i].name,
                                                placeholder(info.attributes[i].type))});
                throw EvalError{};
            }
        }
    }

    static std::string_view placeholder(AttrType type) {
        switch (type) {
        case AttrType::Vec3: return "vec3(0, 0, 0)";
        case AttrType::Colour: return "rgb(1, 1, 1)";
        case AttrType::String: return "\"\"";
        case AttrType::Int: return "1";
        default: return "1.0";
        }
    }

    [[noreturn]] void wrongType(const Attribute& a, const Value& v, std::string_view wanted) {
        in.fail(a.value->range, fmt::format("attribute '{}' of {} must be {}, not {}", a.name,
                                            info.name, wanted, typeName(v)));
    }

    void finite(const Attribute& a, const Value& v, int components) {
        for (int k = 0; k < components; ++k) {
            double x = components == 1 ? v.asDouble() : v.v[k];
            if (!std::isfinite(x)) {
                in.fail(a.value->range, fmt::format("attribute '{}' of {} is {}; it must be finite",
                                                    a.name, info.name, components == 1 ? formatFloat(x) : in.str(v)));
            }
        }
    }

    void check(const Attribute& a, const Value& v) {
        const AttributeInfo& attr = info.attributes[static_cast<size_t>(a.slot)];
        switch (attr.type) {
        case AttrType::Float:
            if (!v.isNumber()) wrongType(a, v, "a float");
            finite(a, v, 1);
            return;
        case AttrType::Int:
            if (v.kind == ValueKind::Float) {
                Diagnostic& d = in.diagnostics_.error(
                    a.value->range, fmt::format("attribute '{}' of {} must be an int, not float",
                                                a.name, info.name));
                addIntFixIt(d, v, a.value->range);
                throw EvalError{};
            }
            if (v.kind != ValueKind::Int) wrongType(a, v, "an int");
            return;
        case AttrType::Bool:
            if (v.kind != ValueKind::Bool) wrongType(a, v, "a bool");
            return;
        case AttrType::String:
            if (v.kind != ValueKind::String) wrongType(a, v, "a string");
            return;
        case AttrType::Vec3:
            if (v.kind != ValueKind::Vec3) wrongType(a, v, "a vec3");
            finite(a, v, 3);
            return;
        case AttrType::Colour:
            if (v.kind != ValueKind::Colour) wrongType(a, v, "a colour");
            finite(a, v, 4);
            return;
        case AttrType::Choice:
            if (v.kind != ValueKind::String) wrongType(a, v, "a string");
            checkChoice(a, v, attr);
            return;
        case AttrType::Material:
            if (v.kind != ValueKind::Material) wrongType(a, v, "a Material");
            return;
        case AttrType::Camera:
            if (v.kind != ValueKind::Camera) wrongType(a, v, "a Camera");
            return;
        case AttrType::Background:
            if (v.kind != ValueKind::Background && v.kind != ValueKind::Colour) {
                wrongType(a, v, "a Background or a colour");
            }
            if (v.kind == ValueKind::Colour) finite(a, v, 4);
            return;
        case AttrType::LightList:
            if (v.kind != ValueKind::List) wrongType(a, v, "a list of lights");
            for (const Value& item : *v.list) {
                if (item.kind != ValueKind::Light) {
                    in.fail(a.value->range, fmt::format("attribute 'lights' must hold only lights, "
                                                        "not {}", typeName(item)));
                }
            }
            return;
        case AttrType::Texture:
            if (v.kind != ValueKind::Texture || !isTextureType(v.objectType)) {
                wrongType(a, v, "a texture (Checker, Stripes, Noise, Marble, Wood or Image)");
            }
            return;
        case AttrType::Bump:
            if (v.kind != ValueKind::Texture || !isBumpType(v.objectType)) {
                wrongType(a, v, "a bump texture (NoiseBump or ImageBump)");
            }
            return;
        case AttrType::Gamma:
            if (v.kind == ValueKind::String) {
                if (!equalsIgnoringCase(*v.s, "srgb")) {
                    in.fail(a.value->range, fmt::format("gamma must be a number or \"srgb\", not \"{}\"", *v.s));
                }
                return;
            }
            if (!v.isNumber()) wrongType(a, v, "a float or \"srgb\"");
            finite(a, v, 1);
            if (v.asDouble() <= 0) in.fail(a.value->range, "gamma must be positive");
            return;
        case AttrType::Aperture:
            if (v.kind == ValueKind::Int) {
                if (v.i < 3) in.fail(a.value->range, "a polygonal aperture needs at least 3 sides");
                return;
            }
            if (v.kind == ValueKind::Float) {
                Diagnostic& d = in.diagnostics_.error(
                    a.value->range, fmt::format("attribute '{}' of {} must be a shape name or a "
                                                "number of sides, not float",
                                                a.name, info.name));
                addIntFixIt(d, v, a.value->range);
                throw EvalError{};
            }
            if (v.kind != ValueKind::String) wrongType(a, v, "a shape name or a number of sides");
            checkChoice(a, v, attr);
            return;
        }
    }

    void checkChoice(const Attribute& a, const Value& v, const AttributeInfo& attr) {
        for (std::string_view choice : attr.choices) {
            if (equalsIgnoringCase(*v.s, choice)) return;
        }
        std::string list;
        for (std::string_view choice : attr.choices) list += fmt::format("{}\"{}\"", list.empty() ? "" : ", ", choice);
        std::vector<std::string_view> names(attr.choices.begin(), attr.choices.end());
        std::string suggestion = closestMatch(*v.s, names);
        Diagnostic& d = in.diagnostics_.error(
            a.value->range, fmt::format("\"{}\" is not a valid {}; expected one of {}", *v.s, a.name, list));
        if (!suggestion.empty()) {
            d.message += fmt::format("; did you mean \"{}\"?", suggestion);
            d.fixits.push_back({a.value->range, fmt::format("\"{}\"", suggestion)});
        }
        throw EvalError{};
    }

    // --- reading with defaults ---
    /// The slot of attribute `name` if the literal gives it, else -1. Only the given
    /// attributes (usually a few) are compared, shortest test first: building objects
    /// asks for every attribute by name, and most are not given.
    int slot(std::string_view name) const {
        for (uint8_t given : givenSlots) {
            std::string_view candidate = info.attributes[given].name;
            if (candidate.size() == name.size() && candidate[0] == name[0] && candidate == name) return given;
        }
        return -1;
    }
    const Value* get(std::string_view name) const {
        int s = slot(name);
        return s >= 0 ? &values[static_cast<size_t>(s)].value : nullptr;
    }
    SourceRange where(std::string_view name) const {
        int s = slot(name);
        return s >= 0 ? given[static_cast<size_t>(s)]->value->range : typeRange;
    }
    double number(std::string_view name, double fallback) const {
        const Value* v = get(name);
        return v ? v->asDouble() : fallback;
    }
    int64_t integer(std::string_view name, int64_t fallback) const {
        const Value* v = get(name);
        return v ? v->i : fallback;
    }
    bool flag(std::string_view name, bool fallback) const {
        const Value* v = get(name);
        return v ? v->b : fallback;
    }
    glm::dvec3 vec(std::string_view name, glm::dvec3 fallback = glm::dvec3(0.0)) const {
        const Value* v = get(name);
        return v ? toVec(*v) : fallback;
    }
    scene::Color colour(std::string_view name, scene::Color fallback) const {
        const Value* v = get(name);
        return v ? toColor(*v) : fallback;
    }
    std::string text(std::string_view name) const {
        const Value* v = get(name);
        return v && v->kind == ValueKind::String ? *v->s : std::string();
    }
    std::string lowerText(std::string_view name, std::string_view fallback) const {
        std::string t = get(name) ? text(name) : std::string(fallback);
        std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return std::tolower(c); });
        return t;
    }

    /// A radius-like attribute: negative is an error; returns whether it is zero.
    bool nonNegative(std::string_view name) {
        if (number(name, 0) < 0) {
            in.fail(where(name), fmt::format("attribute '{}' of {} is negative ({})", name, info.name,
                                             formatFloat(number(name, 0))));
        }
        return number(name, 0) == 0;
    }
    void nonZeroVector(std::string_view name, std::string_view what) {
        if (get(name) && glm::length(vec(name)) == 0) {
            in.fail(where(name), fmt::format("attribute '{}' of {} is a zero vector; {}", name, info.name, what));
        }
    }
};

fs::path folderOf(const std::string& path) {
    std::error_code error;
    fs::path parent = fs::path(path).parent_path();
    fs::path folder = fs::absolute(parent.empty() ? fs::path(".") : parent, error);
    return folder.lexically_normal();
}

void addIntFixIt(Diagnostic& diagnostic, const Value& given, SourceRange where) {
    if (given.kind != ValueKind::Float || !std::isfinite(given.f) || std::abs(given.f) >= 9e15) return;
    std::string fixed = fmt::format("{}", static_cast<int64_t>(std::llround(given.f)));
    diagnostic.message += fmt::format("; use {}", fixed);
    diagnostic.fixits.push_back({where, fixed});
}

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
    scene_.entities.push_back(std::move(entity));
    entityInfo_.push_back(info);
    return static_cast<int32_t>(scene_.entities.size() - 1);
}

void Interpreter::warnOnce(WarningKind kind, SourceRange where, std::string message) {
    if (warnedOnce_.emplace(kind, where.file, where.begin).second) {
        diagnostics_.warning(kind, where, std::move(message));
    }
}

int32_t Interpreter::defaultMaterial() {
    if (defaultMaterial_ < 0) {
        scene_.materials.emplace_back();
        defaultMaterial_ = static_cast<int32_t>(scene_.materials.size() - 1);
    }
    return defaultMaterial_;
}

namespace {

/// Looks a file up as an image or mesh: "/x" under each asset root, else next to the script.
std::string findAsset(const std::string& name, const std::string& scriptPath,
                      const std::vector<std::string>& assetRoots, std::vector<std::string>& searched) {
    std::error_code error;
    fs::path scriptDir = folderOf(scriptPath);
    if (!name.empty() && name[0] == '/') {
        std::vector<fs::path> roots;
        if (!assetRoots.empty()) {
            for (const std::string& root : assetRoots) roots.push_back(fs::absolute(root, error));
        } else {
            if (!scriptDir.has_filename()) scriptDir = scriptDir.parent_path(); // "/dir/" -> "/dir"
            for (fs::path dir = scriptDir;; dir = dir.parent_path()) {
                roots.push_back(dir);
                if (dir == dir.parent_path()) break;
            }
        }
        for (const fs::path& root : roots) {
            fs::path candidate = root / name.substr(1);
            searched.push_back(root.string());
            if (fs::is_regular_file(candidate, error)) return candidate.lexically_normal().string();
        }
        if (fs::is_regular_file(name, error)) return name;
        return {};
    }
    fs::path candidate = fs::path(name).is_absolute() ? fs::path(name) : scriptDir / name;
    searched.push_back(candidate.parent_path().string());
    return fs::is_regular_file(candidate, error) ? candidate.lexically_normal().string() : std::string();
}

} // namespace

Value Interpreter::evalObject(const ObjectExpr* node) {
    if (node->type == ObjectType::Count) fail(node->typeRange, "unknown object type"); // resolver reported
    const ObjectInfo& info = objectInfo(node->type);
    ObjectBuilder b{*this, info, node->range, node->typeRange};
    b.evaluate(node->attributes);
    auto resolveFile = [&](std::string_view attribute, std::string_view what) {
        std::string name = b.text(attribute);
        if (!options_.checkFiles) return std::string();
        std::vector<std::string> searched;
        std::string found = findAsset(name, compilation_.sources.file(node->range.file).path(),
                                      options_.assetRoots, searched);
        if (found.empty()) {
            std::string folders;
            for (const std::string& dir : searched) folders += "\n  " + dir;
            fail(b.where(attribute), fmt::format("cannot find {} \"{}\"; looked in:{}", what, name, folders));
        }
        return found;
    };

    auto entity = [&](scene::Shape shape, bool zeroSize) {
        int32_t material = b.get("material") ? static_cast<int32_t>(b.get("material")->index) : defaultMaterial();
        int32_t index = addEntity(scene::EntityDesc{std::move(shape), material, info.solid, span(node->range)},
                                  EntityInfo{node->range, node->type, true});
        // An animated script (one reading t or clock) often starts from zero size.
        if (zeroSize && !animated_) {
            warnOnce(WarningKind::ZeroSizeEntity, node->typeRange,
                     fmt::format("this {} has zero size and draws nothing", info.name));
        }
        return Value::object(ValueKind::Entity, node->type, static_cast<uint32_t>(index));
    };

    switch (node->type) {
    case ObjectType::Sphere: {
        bool zero = b.nonNegative("radius");
        return entity(scene::SphereShape{b.vec("center"), b.number("radius", 0)}, zero);
    }
    case ObjectType::Box: {
        glm::dvec3 a = b.vec("cornerA"), c = b.vec("cornerB");
        // Identical corners are a mistake, except in an animation growing a box from a point.
        if (a == c && !animated_) fail(b.where("cornerB"), "the corners of this Box are the same point");
        bool zero = a.x == c.x || a.y == c.y || a.z == c.z;
        return entity(scene::BoxShape{a, c}, zero);
    }
    case ObjectType::Plane:
        b.nonZeroVector("normal", "a plane needs a direction");
        return entity(scene::PlaneShape{b.vec("normal"), b.vec("position")}, false);
    case ObjectType::Cylinder: {
        bool zero = b.nonNegative("radius");
        if (b.vec("base") == b.vec("top")) fail(b.where("top"), "the base and top of this Cylinder are the same point");
        return entity(scene::CylinderShape{b.vec("base"), b.vec("top"), b.number("radius", 0), b.flag("open", false)}, zero);
    }
    case ObjectType::Cone: {
        bool zeroBase = b.nonNegative("baseradius");
        bool zeroTop = b.nonNegative("topradius");
        if (b.vec("base") == b.vec("top")) fail(b.where("top"), "the base and top of this Cone are the same point");
        return entity(scene::ConeShape{b.vec("base"), b.number("baseradius", 0), b.vec("top"),
                                        b.number("topradius", 0), b.flag("open", false)},
                      zeroBase && zeroTop);
    }
    case ObjectType::Torus: {
        bool zeroMajor = b.nonNegative("major");
        bool zeroMinor = b.nonNegative("minor");
        b.nonZeroVector("axis", "a torus needs an axis");
        return entity(scene::TorusShape{b.vec("center"), b.number("major", 0), b.number("minor", 0),
                                         b.vec("axis", {0, 1, 0})},
                      zeroMinor || (zeroMajor && zeroMinor));
    }
    case ObjectType::Disc: {
        bool zero = b.nonNegative("radius");
        b.nonNegative("hole");
        b.nonZeroVector("normal", "a disc needs a direction");
        if (b.number("hole", 0) > b.number("radius", 0)) {
            fail(b.where("hole"), "the hole of this Disc is larger than its radius");
        }
        return entity(scene::DiscShape{b.vec("center"), b.vec("normal"), b.number("radius", 0), b.number("hole", 0)},
                      zero || b.number("hole", 0) == b.number("radius", 0));
    }
    case ObjectType::Quad: {
        bool zero = glm::length(glm::cross(b.vec("edgeA"), b.vec("edgeB"))) == 0;
        return entity(scene::QuadShape{b.vec("corner"), b.vec("edgeA"), b.vec("edgeB")}, zero);
    }
    case ObjectType::Triangle: {
        glm::dvec3 p = b.vec("a"), q = b.vec("b"), r = b.vec("c");
        bool zero = glm::length(glm::cross(q - p, r - p)) == 0;
        return entity(scene::TriangleShape{p, q, r}, zero);
    }
    case ObjectType::Mesh: {
        std::string resolved = resolveFile("file", "mesh");
        return entity(scene::MeshShape{b.text("file"), resolved}, false);
    }
    case ObjectType::Material: {
        scene::FinishDesc f;
        f.reflectivity = b.number("reflectivity", 0);
        f.transparency = b.number("transparency", 0);
        f.ior = b.number("ior", 1);
        f.diffuse = b.number("diffuse", std::max(0.0, 1.0 - f.reflectivity - f.transparency));
        f.specular = b.number("specular", 0);
        f.shininess = b.number("shininess", 3);
        f.metallic = b.flag("metallic", false);
        f.glossiness = b.number("glossiness", 0);
        f.fresnel = b.flag("fresnel", false);
        f.absorption = b.colour("absorption", f.absorption);
        f.emission = b.colour("emission", f.emission);
        f.texture = b.get("texture") ? static_cast<int32_t>(b.get("texture")->index) : -1;
        f.bump = b.get("bump") ? static_cast<int32_t>(b.get("bump")->index) : -1;
        if (f.ior <= 0) fail(b.where("ior"), "the index of refraction must be positive");
        if (f.glossiness < 0 || f.glossiness > 1) fail(b.where("glossiness"), "glossiness must be between 0 and 1");
        scene::MaterialDesc& m = scene_.materials.emplace_back();
        m.color = b.colour("color", m.color);
        m.finish = scene_.internFinish(f);
        m.source = span(node->range);
        return Value::object(ValueKind::Material, node->type, static_cast<uint32_t>(scene_.materials.size() - 1));
    }
    case ObjectType::Camera: {
        scene::CameraDesc c;
        c.position = b.vec("position");
        c.pointing = b.vec("pointing");
        if (c.position == c.pointing) fail(b.where("pointing"), "the camera points at its own position");
        c.fov = b.number("fov", 60);
        if (c.fov <= 0 || c.fov >= 180) fail(b.where("fov"), fmt::format("fov must be in (0, 180) degrees, not {}", formatFloat(c.fov)));
        c.aperture = b.number("aperture", 0);
        if (c.aperture < 0) fail(b.where("aperture"), "aperture must not be negative");
        c.focalDistance = b.number("focaldistance", glm::length(c.pointing - c.position));
        if (c.focalDistance <= 0) fail(b.where("focaldistance"), "focaldistance must be positive");
        if (const Value* shape = b.get("apertureshape")) {
            if (shape->kind == ValueKind::Int) {
                c.apertureShape = scene::ApertureShape::Polygon;
                c.apertureBlades = static_cast<int>(std::min<int64_t>(shape->i, 1000));
            } else {
                std::string name = b.lowerText("apertureshape", "circle");
                static const std::pair<std::string_view, int> polygons[] = {
                    {"triangle", 3}, {"square", 4}, {"pentagon", 5}, {"hexagon", 6}, {"octagon", 8}};
                for (auto [polygon, sides] : polygons) {
                    if (name == polygon) {
                        c.apertureShape = scene::ApertureShape::Polygon;
                        c.apertureBlades = sides;
                    }
                }
                if (name == "gaussian") c.apertureShape = scene::ApertureShape::Gaussian;
                if (name == "line") c.apertureShape = scene::ApertureShape::Line;
            }
        }
        c.up = b.vec("up", {0, 1, 0});
        b.nonZeroVector("up", "the camera needs an up direction");
        c.roll = b.number("roll", 0);
        c.projection = b.lowerText("projection", "pinhole") == "spherical" ? scene::Projection::Spherical
                                                                           : scene::Projection::Pinhole;
        c.source = span(node->range);
        cameras_.push_back(c);
        return Value::object(ValueKind::Camera, node->type, static_cast<uint32_t>(cameras_.size() - 1));
    }
    case ObjectType::PointLight:
    case ObjectType::ParallelLight:
    case ObjectType::SpotLight:
    case ObjectType::AreaLight: {
        scene::LightDesc l;
        l.kind = node->type == ObjectType::PointLight      ? scene::LightKind::Point
                 : node->type == ObjectType::ParallelLight ? scene::LightKind::Parallel
                 : node->type == ObjectType::SpotLight     ? scene::LightKind::Spot
                                                           : scene::LightKind::Area;
        l.origin = node->type == ObjectType::AreaLight ? b.vec("corner") : b.vec("origin");
        l.from = b.vec("from");
        l.pointing = b.vec("pointing");
        l.edgeA = b.vec("edgeA");
        l.edgeB = b.vec("edgeB");
        l.color = b.colour("color", l.color);
        l.falloff = b.number("falloff", 0);
        l.ambient = b.number("ambient", 0);
        l.angle = b.number("angle", 30);
        l.softness = b.number("softness", 0.2);
        if (node->type == ObjectType::ParallelLight && l.from == l.pointing) {
            fail(b.where("pointing"), "a ParallelLight needs 'from' and 'pointing' to differ");
        }
        if (node->type == ObjectType::SpotLight) {
            if (l.origin == l.pointing) fail(b.where("pointing"), "a SpotLight needs 'origin' and 'pointing' to differ");
            if (l.angle <= 0 || l.angle >= 180) fail(b.where("angle"), "a SpotLight's angle must be in (0, 180) degrees");
            if (l.softness < 0 || l.softness > 1) fail(b.where("softness"), "softness must be between 0 and 1");
        }
        if (node->type == ObjectType::AreaLight && glm::length(glm::cross(l.edgeA, l.edgeB)) == 0) {
            fail(b.where("edgeB"), "the edges of this AreaLight are parallel or zero; it has no area");
        }
        l.source = span(node->range);
        lights_.push_back(l);
        lightInfo_.push_back({node->type, node->range, false});
        return Value::object(ValueKind::Light, node->type, static_cast<uint32_t>(lights_.size() - 1));
    }
    case ObjectType::Background: {
        scene::BackgroundDesc bg;
        int modes = (b.get("color") ? 1 : 0) + (b.get("horizon") || b.get("sky") ? 1 : 0) + (b.get("image") ? 1 : 0);
        if (modes > 1) {
            fail(node->typeRange, "a Background takes exactly one of 'color', 'horizon' + 'sky', or 'image'");
        }
        if (modes == 0) fail(node->typeRange, "a Background needs 'color', 'horizon' + 'sky', or 'image'");
        if ((b.get("horizon") != nullptr) != (b.get("sky") != nullptr)) {
            fail(node->typeRange, fmt::format("a gradient Background needs both 'horizon' and 'sky'"));
        }
        if (b.get("angle") && !b.get("image")) fail(b.where("angle"), "'angle' only applies to an 'image' Background");
        if (b.get("color")) {
            bg.kind = scene::BackgroundKind::Solid;
            bg.color = b.colour("color", bg.color);
        } else if (b.get("horizon")) {
            bg.kind = scene::BackgroundKind::Gradient;
            bg.horizon = b.colour("horizon", bg.horizon);
            bg.sky = b.colour("sky", bg.sky);
        } else {
            bg.kind = scene::BackgroundKind::Image;
            bg.image = b.text("image");
            bg.resolvedImage = resolveFile("image", "image");
            bg.angle = b.number("angle", 0);
        }
        bg.source = span(node->range);
        backgrounds_.push_back(std::move(bg));
        return Value::object(ValueKind::Background, node->type, static_cast<uint32_t>(backgrounds_.size() - 1));
    }
    default: break;
    }

    // Textures.
    scene::TextureDesc t;
    t.kind = static_cast<scene::TextureKind>(static_cast<int>(node->type) - static_cast<int>(ObjectType::Checker));
    t.a = b.colour("a", t.a);
    t.b = b.colour("b", t.b);
    t.size = b.number("size", 1);
    if (b.get("size") && t.size <= 0) fail(b.where("size"), "a texture's size must be positive");
    t.axis = b.vec("axis", {1, 0, 0});
    if (b.get("axis")) b.nonZeroVector("axis", "stripes need a direction");
    t.octaves = static_cast<int>(std::clamp<int64_t>(b.integer("octaves", 4), 1, 16));
    if (b.get("octaves") && (b.integer("octaves", 4) < 1 || b.integer("octaves", 4) > 16)) {
        fail(b.where("octaves"), "octaves must be between 1 and 16");
    }
    t.turbulence = b.number("turbulence", node->type == ObjectType::Wood ? 0.1 : 1.0);
    t.rings = b.number("rings", 8);
    t.strength = b.number("strength", 0.5);
    if (node->type == ObjectType::Image || node->type == ObjectType::ImageBump) {
        t.file = b.text("file");
        t.resolvedFile = resolveFile("file", "image");
        std::string mapping = b.lowerText("mapping", "uv");
        static const std::pair<std::string_view, scene::TextureMapping> mappings[] = {
            {"uv", scene::TextureMapping::Uv}, {"planar", scene::TextureMapping::Planar},
            {"spherical", scene::TextureMapping::Spherical}, {"cylindrical", scene::TextureMapping::Cylindrical},
            {"cubic", scene::TextureMapping::Cubic}};
        for (auto [name, kind] : mappings) {
            if (mapping == name) t.mapping = kind;
        }
    }
    t.source = span(node->range);
    scene_.textures.push_back(std::move(t));
    return Value::object(ValueKind::Texture, node->type, static_cast<uint32_t>(scene_.textures.size() - 1));
}

void Interpreter::execSettings(const SettingsStmt* node) {
    if (settings_) {
        Diagnostic& d = diagnostics_.error(node->range.begin + 8 <= node->range.end
                                               ? SourceRange{node->range.file, node->range.begin, node->range.begin + 8}
                                               : node->range,
                                           "a second Settings block; a script has at most one");
        d.notes.push_back({{settings_->range.file, settings_->range.begin, settings_->range.begin + 8},
                           "the first Settings block is here"});
        throw EvalError{};
    }
    settings_ = node;
    SourceRange keyword{node->range.file, node->range.begin, node->range.begin + 8};
    ObjectBuilder b{*this, objectInfo(ObjectType::Settings), node->range, keyword};
    b.evaluate(node->attributes);
    settingsAttributes_ = b.given;
    for (size_t i = 0; i < kMaxAttributes; ++i) {
        if (b.given[i]) settingsValues_[i] = b.values[i].value;
    }
}

} // namespace crt::lang
