// Attribute defaults have one source, the scene description's structs; the schema documents
// them for hover, completion and the docs. These tests keep the two from drifting apart:
// through the interpreter, an object built without an attribute must describe the same scene
// as one given the attribute's documented default, written out in the script.
#include <catch2/catch.hpp>

#include "interpreter.hpp"
#include "object_schema.hpp"
#include "scene/scene_json.hpp"

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <charconv>
#include <string>
#include <string_view>
#include <utility>

using namespace crt::lang;
using Json = nlohmann::json;

namespace {

/// A script using one object of each type, with its required attributes; '@' is where the
/// attribute under test goes. The object is linked into the scene (drawn, listed in
/// Settings, a material or texture of something drawn), since unused ones are dropped.
struct Usage {
    ObjectType type;
    std::string_view script;
};

#define CRT_SPHERE_WITH(material)                                                                  \
    "Scene { Sphere { center -> vec3(0, 0, 0) radius -> 1 material -> " material " } }"

constexpr Usage kUsages[] = {
    {ObjectType::Settings, "Settings { @ }"},
    {ObjectType::Camera,
     "Settings { camera -> Camera { position -> vec3(1, 2, -5) pointing -> vec3(0, 1, 0) @ } }"},
    {ObjectType::PointLight,
     "Settings { lights -> [PointLight { origin -> vec3(0, 5, 0) color -> rgb(1, 1, 1) @ }] }"},
    {ObjectType::ParallelLight, "Settings { lights -> [ParallelLight { from -> vec3(0, 5, 0) "
                                "pointing -> vec3(0, 0, 0) color -> rgb(1, 1, 1) @ }] }"},
    {ObjectType::SpotLight, "Settings { lights -> [SpotLight { origin -> vec3(0, 5, 0) pointing -> "
                            "vec3(0, 0, 0) color -> rgb(1, 1, 1) @ }] }"},
    {ObjectType::AreaLight,
     "Settings { lights -> [AreaLight { corner -> vec3(0, 5, 0) edgeA -> vec3(1, 0, 0) "
     "edgeB -> vec3(0, 0, 1) color -> rgb(1, 1, 1) @ }] }"},
    {ObjectType::CylinderLight, "Settings { lights -> [CylinderLight { from -> vec3(-1, 5, 0) "
                                "to -> vec3(1, 5, 0) color -> rgb(1, 1, 1) @ }] }"},
    {ObjectType::SphereLight,
     "Settings { lights -> [SphereLight { center -> vec3(0, 5, 0) radius -> 0.5 color -> rgb(1, 1, 1) @ }] }"},
    {ObjectType::Material, CRT_SPHERE_WITH("Material { @ }")},
    {ObjectType::MaterialMap,
     CRT_SPHERE_WITH("MaterialMap { pattern -> Gradient {} "
                     "materials -> [[0, Material {}], [1, Material {}]] @ }")},
    {ObjectType::Layered, CRT_SPHERE_WITH("Layered { materials -> [Material {}] @ }")},
    {ObjectType::Background, "Settings { background -> Background { image -> \"sky.png\" @ } }"},
    {ObjectType::Medium, CRT_SPHERE_WITH("Material { transparency -> 1 medium -> Medium { @ } }")},
    {ObjectType::Fog, "Settings { fog -> Fog { color -> rgb(0.5, 0.5, 0.5) distance -> 10 falloff -> 2 @ } }"},
    {ObjectType::Sphere, "Scene { Sphere { center -> vec3(0, 0, 0) radius -> 1 @ } }"},
    {ObjectType::Box, "Scene { Box { cornerA -> vec3(0, 0, 0) cornerB -> vec3(1, 1, 1) @ } }"},
    {ObjectType::Plane, "Scene { Plane { normal -> vec3(0, 1, 0) position -> vec3(0, 0, 0) @ } }"},
    {ObjectType::Cylinder,
     "Scene { Cylinder { base -> vec3(0, 0, 0) top -> vec3(0, 1, 0) radius -> 1 @ } }"},
    {ObjectType::Cone,
     "Scene { Cone { base -> vec3(0, 0, 0) baseradius -> 1 top -> vec3(0, 1, 0) @ } }"},
    {ObjectType::Torus, "Scene { Torus { center -> vec3(0, 0, 0) major -> 2 minor -> 0.5 @ } }"},
    {ObjectType::SmoothTriangle,
     "Scene { SmoothTriangle { a -> vec3(0, 0, 0) b -> vec3(1, 0, 0) c -> vec3(0, 0, 1) "
     "na -> vec3(0, 1, 0) nb -> vec3(0, 1, 0) nc -> vec3(0, 1, 0) @ } }"},
    {ObjectType::Polygon,
     "Scene { Polygon { points -> [vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 0, 1)] @ } }"},
    {ObjectType::Superellipsoid, "Scene { Superellipsoid { @ } }"},
    {ObjectType::Sor,
     "Scene { Sor { points -> [vec3(0, 0, 0), vec3(1, 0.1, 0), vec3(1, 1, 0), vec3(0, 1.1, 0)] "
     "@ } }"},
    {ObjectType::Lathe, "Scene { Lathe { points -> [vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0), "
                        "vec3(0, 1, 0)] @ } }"},
    {ObjectType::SphereSweep,
     "Scene { SphereSweep { points -> [vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0), vec3(0, 1, 0)] "
     "radii -> [0.5, 0.2, 0.3, 0.4] @ } }"},
    {ObjectType::Blob,
     "Scene { Blob { components -> [BlobSphere { center -> vec3(0, 0, 0) radius -> 2 }] @ } }"},
    {ObjectType::BlobSphere,
     "Scene { Blob { components -> [BlobSphere { center -> vec3(0, 0, 0) radius -> 2 @ }] } }"},
    {ObjectType::BlobCylinder,
     "Scene { Blob { components -> [BlobCylinder { base -> vec3(0, 0, 0) top -> vec3(0, 1, 0) "
     "radius -> 2 @ }] } }"},
    {ObjectType::Spline,
     "Scene { Sphere { radius -> 1 center -> spline(Spline { points -> [vec3(0, 0, 0), "
     "vec3(1, 0, 0), vec3(2, 1, 0), vec3(3, 0, 0)] @ }, 0.3) } }"},
    {ObjectType::Text, "Scene { Text { text -> \"crt\" @ } }"},
    {ObjectType::Isosurface,
     "Scene { Isosurface { function -> Function (x, y, z) { x * x + y * y + z * z - 0.5 } @ } }"},
    {ObjectType::HeightField, "Scene { HeightField { function -> Function (x, y, z) { x * z } @ } }"},
    {ObjectType::FunctionPattern,
     CRT_SPHERE_WITH("Material { texture -> FunctionPattern { function -> Function (x, y, z) { x } @ } }")},
    {ObjectType::Prism,
     "Scene { Prism { points -> [vec3(0, 0, 1), vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 0, 1), "
     "vec3(0, 0, 0)] @ } }"},
    {ObjectType::Merge, "Scene { Merge { objects -> [Superellipsoid {}] @ } }"},
    {ObjectType::Inverse, "Scene { Inverse { object -> Superellipsoid {} @ } }"},
    {ObjectType::Clipped, "Scene { Clipped { object -> Superellipsoid {} by -> Superellipsoid {} @ } }"},
    {ObjectType::Disc,
     "Scene { Disc { center -> vec3(0, 0, 0) normal -> vec3(0, 1, 0) radius -> 1 @ } }"},
    {ObjectType::Quad,
     "Scene { Quad { corner -> vec3(0, 0, 0) edgeA -> vec3(1, 0, 0) edgeB -> vec3(0, 0, 1) @ } }"},
    {ObjectType::Triangle,
     "Scene { Triangle { a -> vec3(0, 0, 0) b -> vec3(1, 0, 0) c -> vec3(0, 1, 0) @ } }"},
    {ObjectType::Mesh, "Scene { Mesh { file -> \"m.obj\" @ } }"},
    {ObjectType::Checker, CRT_SPHERE_WITH("Material { texture -> Checker { @ } }")},
    {ObjectType::Stripes, CRT_SPHERE_WITH("Material { texture -> Stripes { @ } }")},
    {ObjectType::Noise, CRT_SPHERE_WITH("Material { texture -> Noise { @ } }")},
    {ObjectType::Marble, CRT_SPHERE_WITH("Material { texture -> Marble { @ } }")},
    {ObjectType::Wood, CRT_SPHERE_WITH("Material { texture -> Wood { @ } }")},
    {ObjectType::Image, CRT_SPHERE_WITH("Material { texture -> Image { file -> \"t.png\" @ } }")},
    {ObjectType::NoiseBump, CRT_SPHERE_WITH("Material { bump -> NoiseBump { @ } }")},
    {ObjectType::ImageBump,
     CRT_SPHERE_WITH("Material { bump -> ImageBump { file -> \"b.png\" @ } }")},
    {ObjectType::Ripples, CRT_SPHERE_WITH("Material { texture -> Ripples { @ } }")},
    {ObjectType::Waves, CRT_SPHERE_WITH("Material { texture -> Waves { @ } }")},
    {ObjectType::Gradient, CRT_SPHERE_WITH("Material { texture -> Gradient { @ } }")},
    {ObjectType::Onion, CRT_SPHERE_WITH("Material { texture -> Onion { @ } }")},
    {ObjectType::Leopard, CRT_SPHERE_WITH("Material { texture -> Leopard { @ } }")},
    {ObjectType::Radial, CRT_SPHERE_WITH("Material { texture -> Radial { @ } }")},
    {ObjectType::Spiral, CRT_SPHERE_WITH("Material { texture -> Spiral { arms -> 3 @ } }")},
    {ObjectType::Brick, CRT_SPHERE_WITH("Material { texture -> Brick { @ } }")},
    {ObjectType::Hexagon, CRT_SPHERE_WITH("Material { texture -> Hexagon { @ } }")},
    {ObjectType::Boxed, CRT_SPHERE_WITH("Material { texture -> Boxed { @ } }")},
    {ObjectType::Spherical, CRT_SPHERE_WITH("Material { texture -> Spherical { @ } }")},
    {ObjectType::Cylindrical, CRT_SPHERE_WITH("Material { texture -> Cylindrical { @ } }")},
    {ObjectType::Planar, CRT_SPHERE_WITH("Material { texture -> Planar { @ } }")},
    {ObjectType::Quilted, CRT_SPHERE_WITH("Material { texture -> Quilted { @ } }")},
    {ObjectType::Mandel, CRT_SPHERE_WITH("Material { texture -> Mandel { iterations -> 20 @ } }")},
    {ObjectType::Bozo, CRT_SPHERE_WITH("Material { texture -> Bozo { @ } }")},
    {ObjectType::Spotted, CRT_SPHERE_WITH("Material { texture -> Spotted { @ } }")},
    {ObjectType::Granite, CRT_SPHERE_WITH("Material { texture -> Granite { @ } }")},
    {ObjectType::Agate, CRT_SPHERE_WITH("Material { texture -> Agate { @ } }")},
    {ObjectType::Wrinkles, CRT_SPHERE_WITH("Material { texture -> Wrinkles { @ } }")},
    {ObjectType::Dents, CRT_SPHERE_WITH("Material { texture -> Dents { @ } }")},
    {ObjectType::Crackle, CRT_SPHERE_WITH("Material { texture -> Crackle { @ } }")},
    {ObjectType::Cells, CRT_SPHERE_WITH("Material { texture -> Cells { @ } }")},
    {ObjectType::Slope, CRT_SPHERE_WITH("Material { texture -> Slope { @ } }")},
    {ObjectType::Bump, CRT_SPHERE_WITH("Material { bump -> Bump { pattern -> Granite { } @ } }")},
};

/// Defaults documented as a rule rather than a value; each has its own test below.
constexpr std::pair<ObjectType, std::string_view> kRuleDefaults[] = {
    {ObjectType::Camera, "focaldistance"},     // the distance from position to pointing
    {ObjectType::Camera, "width"},             // the pinhole view's width at pointing
    {ObjectType::Material, "diffuse"},         // what reflection and refraction leave
    {ObjectType::Material, "reflectivitymin"}, // reflectivity
    {ObjectType::Material, "texture"},         // none
    {ObjectType::Material, "bump"},            // none
    {ObjectType::Settings, "fog"},             // none
    {ObjectType::Material, "medium"},          // none
    {ObjectType::Fog, "falloff"},              // none: a constant fog
    {ObjectType::Settings, "reflectiondepth"}, // recursiondepth
    {ObjectType::Settings, "refractiondepth"}, // recursiondepth
    {ObjectType::Settings, "shutterclose"},    // shutteropen: a closed shutter
    {ObjectType::HeightField, "image"},        // a height field has an image or a function
    {ObjectType::HeightField, "function"},
    {ObjectType::Mesh, "file"},                // a mesh has a file, or vertices and faces
    {ObjectType::Mesh, "vertices"},
    {ObjectType::Mesh, "faces"},
    {ObjectType::Mesh, "normals"},
    {ObjectType::Mesh, "uvs"},
};

bool isRuleDefault(ObjectType type, std::string_view attribute) {
    // An entity's material: none of its own, so that a <material m> around it can give one;
    // drawn as Material {} otherwise (tests/unit/tracer/render/given_material_test.cpp).
    if (attribute == "material" && objectInfo(type).category == ObjectCategory::Entity) return true;
    for (auto [t, name] : kRuleDefaults) {
        if (t == type && name == attribute) return true;
    }
    return false;
}

std::string_view usageOf(ObjectType type) {
    for (const Usage& usage : kUsages) {
        if (usage.type == type) return usage.script;
    }
    return {};
}

std::string withAttribute(std::string_view script, const std::string& attribute) {
    std::string text(script);
    text.replace(text.find('@'), 1, attribute);
    return text;
}

crt::scene::SceneDesc evaluate(const std::string& text) {
    EvalOptions options;
    options.checkFiles = false;
    Compilation c = compile("defaults.crt", text, options);
    std::string errors;
    for (const Diagnostic& d : c.diagnostics.items()) {
        if (d.severity == Severity::Error) errors += d.message + "\n";
    }
    INFO(text);
    INFO(errors);
    REQUIRE(c.scene.has_value());
    return *c.scene;
}

void dropSources(Json& json) {
    if (json.is_object()) {
        json.erase("source");
        for (auto& [key, value] : json.items()) dropSources(value);
    } else if (json.is_array()) {
        for (Json& item : json) dropSources(item);
    }
}

/// The scene a script describes, without where its objects were written.
Json described(const std::string& text) {
    Json json = Json::parse(crt::scene::sceneToJson(evaluate(text)));
    dropSources(json);
    return json;
}

double parsed(std::string_view text) {
    double value = 0;
    std::from_chars(text.data(), text.data() + text.size(), value);
    return value;
}

/// A valid value other than the default, to show the comparison sees the attribute at all.
std::string otherValue(const AttributeInfo& attr) {
    switch (attr.type) {
    case AttrType::Int: return std::to_string(static_cast<int64_t>(parsed(attr.defaultText)) + 1);
    case AttrType::Float:
    case AttrType::Gamma: return std::to_string(parsed(attr.defaultText) * 0.5 + 0.3);
    case AttrType::Bool: return attr.defaultText == "false" ? "true" : "false";
    case AttrType::String: return "\"other\"";
    case AttrType::Vec3: return "vec3(0.25, 0.5, 0.75)";
    case AttrType::Color:
    case AttrType::Background: return "rgb(0.25, 0.5, 0.75)";
    case AttrType::Choice:
    case AttrType::Aperture:
        for (std::string_view choice : attr.choices) {
            std::string written = fmt::format("\"{}\"", choice);
            if (written != attr.defaultText) return written;
        }
        return "";
    case AttrType::Material: return "Material { color -> rgb(0.25, 0.5, 0.75) }";
    case AttrType::Camera: return "Camera { position -> vec3(0, 0, -2) pointing -> vec3(0, 1, 0) }";
    case AttrType::LightList:
        return "[PointLight { origin -> vec3(0, 5, 0) color -> rgb(1, 1, 1) }]";
    case AttrType::ColorMap: { // as many stops as the default, for patterns that need so many
        std::string stops;
        size_t count = 0;
        for (size_t at = attr.defaultText.find("rgb("); at != std::string_view::npos;
             at = attr.defaultText.find("rgb(", at + 1)) {
            ++count;
        }
        for (size_t i = 0; i < count; ++i) {
            stops += fmt::format("{}[{}, rgb(0.25, 0.5, {})]", i ? ", " : "",
                                 static_cast<double>(i) / static_cast<double>(count - 1),
                                 0.1 * static_cast<double>(i));
        }
        return "[" + stops + "]";
    }
    case AttrType::Turbulence: return "vec3(0.25, 0.5, 0.75)";
    case AttrType::FloatOrPattern: return "0.5";
    case AttrType::Texture:
    case AttrType::Bump:
    case AttrType::MaterialMap:
    case AttrType::MaterialList:
    case AttrType::PatternList:
    case AttrType::Fog:
    case AttrType::Medium:
    case AttrType::Solid:
    case AttrType::Entity:
    case AttrType::SolidList:
    case AttrType::PointList:
    case AttrType::BlobComponentList:
    case AttrType::Function: return ""; // required: no default to differ from
    case AttrType::Box: return "Box { cornerA -> vec3(-2, -1, -1) cornerB -> vec3(1, 2, 1) }";
    case AttrType::FloatList: return "[0, 0.1, 0.5, 1]";
    case AttrType::FaceList: return "[[0, 1, 2]]";
    }
    return "";
}

} // namespace

