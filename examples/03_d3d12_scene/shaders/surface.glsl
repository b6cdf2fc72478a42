// Lighting shared by plane.rchit and shade.rchit, the library's Whitted shading (shading/
// whitted.glsl) with this scene's rays: Phong, a shadow ray towards the point light
// (the sample's flags, declared with the ray in d3d12_scene.hpp: accept the first hit, skip
// closest hit, cull back faces), and one Schlick-weighted reflection in its own payload
// (trace_radiance's explicit-payload form), so `payload` is never touched. With D3D12_ITERATIVE
// (Tracing::iterative) nothing here traces: the terms go back in the payload for raygen's loop.
#ifndef D3D12_SURFACE_GLSL
#define D3D12_SURFACE_GLSL

#include "d3d12.glsl"
#include "common/ray.glsl"
#include "shading/whitted.glsl"

#ifndef D3D12_ITERATIVE
/// whitted.glsl's shadow ray.
float whitted_visibility(vec3 origin, vec3 dir, float dist) {
  return trace_shadow(origin, 0.0, dir, dist, ShadowPayload(1u)).occluded != 0u ? 0.0 : 1.0;
}

/// whitted.glsl's reflection (the sample has no cut-off by weight).
vec3 whitted_reflection(vec3 origin, vec3 dir, float weight) {
  RadiancePayload next = payload;
  next.colour = vec3(0.0);
  next.depth = payload.depth + 1u;
  next = trace_radiance(origin, 0.0, dir, ray_far, next);
  payload.nonfinite |= next.nonfinite;
  return next.colour;
}
#endif

/// Colour at world point p with world normal n; secondary rays start `offset` off the surface.
vec3 shade_surface(vec3 p, vec3 n, vec3 albedo, float reflectance, float offset) {
  vec3 v = -safe_normalize(gl_WorldRayDirectionEXT, n);
  n = whitted_facing(n, v);
  vec3 to_light = constants.light_position - p;
  float dist = length(to_light);
  vec3 l = safe_normalize(to_light, n);
  vec3 origin = offset_ray_origin(p + offset * n, n);
  // The sample's Phong: diffuse 0.9, specular 0.4, shininess 40.
  WhittedMaterial m = WhittedMaterial(albedo, 0.9, 0.4, 40.0, (constants.flags & flag_reflections) != 0u ? reflectance : 0.0);
#ifdef D3D12_ITERATIVE
  payload.direct = dot(n, l) > 0.0 || (constants.flags & flag_shadows) == 0u
                       ? whitted_phong(n, v, l, constants.light_colour, m)
                       : vec3(0.0);
  payload.light_distance = dot(n, l) > 0.0 ? dist : 0.0;
  payload.light_direction = l;
  payload.next_origin = origin;
  payload.next_direction = reflect(-v, n);
  payload.fresnel = whitted_fresnel(m, n, v);
  return constants.ambient * albedo;
#else
  vec3 colour = constants.ambient * albedo + whitted_direct(origin, n, v, l, dist, constants.light_colour, m,
                                                            (constants.flags & flag_shadows) != 0u);
  float f = payload.depth + 1u < min(constants.max_depth, max_depth_limit) ? whitted_fresnel(m, n, v) : 0.0;
  return whitted_reflect(colour, origin, n, v, f, 1.0, 0.0);
#endif
}

#endif
