// Several spheres, analytic: the first valid boundary point over all of them (the D3D12
// sample's "multiple spheres"), each by ray_sphere (stable roots, Haines et al. discriminant).
//
//   float t; vec3 n;
//   if (ray_spheres(o, d, 1.0f, t_lo, t_hi, cull, t, n)) reportIntersectionEXT(t, 0u);
//
// The set is spheres_centre_radius(i), i < spheres_count, inside the box [-1, 1]^3 for
// radius_scale <= 1. Normals are outward and unit. `d` need not be unit length.
#ifndef PROCEDURAY_PRIMITIVES_SPHERES_GLSL
#define PROCEDURAY_PRIMITIVES_SPHERES_GLSL

#include "../common/compat.glsl"
#include "../common/hit.glsl"
#include "../common/ray.glsl"
#include "sphere.glsl"

const uint spheres_count = 3u;

/// Sphere i: xyz centre, w radius (before radius_scale).
PROCEDURAY_INLINE vec4 spheres_centre_radius(uint i) {
  if (i == 0u) return vec4(-0.3f, -0.3f, -0.3f, 0.6f);
  if (i == 1u) return vec4(0.1f, 0.1f, 0.4f, 0.3f);
  return vec4(0.35f, 0.35f, 0.0f, 0.15f);
}

/// First valid point of one sphere's boundary (entry, else exit) in [t_lo, t_hi].
PROCEDURAY_INLINE bool ray_sphere_first(vec3 o, vec3 d, vec3 centre, float radius, float t_lo, float t_hi, uint cull,
                                        PROCEDURAY_OUT(float) t_hit, PROCEDURAY_OUT(vec3) normal) {
  t_hit = 0.0f;
  normal = vec3(0.0f, 1.0f, 0.0f);
  float ta, tb;
  if (!(radius > 0.0f) || !ray_sphere(o, d, centre, radius, ta, tb)) return false;
  for (int k = 0; k < 2; ++k) {
    float t = k == 0 ? ta : tb;
    vec3 n = (o + t * d - centre) / radius;
    if (hit_is_valid(t, t_lo, t_hi, d, n, cull)) {
      t_hit = t;
      normal = safe_normalize(n, vec3(0.0f, 1.0f, 0.0f));
      return true;
    }
  }
  return false;
}

/// The nearest valid hit over the spheres, radii times radius_scale.
PROCEDURAY_INLINE bool ray_spheres(vec3 o, vec3 d, float radius_scale, float t_lo, float t_hi, uint cull,
                                   PROCEDURAY_OUT(float) t_hit, PROCEDURAY_OUT(vec3) normal) {
  bool found = false;
  t_hit = t_hi;
  normal = vec3(0.0f, 1.0f, 0.0f);
  for (uint i = 0u; i < spheres_count; ++i) {
    vec4 s = spheres_centre_radius(i);
    float t;
    vec3 n;
    if (ray_sphere_first(o, d, vec3(s.x, s.y, s.z), s.w * radius_scale, t_lo, t_hit, cull, t, n)) {
      found = true;
      t_hit = t;
      normal = n;
    }
  }
  if (!found) t_hit = 0.0f;
  return found;
}

#endif
