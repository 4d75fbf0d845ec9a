// SceneDesc -> JSON, keys in a fixed order so dumps are stable and diffable.
#include "scene_json.hpp"

#include <nlohmann/json.hpp>

namespace crt::lang {

using Json = nlohmann::ordered_json;
namespace t = tracer;

namespace {

Json vec(const glm::dvec3& v) { return Json::array({v.x, v.y, v.z}); }
Json colour(const t::Color& c) { return Json::array({c.r, c.g, c.b, c.a}); }
Json source(const t::SourceSpan& s) {
    return Json{{"file", s.file}, {"line", s.line}, {"column", s.column}, {"endLine", s.endLine}, {"endColumn", s.endColumn}};
}

Json modifiers(const std::vector<t::Modifier>& mods) {
    Json out = Json::array();
    for (const t::Modifier& m : mods) {
        const char* kind = m.kind == t::ModifierKind::Translate ? "translate"
                           : m.kind == t::ModifierKind::Rotate  ? "rotate"
                                                                : "scale";
        out.push_back(Json{{kind, vec(m.value)}});
    }
    return out;
}

struct ShapeJson {
    Json& out;
    void operator()(const t::SphereShape& s) {
        out["type"] = "Sphere";
        out["center"] = vec(s.center);
        out["radius"] = s.radius;
    }
    void operator()(const t::BoxShape& s) {
        out["type"] = "Box";
        out["cornerA"] = vec(s.cornerA);
        out["cornerB"] = vec(s.cornerB);
    }
    void operator()(const t::PlaneShape& s) {
        out["type"] = "Plane";
        out["normal"] = vec(s.normal);
        out["position"] = vec(s.position);
    }
    void operator()(const t::CylinderShape& s) {
        out["type"] = "Cylinder";
        out["base"] = vec(s.base);
        out["top"] = vec(s.top);
        out["radius"] = s.radius;
        out["open"] = s.open;
    }
    void operator()(const t::ConeShape& s) {
        out["type"] = "Cone";
        out["base"] = vec(s.base);
        out["baseRadius"] = s.baseRadius;
        out["top"] = vec(s.top);
        out["topRadius"] = s.topRadius;
        out["open"] = s.open;
    }
    void operator()(const t::TorusShape& s) {
        out["type"] = "Torus";
        out["center"] = vec(s.center);
        out["major"] = s.major;
        out["minor"] = s.minor;
        out["axis"] = vec(s.axis);
    }
    void operator()(const t::DiscShape& s) {
        out["type"] = "Disc";
        out["center"] = vec(s.center);
        out["normal"] = vec(s.normal);
        out["radius"] = s.radius;
        out["hole"] = s.hole;
    }
    void operator()(const t::QuadShape& s) {
        out["type"] = "Quad";
        out["corner"] = vec(s.corner);
        out["edgeA"] = vec(s.edgeA);
        out["edgeB"] = vec(s.edgeB);
    }
    void operator()(const t::TriangleShape& s) {
        out["type"] = "Triangle";
        out["a"] = vec(s.a);
        out["b"] = vec(s.b);
        out["c"] = vec(s.c);
    }
    void operator()(const t::MeshShape& s) {
        out["type"] = "Mesh";
        out["file"] = s.file;
        out["resolvedFile"] = s.resolvedFile;
    }
    void operator()(const t::CsgNode& s) {
        out["type"] = s.op == t::CsgOp::Union ? "Union" : s.op == t::CsgOp::Difference ? "Difference" : "Intersection";
        out["left"] = s.left;
        out["right"] = s.right;
    }
    void operator()(const t::TransformNode& s) {
        out["type"] = "Transform";
        out["child"] = s.child;
        out["modifiers"] = modifiers(s.modifiers);
    }
    void operator()(const t::GroupNode& s) {
        out["type"] = "Group";
        out["members"] = s.members;
    }
};

const char* lightKind(t::LightKind kind) {
    switch (kind) {
    case t::LightKind::Point: return "PointLight";
    case t::LightKind::Parallel: return "ParallelLight";
    case t::LightKind::Spot: return "SpotLight";
    case t::LightKind::Area: return "AreaLight";
    }
    return "?";
}

const char* textureKind(t::TextureKind kind) {
    static const char* names[] = {"Checker", "Stripes", "Noise", "Marble", "Wood", "Image", "NoiseBump", "ImageBump"};
    return names[static_cast<int>(kind)];
}

/// Writes arrays of numbers on one line ("[0.0, 1.0, 0.0]"): vectors and colours are
/// read as units, and the dump stays a third as long.
std::string compactNumberArrays(const std::string& json) {
    std::string out;
    out.reserve(json.size());
    for (size_t i = 0; i < json.size(); ++i) {
        if (json[i] == '[') {
            size_t close = json.find_first_of("[]{}\"", i + 1);
            if (close != std::string::npos && json[close] == ']') {
                std::string items;
                bool number = false;
                for (size_t k = i + 1; k < close; ++k) {
                    char c = json[k];
                    if (c == ' ' || c == '\n') continue;
                    if (c == ',') items += ", ";
                    else items += c, number = true;
                }
                if (number) {
                    out += '[' + items + ']';
                    i = close;
                    continue;
                }
            }
        }
        out += json[i];
    }
    return out;
}

} // namespace

std::string sceneToJson(const t::SceneDesc& scene, int indent) {
    Json root;
    root["schema"] = t::SceneDesc::kSchemaVersion;
    root["files"] = scene.files;
    root["time"] = scene.time;
    root["frame"] = scene.frame;
    root["frameCount"] = scene.frameCount;

    const t::SettingsDesc& s = scene.settings;
    static const char* antialias[] = {"grid", "adaptive", "showadaptive"};
    root["settings"] = Json{{"title", s.title}, {"author", s.author}, {"date", s.date}, {"notes", s.notes},
                            {"width", s.width}, {"height", s.height},
                            {"gamma", s.srgb ? Json("srgb") : Json(s.gamma)},
                            {"supersampling", s.supersampling}, {"dofsamples", s.dofSamples},
                            {"recursiondepth", s.recursionDepth}, {"antialias", antialias[static_cast<int>(s.antialias)]},
                            {"aathreshold", s.aaThreshold}, {"aadepth", s.aaDepth},
                            {"shadowsamples", s.shadowSamples}, {"glossysamples", s.glossySamples},
                            {"seed", s.seed}, {"ambient", colour(s.ambient)}};

    const t::CameraDesc& c = scene.camera;
    static const char* apertures[] = {"circle", "polygon", "gaussian", "line"};
    root["camera"] = Json{{"position", vec(c.position)}, {"pointing", vec(c.pointing)}, {"fov", c.fov},
                          {"aperture", c.aperture}, {"focaldistance", c.focalDistance},
                          {"apertureshape", apertures[static_cast<int>(c.apertureShape)]},
                          {"apertureblades", c.apertureBlades}, {"up", vec(c.up)}, {"roll", c.roll},
                          {"projection", c.projection == t::Projection::Pinhole ? "pinhole" : "spherical"},
                          {"source", source(c.source)}};

    Json lights = Json::array();
    for (const t::LightDesc& l : scene.lights) {
        Json light{{"type", lightKind(l.kind)}};
        switch (l.kind) {
        case t::LightKind::Point: light["origin"] = vec(l.origin); break;
        case t::LightKind::Parallel:
            light["from"] = vec(l.from);
            light["pointing"] = vec(l.pointing);
            break;
        case t::LightKind::Spot:
            light["origin"] = vec(l.origin);
            light["pointing"] = vec(l.pointing);
            light["angle"] = l.angle;
            light["softness"] = l.softness;
            break;
        case t::LightKind::Area:
            light["corner"] = vec(l.origin);
            light["edgeA"] = vec(l.edgeA);
            light["edgeB"] = vec(l.edgeB);
            break;
        }
        light["color"] = colour(l.color);
        if (l.kind != t::LightKind::Parallel) light["falloff"] = l.falloff;
        light["ambient"] = l.ambient;
        light["source"] = source(l.source);
        lights.push_back(std::move(light));
    }
    root["lights"] = std::move(lights);

    const t::BackgroundDesc& b = scene.background;
    Json background;
    switch (b.kind) {
    case t::BackgroundKind::Solid: background = Json{{"type", "solid"}, {"color", colour(b.color)}}; break;
    case t::BackgroundKind::Gradient:
        background = Json{{"type", "gradient"}, {"horizon", colour(b.horizon)}, {"sky", colour(b.sky)}};
        break;
    case t::BackgroundKind::Image:
        background = Json{{"type", "image"}, {"image", b.image}, {"resolvedImage", b.resolvedImage}, {"angle", b.angle}};
        break;
    }
    root["background"] = std::move(background);

    Json materials = Json::array();
    for (const t::MaterialDesc& material : scene.materials) {
        const t::FinishDesc& m = scene.finishOf(material);
        materials.push_back(Json{{"color", colour(material.color)}, {"reflectivity", m.reflectivity},
                                 {"transparency", m.transparency}, {"ior", m.ior}, {"diffuse", m.diffuse},
                                 {"specular", m.specular}, {"shininess", m.shininess}, {"metallic", m.metallic},
                                 {"glossiness", m.glossiness}, {"fresnel", m.fresnel},
                                 {"absorption", colour(m.absorption)}, {"emission", colour(m.emission)},
                                 {"texture", m.texture}, {"bump", m.bump}, {"source", source(material.source)}});
    }
    root["materials"] = std::move(materials);

    Json textures = Json::array();
    static const char* mappings[] = {"uv", "planar", "spherical", "cylindrical", "cubic"};
    for (const t::TextureDesc& x : scene.textures) {
        Json texture{{"type", textureKind(x.kind)}};
        switch (x.kind) {
        case t::TextureKind::Image:
        case t::TextureKind::ImageBump:
            texture["file"] = x.file;
            texture["resolvedFile"] = x.resolvedFile;
            texture["mapping"] = mappings[static_cast<int>(x.mapping)];
            if (x.kind == t::TextureKind::ImageBump) texture["strength"] = x.strength;
            break;
        case t::TextureKind::NoiseBump:
            texture["size"] = x.size;
            texture["strength"] = x.strength;
            texture["octaves"] = x.octaves;
            break;
        default:
            texture["a"] = colour(x.a);
            texture["b"] = colour(x.b);
            texture["size"] = x.size;
            if (x.kind == t::TextureKind::Stripes) texture["axis"] = vec(x.axis);
            if (x.kind == t::TextureKind::Noise || x.kind == t::TextureKind::Marble) texture["octaves"] = x.octaves;
            if (x.kind == t::TextureKind::Marble || x.kind == t::TextureKind::Wood) texture["turbulence"] = x.turbulence;
            if (x.kind == t::TextureKind::Wood) texture["rings"] = x.rings;
            break;
        }
        texture["modifiers"] = modifiers(x.modifiers);
        texture["source"] = source(x.source);
        textures.push_back(std::move(texture));
    }
    root["textures"] = std::move(textures);

    Json entities = Json::array();
    for (size_t i = 0; i < scene.entities.size(); ++i) {
        const t::EntityDesc& e = scene.entities[i];
        Json entity{{"id", i}};
        std::visit(ShapeJson{entity}, e.shape);
        if (e.material >= 0) entity["material"] = e.material;
        entity["solid"] = e.solid;
        entity["source"] = source(e.source);
        entities.push_back(std::move(entity));
    }
    root["entities"] = std::move(entities);
    root["drawn"] = scene.drawn;
    return compactNumberArrays(root.dump(indent)) + "\n";
}

} // namespace crt::lang
