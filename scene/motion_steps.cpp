#include "scene/motion_steps.hpp"

#include "scene/scene_json.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace crt::scene {

namespace {

using Json = nlohmann::json;

/// The scene as JSON without its entities (compared apart), and without what the steps may
/// change or need not agree on: the time and settings (the frame's own evaluation gives
/// those) and the camera.
Json comparable(const SceneDesc& scene) {
    SceneDesc rest;
    rest.files = scene.files;
    rest.lights = scene.lights;
    rest.background = scene.background;
    rest.fog = scene.fog;
    rest.materials = scene.materials;
    rest.finishes = scene.finishes;
    rest.textures = scene.textures;
    rest.blends = scene.blends;
    rest.media = scene.media;
    rest.drawn = scene.drawn;
    return Json::parse(sceneToJson(rest, -1));
}

/// Whether entity i is the same in both but for the values of a transform node's modifiers.
bool sameEntity(const SceneDesc& base, const SceneDesc& step, size_t i) {
    const EntityDesc &a = base.entities[i], &b = step.entities[i];
    const auto* moved = std::get_if<TransformNode>(&a.shape);
    const auto* other = std::get_if<TransformNode>(&b.shape);
    if (!moved || !other) return a == b || entityToJson(base, i) == entityToJson(step, i);
    if (moved->child != other->child || moved->modifiers.size() != other->modifiers.size() ||
        a.material != b.material || a.solid != b.solid || a.hidden != b.hidden || !(a.source == b.source))
        return false;
    for (size_t k = 0; k < moved->modifiers.size(); ++k)
        if (moved->modifiers[k].kind != other->modifiers[k].kind) return false;
    return true;
}

SourceSpan spanOf(const Json& part) {
    SourceSpan span;
    if (!part.is_object() || !part.contains("source")) return span;
    const Json& s = part["source"];
    span.file = s.value("file", 0u);
    span.line = s.value("line", 0u);
    span.column = s.value("column", 0u);
    span.endLine = s.value("endLine", 0u);
    span.endColumn = s.value("endColumn", 0u);
    return span;
}

/// What a key of the scene JSON holds, as the conflict's message names one of its entries.
std::string entryName(const std::string& key, const Json& entry) {
    if (key == "entities") return fmt::format("this {}", entry.value("type", std::string("entity")));
    if (key == "lights") return "this light";
    if (key == "materials") return "this material";
    if (key == "textures") return "this pattern";
    if (key == "media") return "this medium";
    if (key == "blends") return "this material blend";
    return fmt::format("the scene's {}", key);
}

/// The first part that differs between the two scenes' comparable JSON.
MotionConflict firstDifference(const Json& base, const Json& step) {
    for (auto item = base.begin(); item != base.end(); ++item) {
        const Json* other = step.contains(item.key()) ? &step[item.key()] : nullptr;
        if (other && *other == item.value()) continue;
        if (other && item->is_array() && other->is_array() && item->size() == other->size())
            for (size_t i = 0; i < item->size(); ++i)
                if ((*item)[i] != (*other)[i]) return {spanOf((*item)[i]), entryName(item.key(), (*item)[i])};
        return {spanOf(item.value()), entryName(item.key(), item.value())};
    }
    return {{}, "the scene"}; // a part only the step has
}

/// Moves the base's value to the steps', where they differ: a list of one value when the
/// steps agree (nothing moves, but the frame's own value is not the shutter's), else every
/// step's.
template <typename T, typename Of>
std::vector<T> valuesAcross(const T& base, const std::vector<SceneDesc>& steps, Of of) {
    bool agree = true;
    for (const SceneDesc& step : steps) agree = agree && of(step) == of(steps.front());
    if (agree) return of(steps.front()) == base ? std::vector<T>{} : std::vector<T>{of(steps.front())};
    std::vector<T> values;
    for (const SceneDesc& step : steps) values.push_back(of(step));
    return values;
}

/// The camera's values that cannot go linearly from one step to the next.
bool sameCameraKind(const CameraDesc& a, const CameraDesc& b) {
    return a.projection == b.projection && a.apertureShape == b.apertureShape &&
           a.apertureBlades == b.apertureBlades;
}

} // namespace

double motionStepFraction(int step, int steps) {
    return steps > 1 ? static_cast<double>(step) / (steps - 1) : 0.0;
}

std::optional<MotionConflict> joinMotionSteps(SceneDesc& base, const std::vector<SceneDesc>& steps) {
    if (steps.empty()) return std::nullopt;
    const Json expected = comparable(base);
    for (const SceneDesc& step : steps) {
        std::optional<MotionConflict> conflict;
        for (size_t i = 0; i < base.entities.size() && i < step.entities.size() && !conflict; ++i)
            if (!sameEntity(base, step, i))
                conflict = MotionConflict{base.entities[i].source,
                                          entryName("entities", Json::parse(entityToJson(base, i)))};
        if (!conflict && base.entities.size() != step.entities.size())
            conflict = MotionConflict{{}, "the scene's entities"};
        if (!conflict) {
            const Json actual = comparable(step);
            if (actual != expected) conflict = firstDifference(expected, actual);
        }
        if (!conflict) continue;
        conflict->message = fmt::format("{} changes across the shutter (between t = {} and t = {}); only "
                                        "modifiers (translate, rotate, scale, matrix) and the camera may move",
                                        conflict->message, base.time, step.time);
        return conflict;
    }
    for (const SceneDesc& step : steps)
        if (!sameCameraKind(step.camera, steps.front().camera))
            return MotionConflict{base.camera.source, "the camera's projection or aperture shape changes across "
                                                      "the shutter; only its place, aim and lens may move"};

    MotionDesc motion;
    for (size_t i = 0; i < base.entities.size(); ++i) {
        auto* node = std::get_if<TransformNode>(&base.entities[i].shape);
        if (!node) continue;
        std::vector<std::vector<Modifier>> across =
            valuesAcross(node->modifiers, steps, [i](const SceneDesc& step) -> const std::vector<Modifier>& {
                return std::get<TransformNode>(step.entities[i].shape).modifiers;
            });
        if (across.size() == 1) node->modifiers = std::move(across.front());
        else if (!across.empty()) motion.transforms.emplace(static_cast<int32_t>(i), std::move(across));
    }
    std::vector<CameraDesc> cameras =
        valuesAcross(base.camera, steps, [](const SceneDesc& step) -> const CameraDesc& { return step.camera; });
    if (cameras.size() == 1) base.camera = cameras.front();
    else motion.cameras = std::move(cameras);
    base.motion = std::move(motion);
    return std::nullopt;
}

} // namespace crt::scene
