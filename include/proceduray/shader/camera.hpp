// A pinhole camera as the shaders see it, and the host math that goes with it.
//
//   proceduray::Camera cam = proceduray::look_at({0, 2, 6}, {0, 0.5f, 0}, 45.0f, width, height);
//   // GLSL (shaders/common/camera.glsl, after the generated declarations):
//   //   vec3 dir = camera_ray(constants.camera, gl_LaunchIDEXT.xy, gl_LaunchSizeEXT.xy);
//   glm::ivec2 px = proceduray::project(cam, world_point, width, height);   // where it lands
//
// Pixel (x, y) looks along forward + u*right - v*up with u, v in (-1, 1) at pixel centres,
// x to the right and y down, so the image needs no flip.
#pragma once

#include <proceduray/config.hpp>
#include <proceduray/error.hpp>
#include <proceduray/shader/field_list.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace proceduray {

/// Eye position and the three view vectors, scaled so pixel centres map to (-1, 1).
struct Camera {
  glm::vec4 eye;      ///< xyz: position; w unused
  glm::vec4 forward;  ///< unit view direction
  glm::vec4 right;    ///< scaled by tan(fov_y / 2) * aspect
  glm::vec4 up;       ///< scaled by tan(fov_y / 2)
  float pixel_angle;  ///< angle one pixel subtends (radians): the footprint at distance t is pixel_angle * t
  float pad0, pad1, pad2;
};
PROCEDURAY_STRUCT(Camera, scalar, eye, forward, right, up, pixel_angle, pad0, pad1, pad2);

/// A camera at `eye` looking at `target` with vertical field of view `fov_y_degrees`; throws UsageError on degenerate input.
PROCEDURAY_DECL Camera look_at(glm::vec3 eye, glm::vec3 target, float fov_y_degrees, std::uint32_t width,
                               std::uint32_t height, glm::vec3 world_up = {0.0f, 1.0f, 0.0f});

/// The pixel a world point appears in (may lie outside the image); the inverse of camera_ray.
inline glm::ivec2 project(const Camera& c, glm::vec3 p, std::uint32_t width, std::uint32_t height) {
  const glm::vec3 v = p - glm::vec3(c.eye);
  const float z = glm::dot(v, glm::vec3(c.forward));
  const glm::vec3 r(c.right), u(c.up);
  const float x = glm::dot(v, r) / glm::dot(r, r) / z;
  const float y = glm::dot(v, u) / glm::dot(u, u) / z;
  return {static_cast<int>(std::floor((x + 1.0f) * 0.5f * static_cast<float>(width))),
          static_cast<int>(std::floor((1.0f - y) * 0.5f * static_cast<float>(height)))};
}

}  // namespace proceduray

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
