// SceneDesc -> JSON, keys in a fixed order so dumps are stable and diffable.
#include "scene/scene_json.hpp"

#include <nlohmann/json.hpp>

namespace crt::scene {

using Json = nlohmann::ordered_json;

namespace {

Json vec(const glm::dvec3& v) { return Json::array({v.x, v.y, v.z}); }
/// A compiled Function: its registers' first values, then one [operation, result register,
/// operand registers…] an instruction.
Json functionJson(const FunctionProgram& f) {
    Json code = Json::array();
    for (const FunctionInstruction& in : f.code) {
        Json step = Json::array({functionOpName(in.op), in.out});
        const uint16_t operands[] = {in.a, in.b, in.c};
        for (int k = 0; k < functionOpArity(in.op); ++k) step.push_back(operands[k]);
        code.push_back(std::move(step));
    }
    return Json{{"parameters", f.parameters}, {"constants", f.constants}, {"code", std::move(code)},
                {"result", f.result}};
}
Json pointList(const std::vector<glm::dvec2>& points) {
    Json out = Json::array();
    for (const glm::dvec2& p : points) out.push_back(Json::array({p.x, p.y}));
    return out;
}
Json color(const Color& c) { return Json::array({c.r, c.g, c.b, c.a}); }
Json source(const SourceSpan& s) {
    return Json{{"file", s.file}, {"line", s.line}, {"column", s.column}, {"endLine", s.endLine}, {"endColumn", s.endColumn}};
}

Json modifiers(const std::vector<Modifier>& mods) {
    Json out = Json::array();
    for (const Modifier& m : mods) {
        if (m.kind == ModifierKind::Matrix) {
            // POV-Ray's twelve numbers: where x, y and z go, then the offset.
            Json numbers = Json::array();
            for (int column = 0; column < 3; ++column)
                for (int row = 0; row < 3; ++row) numbers.push_back(m.linear[column][row]);
            for (int k = 0; k < 3; ++k) numbers.push_back(m.value[k]);
            out.push_back(Json{{"matrix", numbers}});
            continue;
        }
        const char* kind = m.kind == ModifierKind::Translate ? "translate"
                           : m.kind == ModifierKind::Rotate  ? "rotate"
                                                                : "scale";
        out.push_back(Json{{kind, vec(m.value)}});
    }
    return out;
}

struct ShapeJson {
    Json& out;
    const SceneDesc& scene;
    void operator()(const SphereShape& s) {
        out["type"] = "Sphere";
        out["center"] = vec(s.center);
        out["radius"] = s.radius;
    }
    void operator()(const BoxShape& s) {
        out["type"] = "Box";
        out["cornerA"] = vec(s.cornerA);
        out["cornerB"] = vec(s.cornerB);
    }
    void operator()(const PlaneShape& s) {
        out["type"] = "Plane";
        out["normal"] = vec(s.normal);
        out["position"] = vec(s.position);
    }
    void operator()(const CylinderShape& s) {
        out["type"] = "Cylinder";
        out["base"] = vec(s.base);
        out["top"] = vec(s.top);
        out["radius"] = s.radius;
        out["open"] = s.open;
    }
    void operator()(const ConeShape& s) {
        out["type"] = "Cone";
        out["base"] = vec(s.base);
        out["baseRadius"] = s.baseRadius;
        out["top"] = vec(s.top);
        out["topRadius"] = s.topRadius;
        out["open"] = s.open;
    }
    void operator()(const TorusShape& s) {
        out["type"] = "Torus";
        out["center"] = vec(s.center);
        out["major"] = s.major;
        out["minor"] = s.minor;
        out["axis"] = vec(s.axis);
    }
    void operator()(const DiscShape& s) {
        out["type"] = "Disc";
        out["center"] = vec(s.center);
        out["normal"] = vec(s.normal);
        out["radius"] = s.radius;
        out["hole"] = s.hole;
    }
    void operator()(const QuadShape& s) {
        out["type"] = "Quad";
        out["corner"] = vec(s.corner);
        out["edgeA"] = vec(s.edgeA);
        out["edgeB"] = vec(s.edgeB);
    }
    void operator()(const TriangleShape& s) {
        out["type"] = "Triangle";
        out["a"] = vec(s.a);
        out["b"] = vec(s.b);
        out["c"] = vec(s.c);
    }
    void operator()(const PolygonShape& s) {
        out["type"] = "Polygon";
        Json points = Json::array();
        for (const glm::dvec3& p : s.points) points.push_back(vec(p));
        out["points"] = std::move(points);
    }
    void operator()(const SmoothTriangleShape& s) {
        out["type"] = "SmoothTriangle";
        const MeshData empty{{glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0)},
                             {glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0)},
                             {},
                             {}};
        const MeshData& m = s.mesh ? *s.mesh : empty;
        const char* corners[] = {"a", "b", "c"};
        const char* normals[] = {"na", "nb", "nc"};
        for (int i = 0; i < 3; ++i) out[corners[i]] = vec(m.positions[i]);
        for (int i = 0; i < 3; ++i) out[normals[i]] = vec(m.normals[i]);
    }
    void operator()(const SuperellipsoidShape& s) {
        out["type"] = "Superellipsoid";
        out["e"] = s.e;
        out["n"] = s.n;
    }
    void operator()(const PrismShape& s) {
        out["type"] = "Prism";
        out["points"] = pointList(s.points);
        out["from"] = s.from;
        out["to"] = s.to;
        out["spline"] = kSplineKindNames[static_cast<int>(s.spline)];
        out["sweep"] = s.conic ? "conic" : "linear";
        out["open"] = s.open;
    }
    void operator()(const SorShape& s) {
        out["type"] = "Sor";
        out["points"] = pointList(s.points);
        out["open"] = s.open;
    }
    void operator()(const LatheShape& s) {
        out["type"] = "Lathe";
        out["points"] = pointList(s.points);
        out["spline"] = kSplineKindNames[static_cast<int>(s.spline)];
    }
    void operator()(const SphereSweepShape& s) {
        out["type"] = "SphereSweep";
        Json points = Json::array();
        for (const glm::dvec3& p : s.points) points.push_back(vec(p));
        out["points"] = points;
        out["radii"] = s.radii;
        out["spline"] = kSplineKindNames[static_cast<int>(s.spline)];
    }
    void operator()(const TextShape& s) {
        out["type"] = "Text";
        out["text"] = s.desc->text;
        out["font"] = s.desc->font;
        out["resolvedFont"] = s.desc->resolvedFont;
        out["thickness"] = s.desc->thickness;
        out["spacing"] = s.desc->spacing;
    }
    void operator()(const BlobShape& s) {
        out["type"] = "Blob";
        out["threshold"] = s.desc->threshold;
        Json components = Json::array();
        for (const BlobComponent& c : s.desc->components) {
            Json j;
            if (c.cylinder) {
                j["type"] = "BlobCylinder";
                j["base"] = vec(c.a);
                j["top"] = vec(c.b);
            } else {
                j["type"] = "BlobSphere";
                j["center"] = vec(c.a);
            }
            j["radius"] = c.radius;
            j["strength"] = c.strength;
            components.push_back(std::move(j));
        }
        out["components"] = std::move(components);
    }
    void operator()(const IsosurfaceShape& s) {
        out["type"] = "Isosurface";
        out["function"] = functionJson(*s.desc->function);
        out["boundsMin"] = vec(s.desc->boundsMin);
        out["boundsMax"] = vec(s.desc->boundsMax);
        out["threshold"] = s.desc->threshold;
        out["maxgradient"] = s.desc->maxGradient;
        out["accuracy"] = s.desc->accuracy;
        out["open"] = s.desc->open;
    }
    void operator()(const HeightFieldShape& s) {
        out["type"] = "HeightField";
        if (s.desc->function) {
            out["function"] = functionJson(*s.desc->function);
            out["resolution"] = s.desc->resolution;
        } else {
            out["image"] = s.desc->image;
            out["resolvedImage"] = s.desc->resolvedImage;
        }
        out["smooth"] = s.desc->smooth;
    }
    void operator()(const MeshShape& s) {
        out["type"] = "Mesh";
        if (s.written >= 0) {
            writtenMesh(*scene.writtenMeshes[static_cast<size_t>(s.written)]);
            return;
        }
        out["file"] = s.file;
        out["resolvedFile"] = s.resolvedFile;
    }
    void writtenMesh(const MeshData& m) {
        Json vertices = Json::array(), faces = Json::array();
        for (const glm::dvec3& p : m.positions) vertices.push_back(vec(p));
        for (const MeshData::Triangle& t : m.triangles) faces.push_back({t.v[0], t.v[1], t.v[2]});
        out["vertices"] = std::move(vertices);
        out["faces"] = std::move(faces);
        Json normals = Json::array(), uvs = Json::array();
        for (const glm::dvec3& n : m.normals) normals.push_back(vec(n));
        for (const glm::dvec2& uv : m.uvs) uvs.push_back({uv.x, uv.y});
        out["normals"] = std::move(normals);
        out["uvs"] = std::move(uvs);
    }
    void operator()(const CsgNode& s) {
        out["type"] = csgOpName(s.op);
        out["left"] = s.left;
        out["right"] = s.right;
    }
    void operator()(const TransformNode& s) {
        out["type"] = "Transform";
        out["child"] = s.child;
        out["modifiers"] = modifiers(s.modifiers);
    }
    void operator()(const GroupNode& s) {
        out["type"] = "Group";
        out["members"] = s.members;
    }
    void operator()(const InverseNode& s) {
        out["type"] = "Inverse";
        out["child"] = s.child;
    }
};

