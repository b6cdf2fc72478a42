// Whitted shading over a block of lights (proceduray::Lights, shader/lights.hpp): ambient plus
// every light's Phong with its own shadow ray.
//
//   #include "shading/lights.glsl"        // after the generated declarations: needs Light, Lights
//   vec3 colour = whitted_lights(constants.lights, origin, n, v, m, constants.ambient.rgb, true);
//   colour = whitted_reflect(colour, origin, n, v, whitted_fresnel(m, n, v), payload.weight, 0.01);
//
// The Light and Lights structs come from the scene (a uniform holding proceduray::Lights), so
// the layout is the C++ one; make_lights refuses a block of 0 lights on the host.
#ifndef PROCEDURAY_SHADING_LIGHTS_GLSL
#define PROCEDURAY_SHADING_LIGHTS_GLSL

#include "../common/ray.glsl"
#include "whitted.glsl"

/// Light::kind (shader/lights.hpp).
const uint light_point = 0u;
const uint light_directional = 1u;

/// The unit direction from p toward light l, and its distance (1e30 for a directional light:
/// finite, since Vulkan need not honour IEEE infinities).
vec3 light_toward(Light l, vec3 p, out float dist) {
  if (l.kind == light_directional) {
    dist = 1.0e30;
    return l.position;
  }
  vec3 d = l.position - p;
  dist = length(d);
  return safe_normalize(d, vec3(0.0, 1.0, 0.0));
}

/// Ambient plus each light's whitted_direct, shadow rays from `origin` when `shadows`.
vec3 whitted_lights(Lights lights, vec3 origin, vec3 n, vec3 v, WhittedMaterial m, vec3 ambient, bool shadows) {
  vec3 colour = ambient * m.albedo;
  for (uint i = 0u; i < min(lights.count, uint(lights.light.length())); ++i) {
    float dist;
    vec3 l = light_toward(lights.light[i], origin, dist);
    colour += whitted_direct(origin, n, v, l, dist, lights.light[i].colour, m, shadows);
  }
  return colour;
}

#endif
