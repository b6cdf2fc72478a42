// Lighting shared by plane.rchit and shade.rchit: the library's Whitted shading (shading/
// whitted.glsl: Phong, a shadow ray towards the point light, the Schlick-weighted reflection),
// with this scene's shadow and reflection rays.
//
//   payload.colour = shade_surface(p, n, albedo, offset);
//
// With PAPER_ITERATIVE (PaperScene built with Tracing::iterative) nothing here traces: the
// ambient term is returned, and the unshadowed light term, the shadow ray's and the
// reflection's origin and directions, and the reflection's Fresnel share go back in the
// payload, for raygen's loop (raygen.rgen) to trace. The pixel is the same sum either way:
// local (1 - f) + f reflected, level by level.
//
// Needs the generated `constants`, `arguments` (MaterialRecord), `payload` (incoming radiance)
// and trace_shadow / trace_radiance, which trace with the flags the scene declares for each ray
// (paper_scene.hpp). The reflection goes out in its own payload: `payload` is never touched.
#ifndef PAPER_SURFACE_GLSL
#define PAPER_SURFACE_GLSL

#include "paper.glsl"
#include "common/ray.glsl"
#include "shading/whitted.glsl"

#ifndef PAPER_ITERATIVE
/// whitted.glsl's shadow ray: 1 when nothing lies between origin and origin + dist * dir, else 0.
float whitted_visibility(vec3 origin, vec3 dir, float dist) {
  // Started gl_HitTEXT behind the surface (tmin skips that stretch), so t, and the marching
  // threshold that grows with it, counts the whole path from the eye: the pixel's true footprint.
  float path = gl_HitTEXT;
  // occluded stays 1 unless the shadow miss shader runs
  ShadowPayload seen = trace_shadow(origin - path * dir, path, dir, path + dist, ShadowPayload(1u));
  return seen.occluded != 0u ? 0.0 : 1.0;
}

/// whitted.glsl's reflection: the colour a radiance ray from origin along dir brings back, one
/// level deeper, counting `weight` in the pixel.
vec3 whitted_reflection(vec3 origin, vec3 dir, float weight) {
  RadiancePayload next = payload;
  next.colour = vec3(0.0);
  next.depth = payload.depth + 1u;
  next.weight = weight;
  float path = gl_HitTEXT;  // as in whitted_visibility: t counts the path from the eye
  return trace_radiance(origin - path * dir, path, dir, path + ray_far, next).colour;
}
#endif

/// Colour at world point p with world normal n (either side); secondary rays start `offset`
/// off the surface (the hit threshold for marched surfaces; 0 for exact ones) plus a few ulps.
vec3 shade_surface(vec3 p, vec3 n, vec3 albedo, float offset) {
  vec3 v = -safe_normalize(gl_WorldRayDirectionEXT, n);
  n = whitted_facing(n, v);
  vec3 to_light = constants.light_position - p;
  float dist = length(to_light);
  vec3 l = safe_normalize(to_light, n);
  vec3 origin = offset_ray_origin(p + offset * n, n);
  WhittedMaterial m = WhittedMaterial(albedo, arguments.diffuse, arguments.specular, arguments.shininess,
                                      (constants.flags & flag_reflections) != 0u ? arguments.reflectance : 0.0);
#ifdef PAPER_ITERATIVE
  payload.direct = dot(n, l) > 0.0 || (constants.flags & flag_shadows) == 0u
                       ? whitted_phong(n, v, l, constants.light_colour, m)
                       : vec3(0.0);
  payload.light_distance = dot(n, l) > 0.0 ? dist : 0.0;
  payload.light_direction = l;
  payload.next_origin = origin;
  payload.hit_t = gl_HitTEXT;
  payload.next_direction = reflect(-v, n);
  payload.fresnel = whitted_fresnel(m, n, v);
  return constants.ambient * albedo;
#else
  vec3 colour = constants.ambient * albedo + whitted_direct(origin, n, v, l, dist, constants.light_colour, m,
                                                            (constants.flags & flag_shadows) != 0u);
  uint depth_max = min(constants.max_depth, max_depth_limit);
  float f = payload.depth + 1u < depth_max ? whitted_fresnel(m, n, v) : 0.0;
  return whitted_reflect(colour, origin, n, v, f, payload.weight, constants.min_weight);
#endif
}

#endif
