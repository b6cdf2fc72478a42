// Point and directional lights as the shading library (shaders/shading/whitted.glsl) reads them:
// registered structs, so a scene's uniform carries them and GLSL gets the same layout.
//
//   // a uniform's struct holds them: struct Constants { proceduray::Camera camera; proceduray::Lights lights; };
//   proceduray::Lights lights = proceduray::make_lights({proceduray::point_light({0, 4, 2}, glm::vec3(1.0f)),
//                                                        proceduray::directional_light({-1, 2, 1}, glm::vec3(0.3f))});
//   // GLSL: whitted_shade(constants.lights, ...) loops over lights.count of them
//
// make_lights refuses what would shade wrongly without a message: no light at all (every
// surface black but its ambient term), more than max_lights, a non-finite position or colour,
// a zero direction, a negative colour.
#pragma once

#include <proceduray/error.hpp>
#include <proceduray/shader/field_list.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>

namespace proceduray {

/// Light::kind values.
inline constexpr std::uint32_t light_point = 0;
inline constexpr std::uint32_t light_directional = 1;
/// Lights one Lights block holds (the GLSL loop's bound).
inline constexpr std::uint32_t max_lights = 4;

/// One light: a point light at `position`, or a directional one whose `position` is the
/// direction toward it (unit length).
struct Light {
  glm::vec3 position;
  std::uint32_t kind = light_point;
  glm::vec3 colour;
  float pad = 0.0f;
};
PROCEDURAY_STRUCT(Light, scalar, position, kind, colour, pad);

/// Up to max_lights lights; the shaders use the first `count`.
struct Lights {
  Light light[max_lights];
  std::uint32_t count = 0;
  std::uint32_t pad0 = 0, pad1 = 0, pad2 = 0;
};
PROCEDURAY_STRUCT(Lights, scalar, light, count, pad0, pad1, pad2);

inline Light point_light(glm::vec3 position, glm::vec3 colour) { return {position, light_point, colour}; }
/// A light infinitely far along `toward` (from the scene to the light); normalised by make_lights.
inline Light directional_light(glm::vec3 toward, glm::vec3 colour) { return {toward, light_directional, colour}; }

/// The lights as one block; throws UsageError naming the light and the fix for none, too many,
/// a non-finite position or colour, a zero direction, a negative colour, or an unknown kind.
inline Lights make_lights(std::span<const Light> lights) {
  if (lights.empty()) {
    throw UsageError("make_lights: 0 lights; shading needs at least one (every surface would be its ambient term "
                     "alone): add point_light(position, colour) or directional_light(toward, colour)");
  }
  if (lights.size() > max_lights) {
    throw UsageError("make_lights: " + std::to_string(lights.size()) + " lights, over the limit of " +
                     std::to_string(max_lights) + " (proceduray::max_lights); merge or drop lights");
  }
  const auto finite = [](glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
  Lights out;
  out.count = static_cast<std::uint32_t>(lights.size());
  for (std::size_t i = 0; i < lights.size(); ++i) {
    Light l = lights[i];
    const std::string which = "make_lights: light " + std::to_string(i);
    if (l.kind != light_point && l.kind != light_directional) {
      throw UsageError(which + " has kind " + std::to_string(l.kind) + "; use point_light or directional_light");
    }
    if (!finite(l.position) || !finite(l.colour)) {
      throw UsageError(which + " has a non-finite position, direction or colour (NaN or infinity); check the "
                       "values it is computed from");
    }
    if (l.colour.r < 0.0f || l.colour.g < 0.0f || l.colour.b < 0.0f) {
      throw UsageError(which + " has a negative colour (" + std::to_string(l.colour.r) + ", " +
                       std::to_string(l.colour.g) + ", " + std::to_string(l.colour.b) + "); use 0 or more");
    }
    if (l.kind == light_directional) {
      if (glm::dot(l.position, l.position) == 0.0f) {
        throw UsageError(which + " is directional with a zero direction; give the direction toward the light");
      }
      l.position = glm::normalize(l.position);
    }
    out.light[i] = l;
  }
  return out;
}
inline Lights make_lights(std::initializer_list<Light> lights) {
  return make_lights(std::span<const Light>(lights.begin(), lights.size()));
}

}  // namespace proceduray
