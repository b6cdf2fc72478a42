// Lighting shared by plane.rchit and shade.rchit: Phong, a shadow ray towards the point light
// (the sample's flags, declared with the ray in d3d12_scene.hpp: accept the first hit, skip
// closest hit, cull back faces), and one Schlick-weighted reflection in its own payload
// (trace_radiance's explicit-payload form), so `payload` is never touched. With D3D12_ITERATIVE
// (Tracing::iterative) nothing here traces: the terms go back in the payload for raygen's loop.
#ifndef D3D12_SURFACE_GLSL
#define D3D12_SURFACE_GLSL

#include "d3d12.glsl"
#include "common/ray.glsl"
#include "shading/phong.glsl"

#ifndef D3D12_ITERATIVE
float light_visibility(vec3 origin, vec3 dir, float dist) {
  return trace_shadow(origin, 0.0, dir, dist, ShadowPayload(1u)).occluded != 0u ? 0.0 : 1.0;
}

vec3 reflected_colour(vec3 origin, vec3 dir) {
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
  if (dot(n, v) < 0.0) n = -n;
  vec3 to_light = constants.light_position - p;
  float dist = length(to_light);
  vec3 l = safe_normalize(to_light, n);
  vec3 origin = offset_ray_origin(p + offset * n, n);
#ifdef D3D12_ITERATIVE
  payload.direct = dot(n, l) > 0.0 || (constants.flags & flag_shadows) == 0u
                       ? phong(albedo, n, l, v, constants.light_colour, 0.9, 0.4, 40.0)
                       : vec3(0.0);
  payload.light_distance = dot(n, l) > 0.0 ? dist : 0.0;
  payload.light_direction = l;
  payload.next_origin = origin;
  payload.next_direction = reflect(-v, n);
  payload.fresnel = (constants.flags & flag_reflections) != 0u && reflectance > 0.0 ? schlick_fresnel(reflectance, dot(n, v))
                                                                                    : 0.0;
  return constants.ambient * albedo;
#else
  float visible = 1.0;
  if ((constants.flags & flag_shadows) != 0u) visible = dot(n, l) > 0.0 ? light_visibility(origin, l, dist) : 0.0;
  vec3 colour = constants.ambient * albedo + visible * phong(albedo, n, l, v, constants.light_colour, 0.9, 0.4, 40.0);
  if ((constants.flags & flag_reflections) != 0u && reflectance > 0.0 &&
      payload.depth + 1u < min(constants.max_depth, max_depth_limit)) {
    float f = schlick_fresnel(reflectance, dot(n, v));
    colour = mix(colour, reflected_colour(origin, reflect(-v, n)), f);
  }
  return colour;
#endif
}

#endif
