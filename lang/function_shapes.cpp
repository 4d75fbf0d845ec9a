// The shapes made from Functions and height maps: Isosurface and HeightField.
#include "interpreter_impl.hpp"
#include "object_builder.hpp"

namespace crt::lang {

/// The most samples a HeightField's function takes along each side.
constexpr int64_t kMaxHeightFieldResolution = 4096;

scene::Shape Interpreter::isosurfaceShape(ObjectBuilder& b) {
    auto desc = std::make_shared<scene::IsosurfaceDesc>();
    desc->function = functionProgram(b.get("function")->index);
    if (const Value* box = b.get("bounds")) {
        const auto& corners = std::get<scene::BoxShape>(scene_.entities[box->index].shape);
        entityInfo_[box->index].literal = false; // used up here: no "never drawn" warning
        desc->boundsMin = glm::min(corners.cornerA, corners.cornerB);
        desc->boundsMax = glm::max(corners.cornerA, corners.cornerB);
        if (glm::any(glm::equal(desc->boundsMin, desc->boundsMax)))
            fail(b.where("bounds"), "the bounds of an Isosurface must have a size along every axis");
    }
    desc->threshold = b.number("threshold", desc->threshold);
    desc->maxGradient = b.number("maxgradient", desc->maxGradient);
    desc->accuracy = b.number("accuracy", desc->accuracy);
    for (auto [name, value] : {std::pair{"maxgradient", desc->maxGradient}, {"accuracy", desc->accuracy}}) {
        if (!(value > 0) || !std::isfinite(value))
            fail(b.where(name), fmt::format("an Isosurface's {} must be above 0, not {:g}", name, value));
    }
    desc->open = b.flag("open", desc->open);
    desc->source = span(b.range);
    return scene::IsosurfaceShape{std::move(desc)};
}

scene::Shape Interpreter::heightFieldShape(ObjectBuilder& b) {
    auto desc = std::make_shared<scene::HeightFieldDesc>();
    desc->image = b.text("image", desc->image);
    const Value* function = b.get("function");
    if (function && !desc->image.empty()) {
        fail(b.where("function"), "a HeightField takes an image or a function, not both");
    }
    if (!function && desc->image.empty()) {
        fail(b.typeRange, "a HeightField needs an image or a function for its heights");
    }
    if (function) desc->function = functionProgram(function->index);
    if (!desc->image.empty()) desc->resolvedImage = findFile(b, "image", "image");
    const int64_t resolution = b.integer("resolution", desc->resolution);
    if (resolution < 2 || resolution > kMaxHeightFieldResolution) {
        fail(b.where("resolution"), fmt::format("a HeightField's resolution must be from 2 to {}, not {}",
                                                kMaxHeightFieldResolution, resolution));
    }
    desc->resolution = static_cast<int>(resolution);
    desc->smooth = b.flag("smooth", desc->smooth);
    return scene::HeightFieldShape{std::move(desc)};
}

} // namespace crt::lang
