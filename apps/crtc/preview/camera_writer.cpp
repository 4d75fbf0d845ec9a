// The preview's camera as CRT source (see camera_writer.hpp).
#include "preview/camera_writer.hpp"

#include "diagnostic_printer.hpp"
#include "formatter.hpp"
#include "tracer/image_io/temporary_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

namespace crt::crtc::preview {

namespace fs = std::filesystem;
using namespace crt::lang;

namespace {

/// A CRT float literal: up to six decimals, trailing zeros dropped but one kept.
std::string number(double value) {
    std::string text = fmt::format("{:.6f}", std::isfinite(value) ? value : 0.0);
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') text += '0';
    return text == "-0.0" ? "0.0" : text;
}

std::string vector(const glm::dvec3& v) {
    return fmt::format("vec3({}, {}, {})", number(v.x), number(v.y), number(v.z));
}

std::string apertureShape(const scene::CameraDesc& camera) {
    switch (camera.apertureShape) {
    case scene::ApertureShape::Polygon: return std::to_string(camera.apertureBlades);
    case scene::ApertureShape::Gaussian: return "\"gaussian\"";
    case scene::ApertureShape::Line: return "\"line\"";
    case scene::ApertureShape::Circle: break;
    }
    return "\"circle\"";
}

/// The Settings blocks of the main script, wherever they are nested.
void findSettings(Node* node, std::vector<SettingsStmt*>& found) {
    if (node->kind == NodeKind::Settings) found.push_back(static_cast<SettingsStmt*>(node));
    forEachChild(node, [&](Node* child) { findSettings(child, found); });
}

/// Applies the formatter's edits (in order, non-overlapping) to `text`.
std::string applyEdits(std::string text, const std::vector<FormatEdit>& edits) {
    for (auto it = edits.rbegin(); it != edits.rend(); ++it) text.replace(it->begin, it->end - it->begin, it->replacement);
    return text;
}

/// Replaces bytes [begin, end) of `text` with `replacement` and re-indents the lines touched.
CameraEdit splice(const std::string& text, uint32_t begin, uint32_t end, const std::string& replacement) {
    CameraEdit edit;
    std::string changed = text.substr(0, begin) + replacement + text.substr(end);
    const auto changedEnd = static_cast<uint32_t>(begin + replacement.size());
    FormatResult formatted = formatSource(changed, {}, std::pair{begin, changedEnd});
    if (!formatted.ok) {
        edit.message = "the camera could not be formatted into the script: " + formatted.error;
        return edit;
    }
    edit.ok = true;
    edit.text = applyEdits(std::move(changed), formatted.edits);
    return edit;
}

} // namespace

std::string cameraLiteral(const scene::CameraDesc& camera, bool multiline) {
    std::vector<std::string> attributes{"position -> " + vector(camera.position),
                                        "pointing -> " + vector(camera.pointing), "fov -> " + number(camera.fov)};
    const scene::CameraDesc defaults;
    if (camera.up != defaults.up) attributes.push_back("up -> " + vector(camera.up));
    if (camera.roll != 0) attributes.push_back("roll -> " + number(camera.roll));
    if (camera.aperture > 0) {
        attributes.push_back("aperture -> " + number(camera.aperture));
        attributes.push_back("focaldistance -> " + number(camera.focalDistance));
        if (camera.apertureShape != scene::ApertureShape::Circle)
            attributes.push_back("apertureshape -> " + apertureShape(camera));
    }
    if (camera.projection != defaults.projection) {
        const std::string_view name = scene::kProjectionNames[static_cast<int>(camera.projection)];
        attributes.push_back(fmt::format("projection -> \"{}\"", name));
    }
    if (camera.width > 0) attributes.push_back("width -> " + number(camera.width));
    if (multiline) return fmt::format("Camera {{\n{}\n}}", fmt::join(attributes, "\n"));
    return fmt::format("Camera {{ {} }}", fmt::join(attributes, " "));
}

CameraEdit placeCamera(const std::string& path, const std::string& text, const scene::CameraDesc& camera,
                       const EvalOptions& options) {
    CameraEdit edit;
    Compilation c = compile(path, text, options, false);
    if (!c.resolved) {
        edit.message = "the script has syntax errors: fix them before writing the camera into it";
        return edit;
    }
    std::vector<SettingsStmt*> settings;
    for (Node* item : c.main.items) findSettings(item, settings);
    if (settings.size() != 1) {
        edit.message = settings.empty() ? "the script has no Settings block: paste the camera into one"
                                        : "the script has several Settings blocks: paste the camera into the one in use";
        return edit;
    }
    SettingsStmt& block = *settings.front();
    auto attribute = std::find_if(block.attributes.begin(), block.attributes.end(),
                                  [](const Attribute& a) { return a.name == "camera" && !a.overridden; });
    if (attribute == block.attributes.end()) {
        // A Settings block without a camera: add one right after its opening brace.
        const size_t brace = text.find('{', block.range.begin);
        if (brace == std::string::npos || brace >= block.range.end) {
            edit.message = "the script's Settings block has no '{'";
            return edit;
        }
        const auto at = static_cast<uint32_t>(brace + 1);
        CameraEdit added = splice(text, at, at, " camera -> " + cameraLiteral(camera));
        if (added.ok) added.message = "added the camera to the Settings block";
        return added;
    }
    const Expr* value = attribute->value;
    const SourceRange range = value->range;
    const auto* object = static_cast<const ObjectExpr*>(value);
    if (value->kind != NodeKind::Object || object->type != ObjectType::Camera) {
        const std::string_view source = std::string_view(text).substr(range.begin, range.end - range.begin);
        edit.message = fmt::format("the camera is set by '{}' at {}: copy the camera and paste it where that "
                                   "is defined",
                                   source.substr(0, 80), formatLocation(c.sources, range));
        return edit;
    }
    const bool multiline = text.find('\n', range.begin) < range.end;
    CameraEdit replaced = splice(text, range.begin, range.end, cameraLiteral(camera, multiline));
    if (replaced.ok) replaced.message = "replaced the camera at " + formatLocation(c.sources, range);
    return replaced;
}

bool replaceFile(const std::string& path, const std::string& text, std::string& error) {
    // The temporary crtc writes every output through: an unguessable name created with
    // O_EXCL | O_NOFOLLOW, removed by the stop handlers, renamed only once complete.
    tracer::image_io::TemporaryFile temporary(path, error);
    if (!temporary.ok()) {
        error = "cannot replace '" + path + "': " + error;
        return false;
    }
    {
        std::ofstream out(temporary.path(), std::ios::binary | std::ios::trunc);
        out << text;
        out.close();
        if (!out) {
            error = "cannot replace '" + path + "': the write failed";
            return false;
        }
    }
    // Keep the script's permissions: the rename replaces the file with the temporary one.
    std::error_code code;
    const fs::perms permissions = fs::status(path, code).permissions();
    if (!code) fs::permissions(temporary.path(), permissions, code);
    if (!temporary.commit(error)) {
        error = "cannot replace '" + path + "': " + error;
        return false;
    }
    return true;
}

} // namespace crt::crtc::preview