const char* lightKind(LightKind kind) {
    switch (kind) {
    case LightKind::Point: return "PointLight";
    case LightKind::Parallel: return "ParallelLight";
    case LightKind::Spot: return "SpotLight";
    case LightKind::Area: return "AreaLight";
    case LightKind::Cylinder: return "CylinderLight";
    case LightKind::Sphere: return "SphereLight";
    }
    return "?";
}

const char* textureKind(TextureKind kind) {
    static const char* names[] = {
        "Checker",   "Stripes",  "Noise",     "Marble",      "Wood",     "Image",   "NoiseBump",
        "ImageBump", "Gradient", "Onion",     "Leopard",     "Radial",   "Spiral",  "Brick",
        "Hexagon",   "Boxed",    "Spherical", "Cylindrical", "Planar",   "Quilted", "Mandel",
        "Bozo",      "Spotted",  "Granite",   "Agate",       "Wrinkles", "Dents",   "Crackle",
        "Cells",     "Slope",    "Bump",      "Ripples",     "Waves",    "FunctionPattern"};
    static_assert(std::size(names) == static_cast<size_t>(TextureKind::FunctionPattern) + 1);
    return names[static_cast<int>(kind)];
}

/// Where the array opening at `open` closes, when it holds only numbers and arrays of
/// numbers; npos otherwise.
size_t closeOfNumberArray(const std::string& json, size_t open) {
    int depth = 0;
    for (size_t k = open; k < json.size(); ++k) {
        char c = json[k];
        if (c == '{' || c == '"') return std::string::npos;
        if (c == '[' && ++depth > 2) return std::string::npos;
        if (c == ']' && --depth == 0) return k;
    }
    return std::string::npos;
}