TEST_CASE("every object type has a usage for the default checks", "[defaults]") {
    for (const ObjectInfo& info : allObjectTypes()) {
        INFO(info.name);
        CHECK(!usageOf(info.type).empty());
    }
}

TEST_CASE("an absent attribute reads as its documented default", "[defaults]") {
    int checked = 0;
    for (const ObjectInfo& info : allObjectTypes()) {
        std::string_view usage = usageOf(info.type);
        REQUIRE(!usage.empty());
        for (const AttributeInfo& attr : info.attributes) {
            if (attr.required || attr.defaultText.empty() || isRuleDefault(info.type, attr.name)) {
                continue;
            }
            INFO(info.name << "." << attr.name << " documented as " << attr.defaultText);
            Json absent = described(withAttribute(usage, ""));
            Json given = described(withAttribute(usage, std::string(attr.name) + " -> " +
                                                            std::string(attr.defaultText)));
            std::string differences = Json::diff(absent, given).dump();
            CHECK(differences == "[]");
            std::string other = otherValue(attr);
            REQUIRE(!other.empty());
            CHECK(described(withAttribute(usage, std::string(attr.name) + " -> " + other)) !=
                  absent);
            ++checked;
        }
    }
    CHECK(checked > 60); // every literal default of every type, not a few
}

