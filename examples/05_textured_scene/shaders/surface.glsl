// What the closest-hit shaders share: the library's Whitted shading over constants.lights, with
// this scene's shadow and reflection rays (which see the environment map when they miss).
#ifndef TEXTURED_SURFACE_GLSL
#define TEXTURED_SURFACE_GLSL

#include "shading/lights.glsl"

float whitted_visibility(vec3 origin, vec3 direction, float dist) {
  return trace_shadow(origin, 0.0, direction, dist, Shadow(1u)).occluded != 0u ? 0.0 : 1.0;
}

vec3 whitted_reflection(vec3 origin, vec3 direction, float weight) {
  return trace_radiance(origin, 0.0, direction, 1.0e30, Radiance(vec3(0.0), payload.depth + 1u, weight, 0u)).colour;
}

/// Shades world point p with world normal n by material m; with flag_normals, shows n instead.
void shade(vec3 p, vec3 n, Material material) {
  vec3 v = -safe_normalize(gl_WorldRayDirectionEXT, n);
  payload.id = material.id;
  if ((constants.flags & flag_normals) != 0u) {
    payload.colour = n * 0.5 + 0.5;
    return;
  }
  n = whitted_facing(n, v);
  vec3 origin = offset_ray_origin(p, n);
  WhittedMaterial m = WhittedMaterial(material.albedo, material.diffuse, material.specular, material.shininess,
                                      material.reflectance);
  vec3 colour = whitted_lights(constants.lights, origin, n, v, m, constants.ambient.rgb,
                               (constants.flags & flag_shadows) != 0u);
  uint depth_max = min(constants.max_depth, max_depth_limit);
  float f = payload.depth < depth_max ? whitted_fresnel(m, n, v) : 0.0;
  payload.colour = whitted_reflect(colour, origin, n, v, f, payload.weight, constants.min_weight);
}

/// The world normal of an object-space normal: the inverse transpose of the object-to-world transform.
vec3 world_normal(vec3 object_normal) {
  return safe_normalize(transpose(mat3(gl_WorldToObjectEXT)) * object_normal, -gl_WorldRayDirectionEXT);
}

#endif