/// Writes arrays of numbers, and arrays of them, on one line ("[0.0, 1.0, 0.0]", a colour
/// map's "[0.5, [1.0, 0.0, 0.0, 1.0]]"): vectors, colours and stops are read as units, and
/// the dump stays a third as long.
std::string compactNumberArrays(const std::string& json) {
    std::string out;
    out.reserve(json.size());
    for (size_t i = 0; i < json.size(); ++i) {
        size_t close = json[i] == '[' ? closeOfNumberArray(json, i) : std::string::npos;
        if (close != std::string::npos) {
            std::string items;
            bool number = false;
            for (size_t k = i; k <= close; ++k) {
                char c = json[k];
                if (c == ' ' || c == '\n') continue;
                if (c == ',')
                    items += ", ";
                else
                    items += c, number = number || (c != '[' && c != ']');
            }
            if (number) {
                out += items;
                i = close;
                continue;
            }
        }
        out += json[i];
    }
    return out;
}

Json settingsJson(const SettingsDesc& s) {
    Json json{{"title", s.title}, {"author", s.author}, {"date", s.date}, {"notes", s.notes},
                {"width", s.width}, {"height", s.height},
                {"gamma", s.srgb ? Json("srgb") : Json(s.gamma)},
                {"supersampling", s.supersampling}, {"dofsamples", s.dofSamples},
                {"recursiondepth", s.recursionDepth}, {"antialias", kAntialiasNames[static_cast<int>(s.antialias)]},
                {"aathreshold", s.aaThreshold}, {"aadepth", s.aaDepth},
                {"shadowsamples", s.shadowSamples}, {"glossysamples", s.glossySamples},
                {"seed", s.seed}, {"ambient", color(s.ambient)}};
    // Only when set apart from recursiondepth, so dumps of scenes without them are unchanged.
    if (s.reflectionDepth >= 0) json["reflectiondepth"] = s.reflectionDepth;
    if (s.refractionDepth >= 0) json["refractiondepth"] = s.refractionDepth;
    // The path integrator's, likewise: all three when it is chosen, else those set apart
    // from their defaults.
    const SettingsDesc defaults;
    const bool path = s.integrator != defaults.integrator;
    if (path) json["integrator"] = kIntegratorNames[static_cast<int>(s.integrator)];
    if (path || s.samples != defaults.samples) json["samples"] = s.samples;
    if (path || s.bounces != defaults.bounces) json["bounces"] = s.bounces;
    if (s.targetError > 0) json["targeterror"] = s.targetError;
    if (s.shutterOpen != defaults.shutterOpen || s.shutterClose != defaults.shutterClose ||
        s.motionSteps != defaults.motionSteps) {
        json["shutteropen"] = s.shutterOpen;
        json["shutterclose"] = s.shutterClose;
        json["motionsteps"] = s.motionSteps;
    }
    return json;
}

