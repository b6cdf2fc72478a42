// What ground.rchit and shade.rchit share: the library's Whitted shading over constants.lights,
// with this scene's shadow and reflection rays through the generated trace functions.
#ifndef CIS565_SURFACE_GLSL
#define CIS565_SURFACE_GLSL

#include "shading/lights.glsl"

float whitted_visibility(vec3 origin, vec3 direction, float dist) {
  return trace_shadow(origin, 0.0, direction, dist, Shadow(1u)).occluded != 0u ? 0.0 : 1.0;
}

vec3 whitted_reflection(vec3 origin, vec3 direction, float weight) {
  return trace_radiance(origin, 0.0, direction, 1.0e30, Radiance(vec3(0.0), payload.depth + 1u, weight, 0u)).colour;
}

/// Shades world point p with world normal n by the record's material.
void shade(vec3 p, vec3 n) {
  vec3 v = -safe_normalize(gl_WorldRayDirectionEXT, n);
  n = whitted_facing(n, v);
  vec3 origin = offset_ray_origin(p, n);
  WhittedMaterial m = WhittedMaterial(arguments.albedo, arguments.diffuse, arguments.specular, arguments.shininess,
                                      arguments.reflectance);
  vec3 colour = whitted_lights(constants.lights, origin, n, v, m, constants.ambient.rgb,
                               (constants.flags & flag_shadows) != 0u);
  // Depth counts radiance rays on the path: the camera ray is 1. The scene's limit bounds the
  // pipeline's recursion, so a frame asking for more is held to it.
  uint depth_max = min(constants.max_depth, max_depth_limit);
  float f = payload.depth < depth_max ? whitted_fresnel(m, n, v) : 0.0;
  payload.colour = whitted_reflect(colour, origin, n, v, f, payload.weight, constants.min_weight);
  payload.id = arguments.id;
}

#endif
