// The end of an evaluation: what Settings names linked, unreachable objects dropped, warnings
// for what was defined but never used.
#include "object_builder.hpp"

#include "builtins.hpp"
#include "scene/entity_parts.hpp"

#include <algorithm>
#include <map>

namespace crt::lang {

namespace {

/// Removes what `keep` does not mark from `items`, returning old index -> new index.
template <typename T> std::vector<int32_t> compact(std::vector<T>& items, const std::vector<bool>& keep) {
    std::vector<int32_t> remap(items.size(), -1);
    size_t next = 0;
    for (size_t i = 0; i < items.size(); ++i) {
        if (!keep[i]) continue;
        remap[i] = static_cast<int32_t>(next);
        if (next != i) items[next] = std::move(items[i]);
        ++next;
    }
    items.resize(next);
    return remap;
}

} // namespace

void Interpreter::dropUnreachable(const std::vector<bool>& keepEntity,
                                  const std::vector<bool>& keepMaterial,
                                  const std::vector<bool>& keepTexture,
                                  const std::vector<bool>& keepBlend) {
    std::vector<int32_t> entityMap = compact(scene_.entities, keepEntity);
    std::vector<int32_t> materialMap = compact(scene_.materials, keepMaterial);
    std::vector<int32_t> textureMap = compact(scene_.textures, keepTexture);
    std::vector<int32_t> blendMap = compact(scene_.blends, keepBlend);
    for (scene::BlendDesc& blend : scene_.blends) {
        blend.pattern = blend.pattern >= 0 ? textureMap[static_cast<size_t>(blend.pattern)] : -1;
        for (int32_t& m : blend.materials) m = materialMap[static_cast<size_t>(m)];
    }
    for (scene::EntityDesc& entity : scene_.entities) {
        if (entity.material >= 0) entity.material = materialMap[static_cast<size_t>(entity.material)];
        scene::forEachPart(entity, [&](int32_t& child) { child = entityMap[static_cast<size_t>(child)]; });
    }
    for (int32_t& root : scene_.drawn) root = entityMap[static_cast<size_t>(root)];
    // A finish of dropped materials only may name a dropped texture or blend: it becomes -1,
    // unused.
    for (scene::FinishDesc& finish : scene_.finishes) {
        if (finish.texture >= 0) finish.texture = textureMap[static_cast<size_t>(finish.texture)];
        if (finish.bump >= 0) finish.bump = textureMap[static_cast<size_t>(finish.bump)];
        if (finish.blend >= 0) finish.blend = blendMap[static_cast<size_t>(finish.blend)];
    }
}

void Interpreter::assembleScene() {
    if (!settings_) {
        // Without a Settings statement its defaults still have to fit the limits (--max-size).
        buildSettings(ObjectBuilder{*this, objectInfo(ObjectType::Settings), {0, 0, 0}, {0, 0, 0}});
    }
    reportSettingsProblems();
    if (diagnostics_.hasErrors()) throw EvalError{};
    linkSettings();
    keepReachable();
    for (uint32_t i = 0; i < compilation_.sources.fileCount(); ++i) {
        scene_.files.push_back(compilation_.sources.file(i).path());
    }
    scene_.time = prelude_[preludeSlotOfT()].asDouble();
    scene_.frame = options_.frame;
    scene_.frameCount = options_.frameCount;
    scene_.limits = options_.limits.render;
}

void Interpreter::reportSettingsProblems() {
    for (DeferredError& problem : settingsProblems_)
        diagnostics_.error(problem.where, std::move(problem.message));
    settingsProblems_.clear();
}

void Interpreter::linkSettings() {
    if (settingsLinks_.camera) scene_.camera = cameras_[*settingsLinks_.camera];
    if (settingsLinks_.lights) {
        for (const Value& light : *settingsLinks_.lights) {
            lightInfo_[light.index].listed = true;
            scene_.lights.push_back(lights_[light.index]);
        }
    }
    if (const std::optional<Value>& background = settingsLinks_.background) {
        if (background->kind == ValueKind::Color) {
            scene_.background.kind = scene::BackgroundKind::Solid;
            scene_.background.color = {background->v[0], background->v[1], background->v[2], background->v[3]};
            scene_.background.source = span(settingsLinks_.backgroundRange);
        } else {
            scene_.background = backgrounds_[background->index];
        }
    }
    if (settingsLinks_.fog) scene_.fog = fogs_[*settingsLinks_.fog];
}

void Interpreter::keepReachable() {
    // Keep only what the drawn entities reach, so consumers see no dead objects.
    std::vector<bool> keepEntity(scene_.entities.size(), false);
    std::vector<int32_t> pending(scene_.drawn.begin(), scene_.drawn.end());
    while (!pending.empty()) {
        int32_t index = pending.back();
        pending.pop_back();
        if (keepEntity[static_cast<size_t>(index)]) continue;
        keepEntity[static_cast<size_t>(index)] = true;
        scene::forEachPart(scene_.entities[static_cast<size_t>(index)], [&](int32_t child) { pending.push_back(child); });
    }
    std::vector<bool> keepMaterial(scene_.materials.size(), false);
    for (size_t i = 0; i < scene_.entities.size(); ++i) {
        if (keepEntity[i] && scene_.entities[i].material >= 0) keepMaterial[static_cast<size_t>(scene_.entities[i].material)] = true;
    }
    // A material made of others keeps them, and the pattern that mixes them.
    std::vector<bool> keepTexture(scene_.textures.size(), false);
    std::vector<bool> keepBlend(scene_.blends.size(), false);
    std::vector<int32_t> pendingMaterials;
    for (size_t i = 0; i < scene_.materials.size(); ++i) {
        if (keepMaterial[i]) pendingMaterials.push_back(static_cast<int32_t>(i));
    }
    while (!pendingMaterials.empty()) {
        const scene::FinishDesc& finish =
            scene_.finishOf(scene_.materials[static_cast<size_t>(pendingMaterials.back())]);
        pendingMaterials.pop_back();
        for (int32_t t : {finish.texture, finish.bump}) {
            if (t >= 0) keepTexture[static_cast<size_t>(t)] = true;
        }
        if (finish.blend < 0) continue;
        keepBlend[static_cast<size_t>(finish.blend)] = true;
        const scene::BlendDesc& blend = scene_.blends[static_cast<size_t>(finish.blend)];
        if (blend.pattern >= 0) keepTexture[static_cast<size_t>(blend.pattern)] = true;
        for (int32_t m : blend.materials) {
            if (keepMaterial[static_cast<size_t>(m)]) continue;
            keepMaterial[static_cast<size_t>(m)] = true;
            pendingMaterials.push_back(m);
        }
    }
    reachable_ = keepEntity;
    // Usually everything is reachable, and there is nothing to renumber.
    auto allTrue = [](const std::vector<bool>& keep) { return std::find(keep.begin(), keep.end(), false) == keep.end(); };
    if (!allTrue(keepEntity) || !allTrue(keepMaterial) || !allTrue(keepTexture) ||
        !allTrue(keepBlend)) {
        dropUnreachable(keepEntity, keepMaterial, keepTexture, keepBlend);
    }
}

void Interpreter::reportUnused() {
    for (uint32_t slot = 0; slot < globals_.size(); ++slot) {
        const GlobalTable::Entry& entry = globals_.entry(slot);
        if (entry.assigned && entry.reportUnused && !entry.read) {
            diagnostics_.warning(WarningKind::UnusedVariable, entry.firstAssignment,
                                 fmt::format("variable '{}' is assigned but never used", entry.name));
        }
    }
    // A literal run many times (in a loop or a macro) is used if any of its values is:
    // one warning per literal of the main script, in source order. Usually every value is
    // used, so a first pass only collects the literals with an unused value (by where they
    // begin); only those are looked at again, for a used value and their first one.
    auto isMainLiteral = [](const EntityInfo& info) { return info.literal && info.range.file == 0; };
    std::vector<uint32_t> suspects;
    for (size_t i = 0; i < entityInfo_.size(); ++i) {
        const EntityInfo& info = entityInfo_[i];
        if (!isMainLiteral(info) || reachable_[i] || info.outsideScene) continue;
        if (suspects.empty() || suspects.back() != info.range.begin) suspects.push_back(info.range.begin);
    }
    std::sort(suspects.begin(), suspects.end());
    suspects.erase(std::unique(suspects.begin(), suspects.end()), suspects.end());
    std::vector<const EntityInfo*> firstValue(suspects.size(), nullptr);
    std::vector<bool> used(suspects.size(), false);
    if (!suspects.empty()) {
        for (size_t i = 0; i < entityInfo_.size(); ++i) {
            const EntityInfo& info = entityInfo_[i];
            if (!isMainLiteral(info)) continue;
            auto at = std::lower_bound(suspects.begin(), suspects.end(), info.range.begin);
            if (at == suspects.end() || *at != info.range.begin) continue;
            size_t k = static_cast<size_t>(at - suspects.begin());
            if (!firstValue[k]) firstValue[k] = &info;
            if (reachable_[i] || info.outsideScene) used[k] = true;
        }
    }
    for (size_t k = 0; k < suspects.size(); ++k) {
        if (used[k]) continue;
        diagnostics_.warning(WarningKind::EntityNeverDrawn, firstValue[k]->range,
                             fmt::format("this {} is defined but never drawn nor used",
                                         objectInfo(firstValue[k]->type).name));
    }
    // Lights likewise: a literal shines if any of its values is listed. By source order.
    std::map<uint32_t, std::pair<const LightInfo*, bool>> lightLiterals;
    for (const LightInfo& info : lightInfo_) {
        if (info.range.file != 0) continue;
        auto& [first, listed] = lightLiterals.try_emplace(info.range.begin, &info, false).first->second;
        listed = listed || info.listed;
    }
    for (const auto& [begin, literal] : lightLiterals) {
        const auto& [info, listed] = literal;
        if (listed) continue;
        diagnostics_.warning(WarningKind::UnusedLight, info->range,
                             fmt::format("this {} does not shine: it is not in Settings.lights",
                                         objectInfo(info->type).name));
    }
    const bool warnedOutside =
        std::any_of(entityInfo_.begin(), entityInfo_.end(),
                    [](const EntityInfo& info) { return info.outsideScene; });
    if (scene_.drawn.empty() && !warnedOutside) {
        diagnostics_.warning(WarningKind::EmptyScene, {0, 0, 0},
                             "the script draws nothing; only the background will be rendered");
    }
    if (!scene_.drawn.empty() && !sceneIsLit()) {
        diagnostics_.warning(WarningKind::NoLights, unlitSceneRange(),
                             "nothing lights the scene: it has no lights, no ambient light and "
                             "nothing that glows; add a light to Settings { lights -> [...] }");
    }
}

SourceRange Interpreter::unlitSceneRange() const {
    // The keyword alone: the block may be long.
    auto keyword = [](const Node* block, std::string_view word) {
        return SourceRange{block->range.file, block->range.begin,
                           block->range.begin + static_cast<uint32_t>(word.size())};
    };
    if (settings_) return keyword(settings_, "Settings");
    for (const Node* item : compilation_.main.items)
        if (item->kind == NodeKind::Scene) return keyword(item, "Scene");
    return {0, 0, 0};
}

bool Interpreter::sceneIsLit() const {
    const scene::Color& ambient = scene_.settings.ambient;
    if (!scene_.lights.empty() || ambient.r > 0 || ambient.g > 0 || ambient.b > 0) return true;
    // Under the path integrator the background lights what it surrounds.
    const scene::BackgroundDesc& sky = scene_.background;
    const bool dark = sky.kind == scene::BackgroundKind::Solid && sky.color.r <= 0 && sky.color.g <= 0 && sky.color.b <= 0;
    if (scene_.settings.integrator == scene::Integrator::Path && !dark) return true;
    // The materials left are those the drawn entities use.
    return std::any_of(scene_.materials.begin(), scene_.materials.end(),
                       [&](const scene::MaterialDesc& m) {
                           const scene::Color& glow = scene_.finishOf(m).emission;
                           return glow.r > 0 || glow.g > 0 || glow.b > 0;
                       });
}

} // namespace crt::lang