Json cameraJson(const CameraDesc& c) {
    static const char* apertures[] = {"circle", "polygon", "gaussian", "line"};
    Json camera{{"position", vec(c.position)}, {"pointing", vec(c.pointing)}, {"fov", c.fov},
                {"aperture", c.aperture}, {"focaldistance", c.focalDistance},
                {"apertureshape", apertures[static_cast<int>(c.apertureShape)]},
                {"apertureblades", c.apertureBlades}, {"up", vec(c.up)}, {"roll", c.roll},
                {"projection", kProjectionNames[static_cast<int>(c.projection)]},
                {"source", source(c.source)}};
    if (c.width > 0) camera["width"] = c.width;
    return camera;
}

Json motionJson(const MotionDesc& m) {
    Json transforms = Json::array();
    for (const auto& [entity, steps] : m.transforms) {
        Json modifierSteps = Json::array();
        for (const std::vector<Modifier>& step : steps) modifierSteps.push_back(modifiers(step));
        transforms.push_back(Json{{"entity", entity}, {"modifiers", std::move(modifierSteps)}});
    }
    Json cameras = Json::array();
    for (const CameraDesc& c : m.cameras) cameras.push_back(cameraJson(c));
    return Json{{"transforms", std::move(transforms)}, {"cameras", std::move(cameras)}};
}

Json lightJson(const LightDesc& l) {
    Json light{{"type", lightKind(l.kind)}};
    switch (l.kind) {
    case LightKind::Point: light["origin"] = vec(l.origin); break;
    case LightKind::Parallel:
        light["from"] = vec(l.from);
        light["pointing"] = vec(l.pointing);
        break;
    case LightKind::Spot:
        light["origin"] = vec(l.origin);
        light["pointing"] = vec(l.pointing);
        light["angle"] = l.angle;
        light["softness"] = l.softness;
        if (l.tightness != 0) light["tightness"] = l.tightness;
        break;
    case LightKind::Area:
        light["corner"] = vec(l.origin);
        light["edgeA"] = vec(l.edgeA);
        light["edgeB"] = vec(l.edgeB);
        break;
    case LightKind::Cylinder:
        light["from"] = vec(l.from);
        light["to"] = vec(l.to);
        if (l.radius != 0) light["radius"] = l.radius;
        break;
    case LightKind::Sphere:
        light["center"] = vec(l.origin);
        light["radius"] = l.radius;
        break;
    }
    light["color"] = color(l.color);
    if (l.kind != LightKind::Parallel) light["falloff"] = l.falloff;
    // Only when given, so dumps of scenes without it are unchanged.
    if (l.attenuation != glm::dvec3(1, 0, 0)) light["attenuation"] = vec(l.attenuation);
    light["ambient"] = l.ambient;
    if (l.shadowless) light["shadowless"] = true;
    if (l.circular) light["circular"] = true;
    if (l.orient) light["orient"] = true;
    if (l.visible) light["visible"] = true;
    light["source"] = source(l.source);
    return light;
}

Json textureJson(const TextureDesc& x);

