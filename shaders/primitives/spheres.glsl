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

PROCEDURAY_CONST uint spheres_count = 3u;

/// Sphere i: xyz centre, w radius (before radius_scale).
PROCEDURAY_INLINE real4 spheres_centre_radius(uint i) {
  if (i == 0u) return real4(-R(0.3), -R(0.3), -R(0.3), R(0.6));
  if (i == 1u) return real4(R(0.1), R(0.1), R(0.4), R(0.3));
  return real4(R(0.35), R(0.35), R(0.0), R(0.15));
}

/// First valid point of one sphere's boundary (entry, else exit) in [t_lo, t_hi].
PROCEDURAY_INLINE bool ray_sphere_first(real3 o, real3 d, real3 centre, real radius, real t_lo, real t_hi, uint cull,
                                        PROCEDURAY_OUT(real) t_hit, PROCEDURAY_OUT(real3) normal) {
  t_hit = R(0.0);
  normal = real3(R(0.0), R(1.0), R(0.0));
  real ta, tb;
  if (!(radius > R(0.0)) || !ray_sphere(o, d, centre, radius, ta, tb)) return false;
  for (int k = 0; k < 2; ++k) {
    real t = k == 0 ? ta : tb;
    real3 n = (o + t * d - centre) / radius;
    if (hit_is_valid(t, t_lo, t_hi, d, n, cull)) {
      t_hit = t;
      normal = safe_normalize(n, real3(R(0.0), R(1.0), R(0.0)));
      return true;
    }
  }
  return false;
}

/// The nearest valid hit over the spheres, radii times radius_scale.
PROCEDURAY_INLINE bool ray_spheres(real3 o, real3 d, real radius_scale, real t_lo, real t_hi, uint cull,
                                   PROCEDURAY_OUT(real) t_hit, PROCEDURAY_OUT(real3) normal) {
  bool found = false;
  t_hit = t_hi;
  normal = real3(R(0.0), R(1.0), R(0.0));
  for (uint i = 0u; i < spheres_count; ++i) {
    real4 s = spheres_centre_radius(i);
    real t;
    real3 n;
    if (ray_sphere_first(o, d, real3(s.x, s.y, s.z), s.w * radius_scale, t_lo, t_hit, cull, t, n)) {
      found = true;
      t_hit = t;
      normal = n;
    }
  }
  if (!found) t_hit = R(0.0);
  return found;
}

#endif
