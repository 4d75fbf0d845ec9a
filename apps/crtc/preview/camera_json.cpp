// The camera as JSON (see camera_json.hpp).
#include "preview/camera_json.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace crt::crtc::preview {

namespace {

using nlohmann::json;

double finiteNumber(const json& value, const std::string& name) {
    if (!value.is_number() || !std::isfinite(value.get<double>()))
        throw std::invalid_argument(name + " must be a finite number");
    return value.get<double>();
}

glm::dvec3 vector(const json& value, const std::string& name) {
    if (!value.is_array() || value.size() != 3) throw std::invalid_argument(name + " must be an array of 3 numbers");
    return {finiteNumber(value[0], name), finiteNumber(value[1], name), finiteNumber(value[2], name)};
}

} // namespace

json cameraJson(const scene::CameraDesc& camera) {
    auto array = [](const glm::dvec3& v) { return json::array({v.x, v.y, v.z}); };
    return {{"position", array(camera.position)},
            {"pointing", array(camera.pointing)},
            {"up", array(camera.up)},
            {"fov", camera.fov},
            {"roll", camera.roll}};
}

scene::CameraDesc cameraFromJson(scene::CameraDesc camera, const json& value) {
    if (!value.is_object()) throw std::invalid_argument("the camera must be a JSON object");
    if (value.contains("position")) camera.position = vector(value["position"], "position");
    if (value.contains("pointing")) camera.pointing = vector(value["pointing"], "pointing");
    if (value.contains("up")) camera.up = vector(value["up"], "up");
    if (value.contains("fov")) {
        camera.fov = finiteNumber(value["fov"], "fov");
        if (camera.fov <= 0 || camera.fov >= 180) throw std::invalid_argument("fov must be in (0, 180)");
    }
    if (value.contains("roll")) camera.roll = finiteNumber(value["roll"], "roll");
    if (camera.position == camera.pointing) throw std::invalid_argument("position and pointing must differ");
    return camera;
}

} // namespace crt::crtc::preview