Json backgroundJson(const BackgroundDesc& b) {
    switch (b.kind) {
    case BackgroundKind::Solid: return Json{{"type", "solid"}, {"color", color(b.color)}};
    case BackgroundKind::Gradient:
        return Json{{"type", "gradient"}, {"horizon", color(b.horizon)}, {"sky", color(b.sky)}};
    case BackgroundKind::Image:
        return Json{{"type", "image"}, {"image", b.image}, {"resolvedImage", b.resolvedImage}, {"angle", b.angle}};
    case BackgroundKind::Pattern: {
        Json layers = Json::array();
        for (const TextureDesc& t : b.layers) layers.push_back(textureJson(t));
        return Json{{"type", "pattern"}, {"layers", std::move(layers)}};
    }
    }
    return Json();
}

Json fogJson(const FogDesc& f) {
    return Json{{"color", color(f.color)}, {"distance", f.distance}, {"filter", f.filter},
                {"falloff", f.falloff}, {"altitude", f.altitude}, {"up", vec(f.up)},
                {"turbulence", vec(f.turbulence)}, {"turbulencedepth", f.turbulenceDepth},
                {"source", source(f.source)}};
}

Json materialJson(const MaterialDesc& material, const FinishDesc& m) {
    Json json{{"color", color(material.color)},
                {"reflectivity", m.reflectivity},
                {"reflectivitymin", m.reflectivityMin < 0 ? m.reflectivity : m.reflectivityMin},
                {"reflectionfalloff", m.reflectionFalloff},
                {"transparency", m.transparency},
                {"ior", m.ior},
                {"diffuse", m.diffuse},
                {"brilliance", m.brilliance},
                {"conserveenergy", m.conserveEnergy},
                {"specular", m.specular},
                {"shininess", m.shininess},
                {"metallic", m.metallic},
                {"glossiness", m.glossiness},
                {"fresnel", m.fresnel},
                {"absorption", color(m.absorption)},
                {"emission", color(m.emission)},
                {"filter", m.filter},
                {"texture", m.texture},
                {"bump", m.bump},
                {"blend", m.blend}};
    // Only when it has one, so dumps of scenes without media are unchanged.
    if (m.medium >= 0) json["medium"] = m.medium;
    json["source"] = source(material.source);
    return json;
}

Json mediumJson(const MediumDesc& m) {
    Json json{{"absorption", color(m.absorption)}, {"scattering", color(m.scattering)},
              {"emission", color(m.emission)}, {"density", m.density}};
    if (!m.densityPattern.empty()) json["densitypattern"] = textureJson(m.densityPattern.front());
    json["phase"] = kPhaseNames[static_cast<size_t>(m.phase)];
    json["g"] = m.g;
    json["samples"] = m.samples;
    json["source"] = source(m.source);
    return json;
}

Json blendJson(const BlendDesc& b) {
    if (b.kind == BlendKind::Layers) return Json{{"type", "layered"}, {"materials", b.materials}};
    Json entries = Json::array();
    for (size_t i = 0; i < b.values.size(); ++i)
        entries.push_back(Json{b.values[i], b.materials[i]});
    return Json{{"type", "materialmap"}, {"pattern", b.pattern}, {"materials", entries}};
}

/// A pattern's keys, in the order of its attributes in docs/scene-json.md.
void patternJson(const TextureDesc& x, Json& texture) {
    using K = TextureKind;
    Json stops = Json::array();
    for (const ColorStop& stop : x.colors)
        stops.push_back(Json::array({stop.value, color(stop.color)}));
    texture["colors"] = stops;
    bool from2015 = x.kind <= K::Wood;
    if (from2015) texture["size"] = x.size;
    if (x.kind == K::Stripes || x.kind == K::Gradient) texture["axis"] = vec(x.axis);
    if (x.kind == K::Spiral) texture["arms"] = x.arms;
    if (x.kind == K::Brick) {
        texture["bricksize"] = vec(x.brickSize);
        texture["mortar"] = x.mortar;
    }
    if (x.kind == K::Quilted) {
        texture["control0"] = x.control0;
        texture["control1"] = x.control1;
    }
    if (x.kind == K::Mandel) texture["iterations"] = x.iterations;
    if (x.kind == K::FunctionPattern) texture["function"] = functionJson(*x.function);
    if (x.kind == K::Crackle) {
        texture["metric"] = x.metric;
        texture["form"] = vec(x.form);
    }
    if (x.kind == K::Slope) texture["direction"] = vec(x.axis);
    if (x.kind == K::Wood) texture["rings"] = x.rings;
    if (x.kind != K::Wood) texture["octaves"] = x.octaves;
    if (hasOwnTurbulence(x.kind)) {
        texture["turbulence"] = x.turbulence;
    } else {
        texture["turbulence"] = vec(x.displacement);
        texture["omega"] = x.omega;
        texture["lambda"] = x.lambda;
    }
    if (!isDiscretePattern(x.kind)) {
        texture["frequency"] = x.frequency;
        texture["phase"] = x.phase;
        texture["waveform"] = kWaveformNames[static_cast<int>(x.waveform)];
        texture["exponent"] = x.exponent;
    }
}

