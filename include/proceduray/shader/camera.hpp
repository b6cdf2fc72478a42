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

#include "proceduray/shader/camera-inl.hpp"  // the bodies (config.hpp)