TEST_CASE("defaults documented as rules follow their rule", "[defaults]") {
    for (auto [type, name] : kRuleDefaults) {
        const ObjectInfo& info = objectInfo(type);
        int slot = findAttribute(info, name);
        REQUIRE(slot >= 0);
        INFO(info.name << "." << name);
        CHECK_FALSE(info.attributes[static_cast<size_t>(slot)].required);
    }

    SECTION("a camera focuses at the point it looks at") {
        CHECK(objectInfo(ObjectType::Camera)
                  .attributes[findAttribute(objectInfo(ObjectType::Camera), "focaldistance")]
                  .defaultText == "|pointing - position|");
        crt::scene::SceneDesc s = evaluate(withAttribute(usageOf(ObjectType::Camera), ""));
        CHECK(s.camera.focalDistance == glm::length(glm::dvec3(0, 1, 0) - glm::dvec3(1, 2, -5)));
        // Without a camera, the documented default camera's own rule holds too.
        crt::scene::SceneDesc none = evaluate("Settings { }");
        CHECK(none.camera.focalDistance ==
              glm::length(none.camera.pointing - none.camera.position));
    }

    SECTION("an orthographic camera without a width is as wide as the pinhole view at pointing") {
        CHECK(objectInfo(ObjectType::Camera)
                  .attributes[findAttribute(objectInfo(ObjectType::Camera), "width")]
                  .defaultText == "the pinhole view's width at pointing");
        // 0 in the description: the tracer's camera derives it (camera_test.cpp checks how).
        crt::scene::SceneDesc s = evaluate(withAttribute(usageOf(ObjectType::Camera), "projection -> \"orthographic\""));
        CHECK(s.camera.projection == crt::scene::Projection::Orthographic);
        CHECK(s.camera.width == 0);
    }

    SECTION("diffuse is what reflection and refraction leave, never negative") {
        const ObjectInfo& material = objectInfo(ObjectType::Material);
        CHECK(material.attributes[findAttribute(material, "diffuse")].defaultText ==
              "max(0, 1 - reflectivity - transparency)");
        for (auto [reflectivity, transparency] : {std::pair{0.0, 0.0}, {0.25, 0.5}, {0.75, 0.5}}) {
            crt::scene::SceneDesc s =
                evaluate(withAttribute(usageOf(ObjectType::Material),
                                       "reflectivity -> " + std::to_string(reflectivity) +
                                           " transparency -> " + std::to_string(transparency)));
            REQUIRE(s.materials.size() == 1);
            CHECK(s.finishOf(s.materials[0]).diffuse ==
                  std::max(0.0, 1.0 - reflectivity - transparency));
        }
    }

    SECTION("with conserveenergy diffuse is 1, as each point takes its own share") {
        crt::scene::SceneDesc s = evaluate(withAttribute(
            usageOf(ObjectType::Material), "reflectivity -> 0.5 conserveenergy -> true"));
        CHECK(s.finishOf(s.materials[0]).diffuse == 1.0);
    }

    SECTION("reflectivitymin is reflectivity unless given") {
        const ObjectInfo& material = objectInfo(ObjectType::Material);
        CHECK(material.attributes[findAttribute(material, "reflectivitymin")].defaultText ==
              "reflectivity");
        Json absent =
            described(withAttribute(usageOf(ObjectType::Material), "reflectivity -> 0.4"));
        CHECK(absent["materials"][0]["reflectivitymin"] == 0.4);
        Json given = described(withAttribute(usageOf(ObjectType::Material),
                                             "reflectivity -> 0.4 reflectivitymin -> 0.1"));
        CHECK(given["materials"][0]["reflectivitymin"] == 0.1);
    }

    SECTION("reflection and refraction depths follow recursiondepth unless given") {
        const ObjectInfo& settings = objectInfo(ObjectType::Settings);
        for (std::string_view name : {"reflectiondepth", "refractiondepth"}) {
            CHECK(settings.attributes[findAttribute(settings, name)].defaultText ==
                  "recursiondepth");
        }
        crt::scene::SceneDesc absent = evaluate("Settings { recursiondepth -> 7 }");
        CHECK(absent.settings.reflectionLimit() == 7);
        CHECK(absent.settings.refractionLimit() == 7);
        CHECK(absent.settings.bounceLimit() == 7);
        crt::scene::SceneDesc none = evaluate("Settings { }");
        CHECK(none.settings.reflectionLimit() == 3);
        CHECK(none.settings.refractionLimit() == 3);
        crt::scene::SceneDesc given =
            evaluate("Settings { recursiondepth -> 7 reflectiondepth -> 2 refractiondepth -> 9 }");
        CHECK(given.settings.reflectionLimit() == 2);
        CHECK(given.settings.refractionLimit() == 9);
        CHECK(given.settings.bounceLimit() == 9);
    }

    SECTION("the shutter closes as it opens unless told when it closes") {
        const ObjectInfo& settings = objectInfo(ObjectType::Settings);
        CHECK(settings.attributes[findAttribute(settings, "shutterclose")].defaultText == "shutteropen");
        crt::scene::SceneDesc opened = evaluate("Settings { shutteropen -> 0.3 }");
        CHECK(opened.settings.shutterClose == 0.3);
        CHECK_FALSE(opened.settings.shutterIsOpen());
        crt::scene::SceneDesc given = evaluate("Settings { shutteropen -> 0.3 shutterclose -> 0.5 }");
        CHECK(given.settings.shutterClose == 0.5);
        CHECK(given.settings.shutterIsOpen());
    }

    SECTION("a material has no texture and no bump unless given") {
        const ObjectInfo& material = objectInfo(ObjectType::Material);
        CHECK(material.attributes[findAttribute(material, "texture")].defaultText == "none");
        CHECK(material.attributes[findAttribute(material, "bump")].defaultText == "none");
        crt::scene::SceneDesc s = evaluate(withAttribute(usageOf(ObjectType::Material), ""));
        REQUIRE(s.materials.size() == 1);
        CHECK(s.finishOf(s.materials[0]).texture == -1);
        CHECK(s.finishOf(s.materials[0]).bump == -1);
        CHECK(s.textures.empty());
    }

    SECTION("a material has no medium unless given") {
        const ObjectInfo& material = objectInfo(ObjectType::Material);
        CHECK(material.attributes[findAttribute(material, "medium")].defaultText == "none");
        crt::scene::SceneDesc s = evaluate(withAttribute(usageOf(ObjectType::Material), ""));
        CHECK(s.finishOf(s.materials[0]).medium == -1);
        CHECK(s.media.empty());
    }

    SECTION("a scene has no fog unless given, and a fog without falloff is constant") {
        CHECK(objectInfo(ObjectType::Settings).attributes[findAttribute(objectInfo(ObjectType::Settings), "fog")]
                  .defaultText == "none");
        CHECK_FALSE(evaluate("Settings { }").fog.has_value());
        const crt::scene::SceneDesc s = evaluate("Settings { fog -> Fog { color -> rgb(1, 1, 1) distance -> 3 } }");
        REQUIRE(s.fog.has_value());
        CHECK(s.fog->falloff == 0);
        CHECK(evaluate(withAttribute(usageOf(ObjectType::Fog), "")).fog->falloff == 2);
    }
}
