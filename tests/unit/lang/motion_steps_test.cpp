// Motion blur in the front end: with the shutter open the script is evaluated at each motion
// step, and what moves (modifiers, the camera) is joined into one scene; any other change is an
// error at what changed.
#include <catch2/catch.hpp>

#include "interpreter.hpp"

#include <sstream>
#include <string>

using namespace crt::lang;
namespace s = crt::scene;

namespace {

/// A lit scene whose shutter is open from t + 0.5 to t + 1.5, with three motion steps, its
/// camera at `camera` and its light at `light`.
Compilation compileWith(const std::string& body, const std::string& camera = "vec3(0, 0, -5)",
                        const std::string& light = "vec3(0, 5, -5)", EvalOptions options = {}) {
    const std::string text =
        "Settings { shutteropen -> 0.5 shutterclose -> 1.5 motionsteps -> 3\n"
        "  camera -> Camera { position -> " + camera + " pointing -> vec3(0, 0, 0) }\n"
        "  lights -> [PointLight { origin -> " + light + " color -> rgb(1, 1, 1) }] }\n";
    options.checkFiles = false;
    return compile("s.crt", text + body, options);
}

std::string errorsOf(const Compilation& c) {
    std::string all;
    for (const Diagnostic& d : c.diagnostics.items())
        if (d.severity == Severity::Error) all += d.message + "\n";
    return all;
}

} // namespace

TEST_CASE("a modifier that reads t moves across the shutter, step by step", "[motion]") {
    Compilation c = compileWith("Scene { Sphere { center -> vec3(0, 0, 0) radius -> 1 } <translate vec3(t, 0, 0), "
                                "rotate vec3(0, 90 * t, 0)> Box { cornerA -> vec3(2, 0, 0) cornerB -> vec3(3, 1, 1) } "
                                "<translate vec3(0, 1, 0)> }");
    INFO(errorsOf(c));
    REQUIRE(c.scene);
    const s::MotionDesc& motion = c.scene->motion;
    REQUIRE(motion.transforms.size() == 1); // the box stays where it is
    const auto& [entity, steps] = *motion.transforms.begin();
    CHECK(std::holds_alternative<s::TransformNode>(c.scene->entities[static_cast<size_t>(entity)].shape));
    // t is the frame's (0) plus 0.5, 1 and 1.5: the steps from the shutter's opening to its closing.
    REQUIRE(steps.size() == 3);
    for (size_t k = 0; k < 3; ++k) {
        const double t = 0.5 + 0.5 * static_cast<double>(k);
        REQUIRE(steps[k].size() == 2);
        CHECK(steps[k][0].kind == s::ModifierKind::Translate);
        CHECK(steps[k][0].value.x == t);
        CHECK(steps[k][1].value.y == 90 * t);
    }
    CHECK(motion.cameras.empty());
}

TEST_CASE("a camera that reads t moves; one that does not stays", "[motion]") {
    Compilation moving = compileWith("Scene { Sphere { center -> vec3(0, 0, 0) radius -> 1 } }",
                                     "vec3(t, 0, -5)");
    INFO(errorsOf(moving));
    REQUIRE(moving.scene);
    REQUIRE(moving.scene->motion.cameras.size() == 3);
    CHECK(moving.scene->motion.cameras[0].position.x == 0.5);
    CHECK(moving.scene->motion.cameras[2].position.x == 1.5);
    CHECK(moving.scene->motion.transforms.empty());

    Compilation still = compileWith("Scene { Sphere { center -> vec3(0, 0, 0) radius -> 1 } }");
    REQUIRE(still.scene);
    CHECK(still.scene->motion.empty());
}

TEST_CASE("what differs from the frame's t but not across the shutter is taken from the shutter", "[motion]") {
    // The shutter opens at t + 0.5 and the object jumps at t = 0.25: it is at its new place all
    // the while, and does not move.
    Compilation c = compileWith("Scene { Sphere { center -> vec3(0, 0, 0) radius -> 1 } "
                                "<translate vec3(t > 0.25 ? 3 : 0, 0, 0)> }");
    INFO(errorsOf(c));
    REQUIRE(c.scene);
    CHECK(c.scene->motion.empty());
    bool moved = false;
    for (const s::EntityDesc& e : c.scene->entities)
        if (auto* node = std::get_if<s::TransformNode>(&e.shape)) moved = node->modifiers.at(0).value.x == 3;
    CHECK(moved);
}

