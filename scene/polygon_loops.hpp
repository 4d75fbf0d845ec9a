// A polygon's points as POV-Ray reads them: loops closed by repeating their first point,
// and the plane they span. Shared by the front end (which checks them) and the renderer.
#pragma once

#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace crt::scene {

/// The points split into closed loops: a loop ends where its first point comes again (that
/// repetition is not kept), and the last loop also where the list ends. Each loop's last
/// point joins its first.
std::vector<std::vector<glm::dvec3>> polygonLoops(std::span<const glm::dvec3> points);

/// Newell's normal of a closed loop: twice its area along the plane's normal, by the right-hand
/// rule of the loop's order; zero for a loop with no area.
glm::dvec3 newellNormal(std::span<const glm::dvec3> loop);

} // namespace crt::scene
