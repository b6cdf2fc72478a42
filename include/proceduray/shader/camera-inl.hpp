// The bodies of proceduray/shader/camera.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/shader/camera.hpp"

#if PROCEDURAY_BODIES
namespace proceduray {

PROCEDURAY_DECL Camera look_at(glm::vec3 eye, glm::vec3 target, float fov_y_degrees, std::uint32_t width,
                               std::uint32_t height, glm::vec3 world_up) {
  const auto finite = [](glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
  if (!finite(eye) || !finite(target) || !finite(world_up) || !std::isfinite(fov_y_degrees)) {
    // NaN compares false with everything, so it would pass the checks below and trace NaN rays.
    throw UsageError("look_at: eye (" + std::to_string(eye.x) + ", " + std::to_string(eye.y) + ", " +
                     std::to_string(eye.z) + "), target (" + std::to_string(target.x) + ", " + std::to_string(target.y) +
                     ", " + std::to_string(target.z) + "), up or fov " + std::to_string(fov_y_degrees) +
                     " is not finite (NaN or infinity); check the values the camera is computed from");
  }
  const glm::vec3 view = target - eye;
  const glm::vec3 side = glm::cross(view, world_up);
  if (width == 0 || height == 0 || !(fov_y_degrees > 0.0f && fov_y_degrees < 180.0f) ||
      glm::dot(view, view) == 0.0f || glm::dot(side, side) == 0.0f) {
    throw UsageError("look_at: camera from (" + std::to_string(eye.x) + ", " + std::to_string(eye.y) + ", " +
                     std::to_string(eye.z) + ") with fov " + std::to_string(fov_y_degrees) + " at " +
                     std::to_string(width) + "x" + std::to_string(height) +
                     " is degenerate; eye and target must differ, the view must not be parallel to up, "
                     "the fov must be in (0, 180) and the size positive");
  }
  const glm::vec3 forward = glm::normalize(view);
  const glm::vec3 right = glm::normalize(side);
  const glm::vec3 up = glm::cross(right, forward);
  const float tan_half = std::tan(glm::radians(fov_y_degrees) * 0.5f);
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  return {glm::vec4(eye, 1.0f), glm::vec4(forward, 0.0f), glm::vec4(right * tan_half * aspect, 0.0f),
          glm::vec4(up * tan_half, 0.0f), 2.0f * tan_half / static_cast<float>(height), 0, 0, 0};
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