TEST_CASE("anything but modifiers and the camera changing across the shutter is an error at it", "[motion]") {
    Compilation radius = compileWith("Scene {\n  Sphere { center -> vec3(0, 0, 0) radius -> 1 + t } }");
    CHECK_FALSE(radius.scene);
    REQUIRE(radius.diagnostics.errorCount() == 1);
    const Diagnostic& d = radius.diagnostics.items().back();
    CHECK(d.message.find("this Sphere changes across the shutter (between t = 0 and t = 0.5)") != std::string::npos);
    const LineColumn at = radius.sources.file(0).lineColumn(d.range.begin);
    CHECK(at.line == 5);
    CHECK(at.column == 3);

    Compilation light = compileWith("Scene { Sphere { center -> vec3(0, 0, 0) radius -> 1 } }",
                                    "vec3(0, 0, -5)", "vec3(t, 5, -5)");
    CHECK_FALSE(light.scene);
    CHECK(errorsOf(light).find("this light changes across the shutter") != std::string::npos);

    Compilation color = compileWith(
        "Scene { Sphere { center -> vec3(0, 0, 0) radius -> 1 material -> Material { color -> rgb(t, 0, 0) } } }");
    CHECK_FALSE(color.scene);
    CHECK(errorsOf(color).find("this material changes across the shutter") != std::string::npos);

    Compilation appears = compileWith("Scene { if (t > 1) { Sphere { center -> vec3(0, 0, 0) radius -> 1 } } "
                                      "Box { cornerA -> vec3(2, 0, 0) cornerB -> vec3(3, 1, 1) } }");
    CHECK_FALSE(appears.scene);
    CHECK(errorsOf(appears).find("changes across the shutter") != std::string::npos);

    Compilation kinds = compileWith("ball = Sphere { center -> vec3(0, 0, 0) radius -> 1 }\nmoved = ball\n"
                                    "if (t > 1) { moved = ball <translate vec3(1, 0, 0)> } else { moved = ball <scale 2> }\n"
                                    "Scene { moved }");
    CHECK_FALSE(kinds.scene);
    CHECK(errorsOf(kinds).find("changes across the shutter") != std::string::npos);
}

TEST_CASE("an error at a motion step says at which", "[motion]") {
    Compilation c = compileWith("r = t > 1 ? sqrt(-1) : 1\nScene { Sphere { center -> vec3(0, 0, 0) radius -> r } }");
    CHECK_FALSE(c.scene);
    CHECK(errorsOf(c).find("at the motion step t = 1.5: ") != std::string::npos);
}

TEST_CASE("a motion step's print() is not printed again", "[motion]") {
    std::ostringstream out;
    EvalOptions options;
    options.printOut = &out;
    Compilation c = compileWith("print(\"once\")\nScene { Sphere { center -> vec3(0, 0, 0) radius -> 1 } <translate vec3(t, 0, 0)> }",
                                "vec3(0, 0, -5)", "vec3(0, 5, -5)", options);
    INFO(errorsOf(c));
    REQUIRE(c.scene);
    CHECK(out.str() == "once\n");
}

TEST_CASE("the command line's shutter opens the shutter the script left closed, or closes it", "[motion]") {
    EvalOptions options;
    options.checkFiles = false;
    options.shutter = std::pair{0.0, 2.0};
    Compilation opened = compile("s.crt", "Scene { Sphere { center -> vec3(0, 0, 0) radius -> 1 } <translate vec3(t, 0, 0)> }",
                                 options);
    INFO(errorsOf(opened));
    REQUIRE(opened.scene);
    REQUIRE(opened.scene->motion.transforms.size() == 1);
    const auto& steps = opened.scene->motion.transforms.begin()->second;
    REQUIRE(steps.size() == 2);
    CHECK(steps[1][0].value.x == 2);

    options.shutter = std::pair{0.0, 0.0};
    Compilation closed = compileWith("Scene { Sphere { center -> vec3(0, 0, 0) radius -> 1 } <translate vec3(t, 0, 0)> }",
                                     "vec3(0, 0, -5)", "vec3(0, 5, -5)", options);
    REQUIRE(closed.scene);
    CHECK_FALSE(closed.scene->settings.shutterIsOpen());
    CHECK(closed.scene->motion.empty());
}
