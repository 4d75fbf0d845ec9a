// The attribute tables of spec §5.
#include "object_schema.hpp"

#include "scene/scene_desc.hpp"

#include <array>
#include <vector>

namespace crt::lang {
namespace {

using A = AttrType;

// "uniform" is the 2015 name of the circle (a disc sampled uniformly), kept for old scripts.
constexpr std::string_view kApertureChoices[] = {"circle",  "triangle", "square", "pentagon",
                                                 "hexagon", "octagon",  "gaussian", "line",
                                                 "uniform"};
constexpr std::string_view kMappingChoices[] = {"uv", "planar", "spherical", "cylindrical",
                                                "cubic"};

constexpr AttributeInfo kSettings[] = {
    {"title", A::String, false, "\"\"", "The scene's title."},
    {"author", A::String, false, "\"\"", "Who made the scene."},
    {"date", A::String, false, "\"\"", "When the scene was made."},
    {"notes", A::String, false, "\"\"", "Free-form notes."},
    {"width", A::Int, false, "800", "Image width in pixels."},
    {"height", A::Int, false, "600", "Image height in pixels."},
    {"camera", A::Camera, false, "Camera { position -> vec3(0,0,-1) pointing -> vec3(0,0,0) }",
     "The camera the scene is seen through."},
    {"lights", A::LightList, false, "[]", "The lights that shine; others are ignored."},
    {"background", A::Background, false, "rgb(1,1,1)",
     "What rays that hit nothing see: a Background or a colour."},
    {"fog", A::Fog, false, "none", "Fog over the scene, outside every solid."},
    {"gamma", A::Gamma, false, "1.0",
     "Output encoding: c^(1/gamma) per channel, or \"srgb\" for the sRGB curve."},
    {"supersampling", A::Int, false, "1", "n: an n x n grid of samples per pixel."},
    {"dofsamples", A::Int, false, "1", "Lens samples per pixel sample (depth of field needs > 1)."},
    {"recursiondepth", A::Int, false, "3", "How many reflections and refractions deep rays go."},
    {"reflectiondepth", A::Int, false, "recursiondepth",
     "How many reflections deep rays go; overrides recursiondepth for reflections."},
    {"refractiondepth", A::Int, false, "recursiondepth",
     "How many refractions deep rays go; overrides recursiondepth for refractions."},
    {"antialias", A::Choice, false, "\"grid\"",
     "Anti-aliasing: grid, adaptive, showadaptive or stratified (jittered grid).",
     scene::kAntialiasNames},
    {"aathreshold", A::Float, false, "0.1", "Adaptive anti-aliasing: colour difference that subdivides."},
    {"aadepth", A::Int, false, "2", "Adaptive anti-aliasing: maximum subdivision levels."},
    {"shadowsamples", A::Int, false, "16", "Samples per area or cylinder light."},
    {"glossysamples", A::Int, false, "16", "Rays per glossy reflection."},
    {"seed", A::Int, false, "0", "Seed of the renderer's sampling."},
    {"ambient", A::Color, false, "rgb(0,0,0)", "Global ambient light (whitted only)."},
    {"integrator", A::Choice, false, "\"whitted\"",
     "How light is carried: whitted (direct light, mirrors and glass) or path (path tracing: "
     "light bounces off every surface).",
     scene::kIntegratorNames},
    {"samples", A::Int, false, "64", "Path integrator: paths traced per pixel."},
    {"bounces", A::Int, false, "8", "Path integrator: surfaces a path may bounce off."},
    {"targeterror", A::Float, false, "",
     "Path integrator: a pixel stops taking paths (after 16, at most samples) once the relative "
     "standard error of its mean falls below this; 0: every pixel takes samples."},
    {"shutteropen", A::Float, false, "0",
     "Motion blur: when the shutter opens, in units of t after the frame's t."},
    {"shutterclose", A::Float, false, "shutteropen",
     "Motion blur: when the shutter closes, in units of t after the frame's t; after shutteropen, "
     "the scene is evaluated motionsteps times across the shutter and what moves is blurred."},
    {"motionsteps", A::Int, false, "2",
     "Motion blur: evaluations across the shutter (2 to 64); modifiers and the camera move "
     "linearly between them."},
};

constexpr AttributeInfo kCamera[] = {
    {"position", A::Vec3, true, "", "Where the camera is."},
    {"pointing", A::Vec3, true, "", "The point the camera looks at."},
    {"fov", A::Float, false, "60",
     "Vertical field of view in degrees, in (0, 180); fisheye: the angle across its circle, in (0, 360]; "
     "cylindrical: the horizontal angle, in (0, 360]."},
    {"width", A::Float, false, "the pinhole view's width at pointing",
     "Orthographic: the width of the view in scene units."},
    {"aperture", A::Float, false, "0", "Lens size; the lens radius is aperture / 1000 units."},
    {"focaldistance", A::Float, false, "|pointing - position|", "Distance of the sharp plane."},
    {"apertureshape", A::Aperture, false, "\"circle\"",
     "Lens (bokeh) shape: circle, triangle, square, pentagon, hexagon, octagon, gaussian, line, "
     "uniform (the 2015 name of the circle aperture), or a number of polygon sides.",
     kApertureChoices},
    {"up", A::Vec3, false, "vec3(0,1,0)", "Which way is up."},
    {"roll", A::Float, false, "0", "Rotation about the view axis, degrees."},
    {"projection", A::Choice, false, "\"pinhole\"",
     "pinhole, spherical (a panorama), orthographic (parallel rays), fisheye (angle proportional to the "
     "distance from the middle) or cylindrical (a panorama around up, straight lines up).",
     scene::kProjectionNames},
};

// Attributes several lights share.
constexpr AttributeInfo kLightFalloff{"falloff", A::Float, false, "0",
                                      "0: no falloff; else falloff / d^2, d the whole ray path."};
constexpr AttributeInfo kLightAttenuation{
    "attenuation", A::Vec3, false, "vec3(1,0,0)",
    "vec3(c0, c1, c2): intensity / (c0 + c1 d + c2 d^2), d the distance to the light."};
constexpr AttributeInfo kLightAmbient{"ambient", A::Float, false, "0", "Ambient contribution of this light."};
constexpr AttributeInfo kLightShadowless{"shadowless", A::Bool, false, "false",
                                         "Lights everything it reaches as if nothing stood in the way: casts no shadow."};
constexpr AttributeInfo kLightVisible{
    "visible", A::Bool, false, "false",
    "Seen by camera and reflected rays, as its colour (POV-Ray's looks_like, without an object)."};

constexpr AttributeInfo kPointLight[] = {
    {"origin", A::Vec3, true, "", "Where the light is."},
    {"color", A::Color, true, "", "The light's colour and intensity."},
    kLightFalloff,
    kLightAttenuation,
    kLightAmbient,
    kLightShadowless,
};

constexpr AttributeInfo kParallelLight[] = {
    {"from", A::Vec3, true, "", "A point the light comes from."},
    {"pointing", A::Vec3, true, "", "A point the light travels towards."},
    {"color", A::Color, true, "", "The light's colour and intensity."},
    kLightAmbient,
    kLightShadowless,
};

constexpr AttributeInfo kSpotLight[] = {
    {"origin", A::Vec3, true, "", "Where the light is."},
    {"pointing", A::Vec3, true, "", "The point the spot aims at."},
    {"color", A::Color, true, "", "The light's colour and intensity."},
    kLightFalloff,
    kLightAttenuation,
    kLightAmbient,
    {"angle", A::Float, false, "30", "Full cone angle, degrees."},
    {"softness", A::Float, false, "0.2", "Outer fraction of the cone that fades to dark."},
    {"tightness", A::Float, false, "0",
     "Intensity times cos^tightness of the angle from the axis: a brighter middle (POV-Ray's)."},
    kLightShadowless,
};

constexpr AttributeInfo kAreaLight[] = {
    {"corner", A::Vec3, true, "", "One corner of the emitting parallelogram."},
    {"edgeA", A::Vec3, true, "", "First edge from the corner."},
    {"edgeB", A::Vec3, true, "", "Second edge from the corner."},
    {"color", A::Color, true, "", "Total colour and intensity."},
    kLightFalloff,
    kLightAttenuation,
    kLightAmbient,
    kLightShadowless,
    {"circular", A::Bool, false, "false", "The ellipse inscribed in the parallelogram: a round lamp."},
    {"orient", A::Bool, false, "false",
     "Turned about its centre to face each lit point, its edges keeping their lengths: a sphere-like lamp."},
    kLightVisible,
};

constexpr AttributeInfo kCylinderLight[] = {
    {"from", A::Vec3, true, "", "One end of the emitting segment (the tube's axis)."},
    {"to", A::Vec3, true, "", "The other end; must differ from 'from'."},
    {"color", A::Color, true, "", "Total colour and intensity."},
    kLightFalloff,
    kLightAttenuation,
    kLightAmbient,
    kLightShadowless,
    {"radius", A::Float, false, "0", "The tube's radius as it is seen when visible (it lights from its axis)."},
    kLightVisible,
};

constexpr AttributeInfo kSphereLight[] = {
    {"center", A::Vec3, true, "", "Centre of the glowing sphere."},
    {"radius", A::Float, true, "", "Its radius, above 0."},
    {"color", A::Color, true, "", "Total colour and intensity."},
    kLightFalloff,
    kLightAttenuation,
    kLightAmbient,
    kLightShadowless,
    kLightVisible,
};

constexpr AttributeInfo kMaterial[] = {
    {"color", A::Color, false, "rgb(0.5,0.5,0.5)", "Surface colour."},
    {"reflectivity", A::Float, false, "0",
     "Mirror reflection, 0 to 1 (at grazing angles, with reflectivitymin)."},
    {"reflectivitymin", A::Float, false, "reflectivity", "Mirror reflection facing the viewer."},
    {"reflectionfalloff", A::Float, false, "1",
     "How reflection grows from reflectivitymin to reflectivity: (1 - cos)^falloff."},
    {"transparency", A::Float, false, "0", "Refracted light, 0 to 1."},
    {"ior", A::Float, false, "1.0", "Index of refraction."},
    {"diffuse", A::Float, false, "max(0, 1 - reflectivity - transparency)",
     "Diffuse factor (1 with conserveenergy)."},
    {"brilliance", A::Float, false, "1", "Diffuse light falls as cos^brilliance."},
    {"conserveenergy", A::Bool, false, "false",
     "Diffuse takes only what reflection and transmission leave at each point."},
    {"specular", A::Float, false, "0", "Highlight strength."},
    {"shininess", A::Float, false, "3", "Highlight exponent."},
    {"metallic", A::Bool, false, "false", "Tint highlights and reflections by the colour."},
    {"glossiness", A::Float, false, "0", "0: sharp mirror; up to 1: blurrier."},
    {"fresnel", A::Bool, false, "false", "Angle-dependent reflection (Fresnel)."},
    {"absorption", A::Color, false, "rgb(0,0,0)", "Beer-Lambert absorption per unit inside."},
    {"texture", A::Texture, false, "none", "A texture that replaces the colour."},
    {"bump", A::Bump, false, "none", "A bump texture that perturbs the normal."},
    {"emission", A::Color, false, "rgb(0,0,0)", "Light the surface gives off."},
    {"medium", A::Medium, false, "none", "What fills the solid: smoke, dusty air, a cloud (a Medium)."},
    {"filter", A::Float, false, "0",
     "0 to 1: how much of what the colour's alpha lets through takes the colour."},
    // `refractiveindex` is a synonym of `ior`, handled by findAttribute.
};

constexpr AttributeInfo kMaterialMap[] = {
    {"pattern", A::Texture, true, "", "The pattern whose value picks the materials."},
    {"materials", A::MaterialMap, true, "",
     "[[value, material], ...]: values in order from 0 to 1; between two, their mix."},
};

constexpr AttributeInfo kLayered[] = {
    {"materials", A::MaterialList, true, "",
     "[bottom, ..., top]: each layer's colour alpha shows the layers under it."},
};

constexpr AttributeInfo kBackground[] = {
    {"color", A::Color, false, "", "A solid colour."},
    {"horizon", A::Color, false, "", "Gradient colour at the horizon (with sky)."},
    {"sky", A::Color, false, "", "Gradient colour straight up and down (with horizon)."},
    {"image", A::String, false, "", "An equirectangular panorama."},
    {"angle", A::Float, false, "0", "Yaw of the panorama, radians."},
    {"pattern", A::Texture, false, "",
     "A pattern read on the ray's direction (POV-Ray's sky_sphere); black shows through its alpha."},
    {"layers", A::PatternList, false, "",
     "[bottom, ..., top]: patterns read on the ray's direction, each one's alpha showing those under it."},
};

constexpr AttributeInfo kMedium[] = {
    {"absorption", A::Color, false, "rgb(0,0,0)", "Light absorbed per unit length, at density 1."},
    {"scattering", A::Color, false, "rgb(0,0,0)", "Light scattered per unit length, at density 1: what lights it."},
    {"emission", A::Color, false, "rgb(0,0,0)", "Light given off per unit length, at density 1."},
    {"density", A::FloatOrPattern, false, "1", "A number, or a pattern whose value (0 to 1) is the density."},
    {"phase", A::Choice, false, "\"isotropic\"",
     "How it scatters: isotropic, rayleigh (air), henyey-greenstein (with g).", scene::kPhaseNames},
    {"g", A::Float, false, "0", "Henyey-Greenstein: -1 to 1, back to forward scattering."},
    {"samples", A::Int, false, "16", "Steps along each ray through it."},
};

constexpr AttributeInfo kFog[] = {
    {"color", A::Color, true, "", "The fog's colour; its alpha a lets 1 - a of what is behind always through."},
    {"distance", A::Float, true, "", "How far one sees 1/e of what is behind (a constant fog's)."},
    {"filter", A::Float, false, "0", "0 to 1: how much of what is behind takes the fog's colour."},
    {"falloff", A::Float, false, "none",
     "Makes ground fog: density 1/(1 + h^2) at h times this above the altitude (POV-Ray's fog_alt)."},
    {"altitude", A::Float, false, "0", "Ground fog: the height along up to which the fog is dense."},
    {"up", A::Vec3, false, "vec3(0, 1, 0)", "Ground fog: the direction heights are measured along."},
    {"turbulence", A::Turbulence, false, "0",
     "How the fog thins in places: the scale of the noise that thins it (per axis); 0: evenly."},
    {"turbulencedepth", A::Float, false, "0.5", "0 to 1: how much of the fog the noise may take away."},
};

#define CRT_ENTITY_ATTRS                                                                           \
    {"material", A::Material, false, "Material {}",                                                \
     "The surface material (without one: what an enclosing `<material m>` gives, else the "        \
     "default)."},                                                                                 \
        {"shadow", A::Bool, false, "true", "false: casts no shadow (POV-Ray's no_shadow)."},       \
        {"camera", A::Bool, false, "true",                                                         \
         "false: unseen by the camera, still reflected and casting shadows (no_image)."},          \
    {                                                                                              \
        "reflected", A::Bool, false, "true",                                                       \
            "false: absent from reflections and refractions (POV-Ray's no_reflection)."           \
    }

constexpr AttributeInfo kSphere[] = {
    {"center", A::Vec3, true, "", "Centre of the sphere."},
    {"radius", A::Float, true, "", "Radius (>= 0)."},
    CRT_ENTITY_ATTRS,
};
constexpr AttributeInfo kBox[] = {
    {"cornerA", A::Vec3, true, "", "One corner."},
    {"cornerB", A::Vec3, true, "", "The opposite corner."},
    CRT_ENTITY_ATTRS,
};
constexpr AttributeInfo kPlane[] = {
    {"normal", A::Vec3, true, "", "Normal; as a solid, the half-space behind it."},
    {"position", A::Vec3, true, "", "A point on the plane."},
    CRT_ENTITY_ATTRS,
};
constexpr AttributeInfo kCylinder[] = {
    {"base", A::Vec3, true, "", "Centre of the base."},
    {"top", A::Vec3, true, "", "Centre of the top."},
    {"radius", A::Float, true, "", "Radius (>= 0)."},
    {"open", A::Bool, false, "false", "No caps."},
    CRT_ENTITY_ATTRS,
};
constexpr AttributeInfo kCone[] = {
    {"base", A::Vec3, true, "", "Centre of the base."},
    {"baseradius", A::Float, true, "", "Radius at the base."},
    {"top", A::Vec3, true, "", "Centre of the top."},
    {"topradius", A::Float, false, "0", "Radius at the top."},
    {"open", A::Bool, false, "false", "No caps."},
    CRT_ENTITY_ATTRS,
};
constexpr std::string_view kSweepChoices[] = {"linear", "conic"};
constexpr AttributeInfo kPrism[] = {
    {"points", A::PointList, true, "",
     "The outline, as POV-Ray's prism reads it, in the x-z plane (each y 0); a loop closes where "
     "its first point on the curve comes again, and loops inside loops are holes."},
    {"from", A::Float, false, "0", "Height of the bottom face."},
    {"to", A::Float, false, "1", "Height of the top face."},
    {"spline", A::Choice, false, "\"linear\"",
     "How the points make the outline: linear, quadratic, cubic or bezier.",
     scene::kLoopSplineKindNames},
    {"sweep", A::Choice, false, "\"linear\"",
     "linear (straight up) or conic (scaled with the height, from a point at the origin).",
     kSweepChoices},
    {"open", A::Bool, false, "false", "No end faces."},
    CRT_ENTITY_ATTRS,
};
constexpr AttributeInfo kSor[] = {
    {"points", A::PointList, true, "",
     "(radius, height) in the x-y plane (each z 0), at least four, rising from the second to "
     "the last but one; the first and last set the slopes at the ends."},
    {"open", A::Bool, false, "false", "No end faces."},
    CRT_ENTITY_ATTRS,
};
constexpr AttributeInfo kLathe[] = {
    {"points", A::PointList, true, "",
     "The curve in the x-y plane (each z 0), x the distance from the y axis, as POV-Ray's lathe "
     "reads it; closed, or from the axis to the axis, it bounds a solid."},
    {"spline", A::Choice, false, "\"linear\"",
     "How the points make the curve: linear, quadratic, cubic, bezier or bspline.",
     scene::kSplineKindNames},
    CRT_ENTITY_ATTRS,
};
constexpr AttributeInfo kSphereSweep[] = {
    {"points", A::PointList, true, "",
     "Where the sphere's centre passes, as `spline` reads them: at least 2 for linear, 4 "
     "otherwise."},
    {"radii", A::FloatList, true, "", "The sphere's radius at each point, one a point (>= 0)."},
    {"spline", A::Choice, false, "\"linear\"",
     "How the points make the curve: linear (straight between them), cubic (through all but "
     "the first and last) or bspline (smooth, near them).",
     scene::kSweepSplineKindNames},
    CRT_ENTITY_ATTRS,
};
constexpr AttributeInfo kText[] = {
    {"text", A::String, true, "", "The characters, on one line."},
    {"font", A::String, false, "\"\"",
     "A TrueType or OpenType file, looked up as images are; \"\" for DejaVu Sans."},
    {"thickness", A::Float, false, "0.25", "How far the glyphs are extruded along z."},
    {"spacing", A::Float, false, "1", "Times the font's advance from one glyph to the next."},
    CRT_ENTITY_ATTRS,
};
constexpr AttributeInfo kBlob[] = {
    {"threshold", A::Float, false, "1",
     "The solid is where the components' fields add up to more than this (> 0)."},
    {"components", A::BlobComponentList, true, "",
     "BlobSphere and BlobCylinder fields; a negative strength takes away."},
    CRT_ENTITY_ATTRS,
};
constexpr AttributeInfo kIsosurface[] = {
    {"function", A::Function, true, "",
     "f(x, y, z): the solid is where it is below the threshold."},
    {"bounds", A::Box, false, "Box { cornerA -> vec3(-1,-1,-1) cornerB -> vec3(1,1,1) }",
     "The box the surface is sought in; its faces close the solid where f is below the threshold."},
    {"threshold", A::Float, false, "0", "The value of f on the surface."},
    {"maxgradient", A::Float, false, "1.1",
     "How fast f may change per unit of length (> 0): too low leaves holes, too high is slow."},
    {"accuracy", A::Float, false, "0.001",
     "How short the spans are where a crossing is sought (> 0): thinner parts may be missed."},
    {"open", A::Bool, false, "false", "Without the faces of the bounds."},
    CRT_ENTITY_ATTRS,
};
constexpr AttributeInfo kHeightField[] = {
    {"image", A::String, false, "\"\"",
     "An image whose grey levels are the heights, its first row at z = 1; or give a function."},
    {"function", A::Function, false, "none",
     "f(x, 0, z), the height at (x, z), sampled on a grid of resolution points."},
    {"resolution", A::Int, false, "100",
     "For a function: how many samples along x, and as many along z (2 to 10,000)."},
    {"smooth", A::Bool, false, "false", "Normals interpolated across each cell."},
    CRT_ENTITY_ATTRS,
};
constexpr AttributeInfo kBlobSphere[] = {
    {"center", A::Vec3, true, "", "Centre."},
    {"radius", A::Float, true, "", "How far the field reaches (> 0)."},
    {"strength", A::Float, false, "1", "The field at the centre."},
};
constexpr AttributeInfo kBlobCylinder[] = {
    {"base", A::Vec3, true, "", "One end of the axis."},
    {"top", A::Vec3, true, "", "The other end."},
    {"radius", A::Float, true, "", "How far the field reaches from the axis (> 0)."},
    {"strength", A::Float, false, "1", "The field on the axis."},
};
constexpr AttributeInfo kSpline[] = {
    {"points", A::PointList, true, "", "The points the curve is made from, as `kind` reads them."},
    {"kind", A::Choice, false, "\"linear\"",
     "linear, quadratic, cubic, bezier (as a Lathe reads its points) or bspline.",
     scene::kSplineKindNames},
    {"times", A::FloatList, false, "[]",
     "When the curve is at each point between its segments, rising; [] for evenly from 0 to 1."},
};
constexpr AttributeInfo kTorus[] = {
    {"center", A::Vec3, true, "", "Centre."},
    {"major", A::Float, true, "", "Radius of the ring."},
    {"minor", A::Float, true, "", "Radius of the tube."},
    {"axis", A::Vec3, false, "vec3(0,1,0)", "Axis of the ring."},
    CRT_ENTITY_ATTRS,
};
constexpr AttributeInfo kSuperellipsoid[] = {
    {"e", A::Float, false, "1",
     "Exponent across z (east-west): toward 0 square, 1 round, above 2 pinched."},
    {"n", A::Float, false, "1",
     "Exponent along z (north-south): toward 0 square, 1 round, above 2 pinched."},
    CRT_ENTITY_ATTRS,
};
constexpr AttributeInfo kMerge[] = {
    {"objects", A::SolidList, true, "",
     "The solids to join; the surfaces inside the result are left out."},
    CRT_ENTITY_ATTRS,
};
constexpr AttributeInfo kInverse[] = {
    {"object", A::Solid, true, "", "The solid whose outside this is."},
    CRT_ENTITY_ATTRS,
};
constexpr AttributeInfo kClipped[] = {
    {"object", A::Entity, true, "", "The entity whose surfaces are kept where they are inside 'by'."},
    {"by", A::Solid, true, "", "The solid that keeps them."},
    CRT_ENTITY_ATTRS,
};
constexpr AttributeInfo kDisc[] = {
    {"center", A::Vec3, true, "", "Centre."},
    {"normal", A::Vec3, true, "", "Normal."},
    {"radius", A::Float, true, "", "Outer radius."},
    {"hole", A::Float, false, "0", "Inner radius."},
    CRT_ENTITY_ATTRS,
};
constexpr AttributeInfo kQuad[] = {
    {"corner", A::Vec3, true, "", "One corner."},
    {"edgeA", A::Vec3, true, "", "First edge from the corner."},
    {"edgeB", A::Vec3, true, "", "Second edge from the corner."},
    CRT_ENTITY_ATTRS,
};
constexpr AttributeInfo kTriangle[] = {
    {"a", A::Vec3, true, "", "First vertex."},
    {"b", A::Vec3, true, "", "Second vertex."},
    {"c", A::Vec3, true, "", "Third vertex."},
    CRT_ENTITY_ATTRS,
};
constexpr AttributeInfo kSmoothTriangle[] = {
    {"a", A::Vec3, true, "", "First vertex."},
    {"b", A::Vec3, true, "", "Second vertex."},
    {"c", A::Vec3, true, "", "Third vertex."},
    {"na", A::Vec3, true, "", "Normal at a."},
    {"nb", A::Vec3, true, "", "Normal at b."},
    {"nc", A::Vec3, true, "", "Normal at c."},
    CRT_ENTITY_ATTRS,
};
constexpr AttributeInfo kPolygon[] = {
    {"points", A::PointList, true, "",
     "The corners, in one plane; repeating a loop's first point closes it and starts the next "
     "(holes by the even-odd rule)."},
    CRT_ENTITY_ATTRS,
};
constexpr AttributeInfo kMesh[] = {
    {"file", A::String, false, "\"\"", "A Wavefront OBJ file; or give the vertices and faces."},
    {"vertices", A::PointList, false, "[]", "The corners, numbered from 0 (POV-Ray's mesh2)."},
    {"faces", A::FaceList, false, "[]", "Triangles: [a, b, c], three vertex numbers each."},
    {"normals", A::PointList, false, "[]", "A normal at each vertex, for smooth shading; [] for flat."},
    {"uvs", A::PointList, false, "[]", "A vec3(u, v, 0) at each vertex, for textures; [] for none."},
    CRT_ENTITY_ATTRS,
};

// What every pattern may take besides its own attributes (docs/language.md, "Textures").
// clang-format off
#define CRT_PATTERN_COLORS(defaultMap)                                                          \
    {"colors", A::ColorMap, false, defaultMap,                                                  \
     "The colour map: [[value, colour], ...], values from 0 to 1 in order."}
#define CRT_PATTERN_WAVE(defaultWave)                                                           \
    {"frequency", A::Float, false, "1", "The value becomes frac(value * frequency + phase)."},  \
    {"phase", A::Float, false, "0", "Added to the value times frequency."},                     \
    {"waveform", A::Choice, false, defaultWave,                                                 \
     "How the value is shaped: ramp, triangle, sine, scallop, cubic or poly.",                  \
     scene::kWaveformNames},                                                                    \
    {"exponent", A::Float, false, "1", "The poly waveform's exponent."}
#define CRT_PATTERN_TURBULENCE_STEPS                                                            \
    {"omega", A::Float, false, "0.5", "Each turbulence octave's amplitude over the last's."},   \
    {"lambda", A::Float, false, "2", "Each turbulence octave's frequency over the last's."}
#define CRT_PATTERN_TURBULENCE                                                                  \
    {"turbulence", A::Turbulence, false, "0",                                                   \
     "How far turbulence moves each point: a float, or a vec3 per axis."},                      \
    {"octaves", A::Int, false, "6", "Octaves of turbulence, 1 to 16."},                         \
    CRT_PATTERN_TURBULENCE_STEPS
// clang-format on
#define CRT_WHITE_BLACK "[[0, rgb(1, 1, 1)], [1, rgb(0, 0, 0)]]"
#define CRT_BLACK_WHITE "[[0, rgb(0, 0, 0)], [1, rgb(1, 1, 1)]]"
#define CRT_PATTERN_AB                                                                             \
    {"a", A::Color, false, "rgb(1,1,1)", "First colour (the map's stop at 0)."},                   \
        {"b", A::Color, false, "rgb(0,0,0)", "Second colour (the map's stop at 1)."},              \
        {"size", A::Float, false, "1", "Size of the pattern."},                                    \
        CRT_PATTERN_COLORS(CRT_WHITE_BLACK)
#define CRT_PATTERN(defaultMap)                                                                    \
    CRT_PATTERN_COLORS(defaultMap), CRT_PATTERN_WAVE("\"ramp\""), CRT_PATTERN_TURBULENCE

constexpr AttributeInfo kChecker[] = {CRT_PATTERN_AB, CRT_PATTERN_TURBULENCE};
constexpr AttributeInfo kStripes[] = {
    CRT_PATTERN_AB,
    {"axis", A::Vec3, false, "vec3(1,0,0)", "Direction across the stripes."},
    CRT_PATTERN_TURBULENCE,
};
constexpr AttributeInfo kNoise[] = {
    CRT_PATTERN_AB,
    {"octaves", A::Int, false, "4", "Layers of Perlin noise (and of turbulence), 1 to 16."},
    {"turbulence", A::Turbulence, false, "0",
     "How far turbulence moves each point: a float, or a vec3 per axis."},
    CRT_PATTERN_TURBULENCE_STEPS,
    CRT_PATTERN_WAVE("\"ramp\""),
};
constexpr AttributeInfo kMarble[] = {
    CRT_PATTERN_AB,
    {"turbulence", A::Float, false, "1", "How much the veins wander."},
    {"octaves", A::Int, false, "4", "Layers of noise."},
    CRT_PATTERN_WAVE("\"ramp\""),
};
constexpr AttributeInfo kWood[] = {
    CRT_PATTERN_AB,
    {"turbulence", A::Float, false, "0.1", "How much the rings wander."},
    {"rings", A::Float, false, "8", "Rings per unit."},
    CRT_PATTERN_WAVE("\"ramp\""),
};
constexpr AttributeInfo kGradient[] = {
    {"axis", A::Vec3, false, "vec3(1,0,0)",
     "The direction the value grows along, 0 to 1 per unit."},
    CRT_PATTERN(CRT_BLACK_WHITE),
};
constexpr AttributeInfo kPlainPattern[] = {CRT_PATTERN(CRT_BLACK_WHITE)};
constexpr AttributeInfo kFunctionPattern[] = {
    {"function", A::Function, true, "",
     "f(x, y, z), the pattern's value (above 1 and below 0 it wraps, as in POV-Ray)."},
    CRT_PATTERN(CRT_BLACK_WHITE),
};
constexpr AttributeInfo kSpiral[] = {
    {"arms", A::Int, true, "", "How many arms wind around the z axis."},
    CRT_PATTERN_COLORS(CRT_BLACK_WHITE),
    CRT_PATTERN_WAVE("\"triangle\""),
    CRT_PATTERN_TURBULENCE,
};
constexpr AttributeInfo kBrick[] = {
    {"bricksize", A::Vec3, false, "vec3(8,3,4.5)",
     "A brick's length (x), height (y) and depth (z)."},
    {"mortar", A::Float, false, "0.5", "The width of the joints."},
    CRT_PATTERN_COLORS("[[0, rgb(0.5, 0.5, 0.5)], [1, rgb(0.6, 0.15, 0.15)]]"),
    CRT_PATTERN_TURBULENCE,
};
constexpr AttributeInfo kHexagon[] = {
    CRT_PATTERN_COLORS("[[0, rgb(0, 0, 1)], [0.5, rgb(0, 1, 0)], [1, rgb(1, 0, 0)]]"),
    CRT_PATTERN_TURBULENCE,
};
constexpr AttributeInfo kQuilted[] = {
    {"control0", A::Float, false, "1", "The first inner control point of each quilt's curve."},
    {"control1", A::Float, false, "1", "The second inner control point of each quilt's curve."},
    CRT_PATTERN(CRT_BLACK_WHITE),
};
constexpr AttributeInfo kCrackle[] = {
    {"metric", A::Float, false, "2", "How distance is measured: 2 straight, 1 along the axes."},
    {"form", A::Vec3, false, "vec3(-1,1,0)",
     "Weights of the distances to the nearest, second and third feature point."},
    CRT_PATTERN(CRT_BLACK_WHITE),
};
constexpr AttributeInfo kSlope[] = {
    {"direction", A::Vec3, false, "vec3(0,1,0)",
     "0 where the surface faces away from it, 1 where it faces it (in world space)."},
    CRT_PATTERN(CRT_BLACK_WHITE),
};
constexpr AttributeInfo kBump[] = {
    {"pattern", A::Texture, true, "", "The pattern whose value is the surface's height."},
    {"strength", A::Float, false, "0.5", "Height of the bumps."},
};
constexpr AttributeInfo kMandel[] = {
    {"iterations", A::Int, true, "", "The most iterations before a point counts as inside."},
    CRT_PATTERN(CRT_BLACK_WHITE),
};
constexpr AttributeInfo kImage[] = {
    {"file", A::String, true, "", "The image."},
    {"mapping", A::Choice, false, "\"uv\"", "uv, planar, spherical, cylindrical or cubic.",
     kMappingChoices},
};
constexpr AttributeInfo kNoiseBump[] = {
    {"size", A::Float, false, "1", "Size of the bumps."},
    {"strength", A::Float, false, "0.5", "Height of the bumps."},
    {"octaves", A::Int, false, "4", "Layers of noise."},
};
constexpr AttributeInfo kImageBump[] = {
    {"file", A::String, true, "", "A grey-level height image."},
    {"strength", A::Float, false, "0.5", "Height of the bumps."},
    {"mapping", A::Choice, false, "\"uv\"", "uv, planar, spherical, cylindrical or cubic.",
     kMappingChoices},
};

using C = ObjectCategory;
using T = ObjectType;

constexpr ObjectInfo kObjects[] = {
    {T::Settings, "Settings", C::Settings, false, "How to render: camera, lights, image size.",
     kSettings},
    {T::Camera, "Camera", C::Camera, false,
     "A camera (pinhole, lens, spherical, orthographic, fisheye or cylindrical).", kCamera},
    {T::PointLight, "PointLight", C::Light, false, "A light shining from a point.", kPointLight},
    {T::ParallelLight, "ParallelLight", C::Light, false, "Parallel light, like the sun.",
     kParallelLight},
    {T::SpotLight, "SpotLight", C::Light, false, "A point light limited to a cone.", kSpotLight},
    {T::AreaLight, "AreaLight", C::Light, false, "A parallelogram that emits light (soft shadows).",
     kAreaLight},
    {T::CylinderLight, "CylinderLight", C::Light, false,
     "A segment that emits light, as a fluorescent tube.", kCylinderLight},
    {T::SphereLight, "SphereLight", C::Light, false, "A glowing sphere: soft shadows as round as it.",
     kSphereLight},
    {T::Material, "Material", C::Material, false, "How a surface looks.", kMaterial},
    {T::MaterialMap, "MaterialMap", C::Material, false,
     "Materials picked and mixed by a pattern's value.", kMaterialMap},
    {T::Layered, "Layered", C::Material, false,
     "Materials in layers, the ones below showing through each layer's alpha.", kLayered},
    {T::Background, "Background", C::Background, false, "What rays that hit nothing see.",
     kBackground},
    {T::Fog, "Fog", C::Fog, false,
     "Fog over the scene: constant, or ground fog thinning above an altitude (POV-Ray's fog).", kFog},
    {T::Medium, "Medium", C::Medium, false,
     "What fills a solid: it absorbs, scatters and gives off light along the rays through it.", kMedium},
    {T::Sphere, "Sphere", C::Entity, true, "A sphere (solid).", kSphere},
    {T::Box, "Box", C::Entity, true, "An axis-aligned box (solid).", kBox},
    {T::Plane, "Plane", C::Entity, true,
     "An infinite plane; as a solid, the half-space behind its normal.", kPlane},
    {T::Cylinder, "Cylinder", C::Entity, true, "A cylinder between two points (solid).", kCylinder},
    {T::Cone, "Cone", C::Entity, true, "A cone or truncated cone (solid).", kCone},
    {T::Torus, "Torus", C::Entity, true, "A torus (solid).", kTorus},
    {T::Superellipsoid, "Superellipsoid", C::Entity, true,
     "POV-Ray's superellipsoid in the cube from -1 to 1 (solid): a sphere, a rounded box, a "
     "cylinder or a star; move and size it with modifiers.",
     kSuperellipsoid},
    {T::Prism, "Prism", C::Entity, true,
     "An outline swept along y, straight or to a point (POV-Ray's prism; solid).", kPrism},
    {T::Sor, "Sor", C::Entity, true,
     "A smooth curve turned about the y axis, its radius squared a cubic of the height "
     "(POV-Ray's sor; solid).",
     kSor},
    {T::Lathe, "Lathe", C::Entity, true,
     "A curve turned about the y axis (POV-Ray's lathe; solid when the curve closes).", kLathe},
    {T::SphereSweep, "SphereSweep", C::Entity, true,
     "The solid a sphere fills as it moves along a curve, its radius changing (POV-Ray's "
     "sphere_sweep).",
     kSphereSweep},
    {T::Text, "Text", C::Entity, true,
     "A line of text in 3D: glyph outlines on the x-y plane, one unit an em, extruded along z "
     "(POV-Ray's text; solid).",
     kText},
    {T::Blob, "Blob", C::Entity, true,
     "Spheres and cylinders whose fields blend into one smooth shape (POV-Ray's blob; solid).",
     kBlob},
    {T::Isosurface, "Isosurface", C::Entity, true,
     "The solid where a Function of (x, y, z) is below a threshold, within a box (POV-Ray's "
     "isosurface).",
     kIsosurface},
    {T::HeightField, "HeightField", C::Entity, true,
     "Heights from 0 to 1 over the unit square of the x-z plane, from an image or a Function "
     "(POV-Ray's height_field; solid below its surface).",
     kHeightField},
    {T::Merge, "Merge", C::Entity, true,
     "A union of solids without the surfaces inside it (POV-Ray's merge): for glass and "
     "anything seen through.",
     kMerge},
    {T::Inverse, "Inverse", C::Entity, true,
     "Everything outside a solid (POV-Ray's inverse): its surface, facing inward.", kInverse},
    {T::Clipped, "Clipped", C::Entity, false,
     "An entity's surfaces where they lie inside a solid (POV-Ray's clipped_by): a surface, open "
     "where it was cut.",
     kClipped},
    {T::Disc, "Disc", C::Entity, false, "A flat disc, optionally with a hole.", kDisc},
    {T::Quad, "Quad", C::Entity, false, "A flat parallelogram.", kQuad},
    {T::Triangle, "Triangle", C::Entity, false, "A triangle.", kTriangle},
    {T::SmoothTriangle, "SmoothTriangle", C::Entity, false,
     "A triangle shaded with normals interpolated from its corners' (POV-Ray's smooth_triangle).",
     kSmoothTriangle},
    {T::Polygon, "Polygon", C::Entity, false, "A flat polygon, with holes (POV-Ray's polygon).",
     kPolygon},
    {T::Mesh, "Mesh", C::Entity, false,
     "A triangle mesh, from a Wavefront OBJ file or written in the script.", kMesh},
    {T::Checker, "Checker", C::Texture, false, "A 3D checker pattern.", kChecker},
    {T::Stripes, "Stripes", C::Texture, false, "Stripes across an axis.", kStripes},
    {T::Noise, "Noise", C::Texture, false, "Perlin noise between two colours.", kNoise},
    {T::Marble, "Marble", C::Texture, false, "Marble veins.", kMarble},
    {T::Wood, "Wood", C::Texture, false, "Wood rings.", kWood},
    {T::Image, "Image", C::Texture, false, "An image mapped onto the surface.", kImage},
    {T::NoiseBump, "NoiseBump", C::Texture, false, "Bumps from Perlin noise.", kNoiseBump},
    {T::ImageBump, "ImageBump", C::Texture, false, "Bumps from an image's grey levels.",
     kImageBump},
    {T::Gradient, "Gradient", C::Texture, false, "A value growing along an axis.", kGradient},
    {T::Onion, "Onion", C::Texture, false, "Concentric spheres, one per unit.", kPlainPattern},
    {T::Leopard, "Leopard", C::Texture, false, "Regular spots from sines of x, y and z.",
     kPlainPattern},
    {T::Radial, "Radial", C::Texture, false, "The angle around the y axis.", kPlainPattern},
    {T::Spiral, "Spiral", C::Texture, false, "Arms winding around the z axis.", kSpiral},
    {T::Brick, "Brick", C::Texture, false, "Bricks and mortar.", kBrick},
    {T::Hexagon, "Hexagon", C::Texture, false, "Hexagons of three colours in the x-z plane.",
     kHexagon},
    {T::Boxed, "Boxed", C::Texture, false, "1 at the origin, falling to 0 on a unit cube.",
     kPlainPattern},
    {T::Spherical, "Spherical", C::Texture, false,
     "1 at the origin, falling to 0 on a unit sphere.", kPlainPattern},
    {T::Cylindrical, "Cylindrical", C::Texture, false,
     "1 on the y axis, falling to 0 at distance 1 from it.", kPlainPattern},
    {T::Planar, "Planar", C::Texture, false, "1 on the x-z plane, falling to 0 at distance 1.",
     kPlainPattern},
    {T::Quilted, "Quilted", C::Texture, false, "Cushions filling each unit cube.", kQuilted},
    {T::Mandel, "Mandel", C::Texture, false, "The Mandelbrot set in the x-y plane.", kMandel},
    {T::Bozo, "Bozo", C::Texture, false, "Smooth noise: blotches.", kPlainPattern},
    {T::Spotted, "Spotted", C::Texture, false, "Smooth noise (POV-Ray's spotted, as Bozo).",
     kPlainPattern},
    {T::Granite, "Granite", C::Texture, false, "Sharp fractal noise, as of granite.",
     kPlainPattern},
    {T::Agate, "Agate", C::Texture, false, "Turbulent bands along z, as of agate.", kPlainPattern},
    {T::Wrinkles, "Wrinkles", C::Texture, false, "Ten octaves of noise: wrinkled.", kPlainPattern},
    {T::Dents, "Dents", C::Texture, false, "The cube of noise: dark dents in light.",
     kPlainPattern},
    {T::Crackle, "Crackle", C::Texture, false, "Cells around random points (Worley noise).",
     kCrackle},
    {T::Cells, "Cells", C::Texture, false, "A random value for each unit cube.", kPlainPattern},
    {T::Slope, "Slope", C::Texture, false, "The surface's slope against a direction.", kSlope},
    {T::Bump, "Bump", C::Texture, false, "Bumps from any pattern's value.", kBump},
    {T::Ripples, "Ripples", C::Texture, false,
     "Rings spreading from ten points near the origin, one unit apart (POV-Ray's ripples).",
     kPlainPattern},
    {T::Waves, "Waves", C::Texture, false,
     "Waves from ten points near the origin, each of its own length (POV-Ray's waves).",
     kPlainPattern},
    {T::FunctionPattern, "FunctionPattern", C::Texture, false,
     "A Function's value at each point, through a colour map (POV-Ray's function pattern).",
     kFunctionPattern},
    {T::BlobSphere, "BlobSphere", C::BlobComponent, false,
     "A Blob's spherical field: strength · (1 − (d / radius)²)² within radius of the centre.",
     kBlobSphere},
    {T::BlobCylinder, "BlobCylinder", C::BlobComponent, false,
     "A Blob's field about a segment, round at its ends: strength · (1 − (d / radius)²)².",
     kBlobCylinder},
    {T::Spline, "Spline", C::Spline, false,
     "A curve through space, for paths: spline(s, t) is its point at t (POV-Ray's spline).",
     kSpline},
};
static_assert(std::size(kObjects) == static_cast<size_t>(ObjectType::Count));
static_assert(std::size(kSettings) <= kMaxAttributes && std::size(kMaterial) <= kMaxAttributes);

} // namespace

const ObjectInfo& objectInfo(ObjectType type) { return kObjects[static_cast<size_t>(type)]; }

ObjectType findObjectType(std::string_view name) {
    for (const ObjectInfo& info : kObjects) {
        if (info.name == name && info.type != ObjectType::Settings) return info.type;
    }
    return ObjectType::Count;
}

int findAttribute(const ObjectInfo& info, std::string_view name) {
    if (name.empty()) return -1;
    if (info.type == ObjectType::Material && name == "refractiveindex") name = "ior";
    // Called for every attribute read while building objects: compare the cheap parts first.
    for (size_t i = 0; i < info.attributes.size(); ++i) {
        std::string_view candidate = info.attributes[i].name;
        if (candidate.size() == name.size() && candidate[0] == name[0] && candidate == name) {
            return static_cast<int>(i);
        }
    }
    return -1;
}

std::span<const ObjectInfo> allObjectTypes() { return kObjects; }

std::string solidTypeList() {
    std::vector<std::string_view> names;
    for (const ObjectInfo& info : kObjects)
        if (info.category == ObjectCategory::Entity && info.solid) names.push_back(info.name);
    std::string list;
    for (size_t i = 0; i < names.size(); ++i) {
        if (i > 0) list += i + 1 == names.size() ? " and " : ", ";
        list += names[i];
    }
    return list;
}

bool isBumpTexture(ObjectType type) {
    return type == ObjectType::NoiseBump || type == ObjectType::ImageBump ||
           type == ObjectType::Bump;
}

bool isColorTexture(ObjectType type) {
    return objectInfo(type).category == ObjectCategory::Texture && !isBumpTexture(type);
}

std::string_view attrTypeName(AttrType type) {
    switch (type) {
    case A::Float: return "float";
    case A::Int: return "int";
    case A::Bool: return "bool";
    case A::String: return "string";
    case A::Vec3: return "vec3";
    case A::Color: return "colour";
    case A::Choice: return "string";
    case A::Material: return "material";
    case A::Camera: return "camera";
    case A::Background: return "background or colour";
    case A::Fog: return "fog";
    case A::Medium: return "medium";
    case A::FloatOrPattern: return "float or pattern";
    case A::LightList: return "list of lights";
    case A::Texture: return "texture";
    case A::Bump: return "bump texture";
    case A::Gamma: return "float or \"srgb\"";
    case A::Aperture: return "aperture shape";
    case A::ColorMap: return "colour map";
    case A::Turbulence: return "float or vec3";
    case A::MaterialMap: return "material map";
    case A::MaterialList: return "list of materials";
    case A::PatternList: return "list of patterns";
    case A::Solid: return "solid";
    case A::Entity: return "entity";
    case A::SolidList: return "list of solids";
    case A::PointList: return "list of vec3";
    case A::BlobComponentList: return "list of blob components";
    case A::FloatList: return "list of floats";
    case A::FaceList: return "list of [a, b, c]";
    case A::Function: return "Function";
    case A::Box: return "Box";
    }
    return "value";
}

} // namespace crt::lang
