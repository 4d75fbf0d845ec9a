// What a POV-Ray user writes out of habit, and how CRT says it (docs/from-povray.md has the
// whole comparison; these are the words a newcomer types first).
#include "povray_habits.hpp"

#include <algorithm>
#include <iterator>
#include <span>
#include <utility>

namespace crt::lang::povray {
namespace {

using Hint = std::pair<std::string_view, std::string_view>;

std::string_view lookUp(std::span<const Hint> table, std::string_view word) {
    for (const auto& [key, hint] : table)
        if (key == word) return hint;
    return "";
}

// The directives whose line reads as CRT once the '#' is gone (#declare x = 1): every
// other one's line is skipped, so that it adds no errors of its own.
constexpr std::string_view kLinesKept[] = {"declare", "local", "include"};

constexpr Hint kDirectives[] = {
    {"declare", "write 'x = value' for '#declare x = value'"},
    {"local", "write 'x = value' for '#local x = value' (a macro's variables are its own)"},
    {"include", "write 'include \"file.crt\"'"},
    {"macro", "write 'name = Macro (a, b) { ... }'"},
    {"while", "write 'while (condition) { ... }'"},
    {"for", "write 'for i in range(n) { ... }'"},
    {"if", "write 'if (condition) { ... } else { ... }'"},
    {"ifdef", "write 'if (condition) { ... }'"},
    {"else", "write 'if (condition) { ... } else { ... }'"},
    {"end", "blocks end with '}'"},
    {"version", "leave it out"},
    {"default", "give each Material what it needs"},
};

constexpr Hint kBlocks[] = {
    {"light_source", "a light is 'PointLight { origin -> ... color -> ... }' (or SpotLight, "
                     "ParallelLight, AreaLight), listed in Settings.lights"},
    {"union", "CSG is written with operators: 'a + b' is a union"},
    {"merge", "CSG is written with operators: 'a + b' is a union, which keeps the inner surfaces"},
    {"difference", "CSG is written with operators: 'a - b' is a difference"},
    {"intersection", "CSG is written with operators: 'a ^ b' is an intersection"},
    {"object", "an object is drawn by its name, and moved with 'thing <translate ...>'"},
    {"texture", "a surface's look is a 'Material { ... }' given to the shape's 'material'"},
    {"pigment",
     "a surface's colour is 'Material { color -> ... }' or 'Material { texture -> ... }'"},
    {"finish",
     "a finish's attributes (diffuse, specular, reflectivity ...) are the Material's own"},
    {"normal",
     "bumps are 'Material { bump -> Bump { pattern -> ... } }' (or NoiseBump, ImageBump)"},
    {"interior", "ior and absorption are the Material's own attributes"},
    {"global_settings", "scene-wide settings go in 'Settings { ... }'"},
    {"sky_sphere",
     "the sky is 'Settings { background -> Background { horizon -> ... sky -> ... } }'"},
};

struct AttributeEntry {
    ObjectCategory category;
    std::string_view povName;
    AttributeHint hint;
};

constexpr std::string_view kInMaterial = "a shape's look belongs in its Material: "
                                         "'material -> Material { texture -> ... }'";

constexpr AttributeEntry kAttributes[] = {
    {ObjectCategory::Camera, "location", {"position", "POV-Ray's location is CRT's position"}},
    {ObjectCategory::Camera, "look_at", {"pointing", "POV-Ray's look_at is CRT's pointing"}},
    {ObjectCategory::Camera,
     "angle",
     {"fov", "CRT's fov is the vertical angle of view; POV-Ray's angle is the horizontal one"}},
    {ObjectCategory::Camera, "sky", {"up", "POV-Ray's sky is CRT's up"}},
    {ObjectCategory::Light, "location", {"origin", "a light's position is its origin"}},
    {ObjectCategory::Light, "point_at", {"pointing", "POV-Ray's point_at is CRT's pointing"}},
    {ObjectCategory::Settings,
     "ambient_light",
     {"ambient", "POV-Ray's ambient_light is Settings.ambient"}},
    {ObjectCategory::Settings,
     "max_trace_level",
     {"recursiondepth", "POV-Ray's max_trace_level is Settings.recursiondepth"}},
    {ObjectCategory::Settings,
     "assumed_gamma",
     {"gamma", "CRT's colours are linear; Settings.gamma is the output's encoding"}},
    {ObjectCategory::Material, "pigment", {"", "a Material's colour is 'color' or 'texture'"}},
    {ObjectCategory::Material, "finish", {"", "a finish's attributes are the Material's own"}},
    {ObjectCategory::Material, "normal", {"bump", "POV-Ray's normal is a Material's bump"}},
    {ObjectCategory::Material,
     "phong",
     {"specular", "CRT's highlight is Phong's: phong is specular"}},
    {ObjectCategory::Material, "phong_size", {"shininess", "phong_size is shininess"}},
    {ObjectCategory::Material,
     "reflection",
     {"reflectivity", "POV-Ray's reflection is reflectivity"}},
    {ObjectCategory::Material,
     "ambient",
     {"", "ambient light is Settings.ambient, times each Material's colour and diffuse"}},
    {ObjectCategory::Material,
     "conserve_energy",
     {"conserveenergy", "conserve_energy is conserveenergy"}},
    {ObjectCategory::Entity, "texture", {"", kInMaterial}},
    {ObjectCategory::Entity, "pigment", {"", kInMaterial}},
    {ObjectCategory::Entity, "finish", {"", kInMaterial}},
    {ObjectCategory::Entity, "normal", {"", kInMaterial}},
};

constexpr Hint kIncludes[] = {
    {"colors.inc", "colors.crt"},    {"textures.inc", "materials.crt"},
    {"metals.inc", "metals.crt"},    {"glass.inc", "glass.crt"},
    {"golds.inc", "metals.crt"},     {"woods.inc", "woods.crt"},
    {"stones.inc", "stones.crt"},    {"shapes.inc", "shapes.crt"},
    {"finish.inc", "materials.crt"},
};

} // namespace

std::string_view directiveHint(std::string_view word) {
    return lookUp(kDirectives, word);
}

bool directiveLineIsForeign(std::string_view word) {
    return !directiveHint(word).empty() &&
           std::find(std::begin(kLinesKept), std::end(kLinesKept), word) == std::end(kLinesKept);
}

std::string_view blockHint(std::string_view word) {
    return lookUp(kBlocks, word);
}

std::optional<AttributeHint> attributeHint(ObjectCategory category, std::string_view name) {
    for (const AttributeEntry& entry : kAttributes)
        if (entry.category == category && entry.povName == name) return entry.hint;
    return std::nullopt;
}

std::string_view includeReplacement(std::string_view file) {
    return lookUp(kIncludes, file);
}

} // namespace crt::lang::povray