Json textureJson(const TextureDesc& x) {
    static const char* mappings[] = {"uv", "planar", "spherical", "cylindrical", "cubic"};
    Json texture{{"type", textureKind(x.kind)}};
    switch (x.kind) {
    case TextureKind::Image:
    case TextureKind::ImageBump:
        texture["file"] = x.file;
        texture["resolvedFile"] = x.resolvedFile;
        texture["mapping"] = mappings[static_cast<int>(x.mapping)];
        if (x.kind == TextureKind::ImageBump) texture["strength"] = x.strength;
        break;
    case TextureKind::Bump:
        texture["pattern"] = textureJson(x.pattern.front());
        texture["strength"] = x.strength;
        break;
    case TextureKind::NoiseBump:
        texture["size"] = x.size;
        texture["strength"] = x.strength;
        texture["octaves"] = x.octaves;
        break;
    default: patternJson(x, texture); break;
    }
    texture["modifiers"] = modifiers(x.modifiers);
    texture["source"] = source(x.source);
    return texture;
}

Json entityJson(const EntityDesc& e, size_t id, const SceneDesc& scene) {
    Json entity{{"id", id}};
    std::visit(ShapeJson{entity, scene}, e.shape);
    if (e.material >= 0) entity["material"] = e.material;
    entity["solid"] = e.solid;
    // Only when hidden, so dumps of scenes without it are unchanged.
    if (e.hidden & kHiddenFromCamera) entity["camera"] = false;
    if (e.hidden & kHiddenFromShadows) entity["shadow"] = false;
    if (e.hidden & kHiddenFromReflections) entity["reflected"] = false;
    entity["source"] = source(e.source);
    return entity;
}

} // namespace

std::string entityToJson(const SceneDesc& scene, size_t id) {
    return entityJson(scene.entities[id], id, scene).dump(-1, ' ', false, Json::error_handler_t::replace);
}

std::string sceneToJson(const SceneDesc& scene, int indent) {
    Json root;
    root["schema"] = SceneDesc::kSchemaVersion;
    root["files"] = scene.files;
    root["time"] = scene.time;
    root["frame"] = scene.frame;
    root["frameCount"] = scene.frameCount;
    root["settings"] = settingsJson(scene.settings);
    root["camera"] = cameraJson(scene.camera);
    Json& lights = root["lights"] = Json::array();
    for (const LightDesc& l : scene.lights) lights.push_back(lightJson(l));
    root["background"] = backgroundJson(scene.background);
    if (scene.fog) root["fog"] = fogJson(*scene.fog);
    if (!scene.motion.empty()) root["motion"] = motionJson(scene.motion);
    Json& materials = root["materials"] = Json::array();
    for (const MaterialDesc& m : scene.materials) materials.push_back(materialJson(m, scene.finishOf(m)));
    Json& textures = root["textures"] = Json::array();
    for (const TextureDesc& t : scene.textures) textures.push_back(textureJson(t));
    if (!scene.media.empty()) {
        Json& media = root["media"] = Json::array();
        for (const MediumDesc& m : scene.media) media.push_back(mediumJson(m));
    }
    Json& blends = root["blends"] = Json::array();
    for (const BlendDesc& b : scene.blends) blends.push_back(blendJson(b));
    Json& entities = root["entities"] = Json::array();
    for (size_t i = 0; i < scene.entities.size(); ++i) entities.push_back(entityJson(scene.entities[i], i, scene));
    root["drawn"] = scene.drawn;
    // JSON holds only UTF-8, and a script's strings (titles, file names) may hold any bytes.
    return compactNumberArrays(root.dump(indent, ' ', false, Json::error_handler_t::replace)) + "\n";
}

} // namespace crt::scene
