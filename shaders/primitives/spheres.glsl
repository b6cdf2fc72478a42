// Several spheres, analytic: the first valid boundary point over all of them (the D3D12
// sample's "multiple spheres"), each by ray_sphere (stable roots, Haines et al. discriminant).
//
//   float t; vec3 n;
//   if (ray_spheres(o, d, 1.0f, t_lo, t_hi, cull, t, n)) reportIntersectionEXT(t, 0u);   // the sample's three
//   SphereList mine = sphere_list(constants.balls);     // any up to spheres_max: proceduray::SphereSet (sphere_set.glsl)
//   if (ray_spheres(o, d, mine, 1.0f, t_lo, t_hi, cull, t, n)) ...
//
// The sample's set is spheres_centre_radius(i), i < spheres_count, inside the box [-1, 1]^3 for
// radius_scale <= 1; a SphereList is any set, as data (its box: proceduray::sphere_set_bounds).
// Normals are outward and unit. `d` need not be unit length.
#ifndef PROCEDURAY_PRIMITIVES_SPHERES_GLSL
#define PROCEDURAY_PRIMITIVES_SPHERES_GLSL

#include "../common/compat.glsl"
#include "../common/hit.glsl"
#include "../common/ray.glsl"
#include "sphere.glsl"

PROCEDURAY_CONST uint spheres_count = 3u;  // the D3D12 sample's
/// Spheres a SphereList holds (proceduray::max_sphere_set).
PROCEDURAY_CONST uint spheres_max = 8u;

/// Spheres as data: sphere[i].xyz the centre, sphere[i].w the radius; the first `count` count.
struct SphereList {
  pr_real4 sphere[spheres_max];
  uint count;
};

/// Sphere i: xyz centre, w radius (before radius_scale).
PROCEDURAY_INLINE pr_real4 spheres_centre_radius(uint i) {
  if (i == 0u) return pr_real4(-PR(0.3), -PR(0.3), -PR(0.3), PR(0.6));
  if (i == 1u) return pr_real4(PR(0.1), PR(0.1), PR(0.4), PR(0.3));
  return pr_real4(PR(0.35), PR(0.35), PR(0.0), PR(0.15));
}

/// First valid point of one sphere's boundary (entry, else exit) in [t_lo, t_hi].
PROCEDURAY_INLINE bool ray_sphere_first(pr_real3 o, pr_real3 d, pr_real3 centre, pr_real radius, pr_real t_lo, pr_real t_hi, uint cull,
                                        PROCEDURAY_OUT(pr_real) t_hit, PROCEDURAY_OUT(pr_real3) normal) {
  t_hit = PR(0.0);
  normal = pr_real3(PR(0.0), PR(1.0), PR(0.0));
  pr_real ta, tb;
  if (!(radius > PR(0.0)) || !ray_sphere(o, d, centre, radius, ta, tb)) return false;
  for (int k = 0; k < 2; ++k) {
    pr_real t = k == 0 ? ta : tb;
    pr_real3 n = (o + t * d - centre) / radius;
    if (hit_is_valid(t, t_lo, t_hi, d, n, cull)) {
      t_hit = t;
      normal = safe_normalize(n, pr_real3(PR(0.0), PR(1.0), PR(0.0)));
      return true;
    }
  }
  return false;
}

/// The D3D12 sample's three spheres as a list.
PROCEDURAY_INLINE SphereList spheres_sample() {
  SphereList list;
  for (uint i = 0u; i < spheres_max; ++i) list.sphere[i] = i < spheres_count ? spheres_centre_radius(i) : pr_real4(PR(0.0));
  list.count = spheres_count;
  return list;
}

/// The nearest valid hit over the list's spheres (at most spheres_max), radii times radius_scale.
PROCEDURAY_INLINE bool ray_spheres(pr_real3 o, pr_real3 d, SphereList spheres, pr_real radius_scale, pr_real t_lo, pr_real t_hi,
                                   uint cull, PROCEDURAY_OUT(pr_real) t_hit, PROCEDURAY_OUT(pr_real3) normal) {
  bool found = false;
  t_hit = t_hi;
  normal = pr_real3(PR(0.0), PR(1.0), PR(0.0));
  for (uint i = 0u; i < min(spheres.count, spheres_max); ++i) {
    pr_real4 s = spheres.sphere[i];
    pr_real t;
    pr_real3 n;
    if (ray_sphere_first(o, d, pr_real3(s.x, s.y, s.z), s.w * radius_scale, t_lo, t_hit, cull, t, n)) {
      found = true;
      t_hit = t;
      normal = n;
    }
  }
  if (!found) t_hit = PR(0.0);
  return found;
}

/// The D3D12 sample's three spheres, radii times radius_scale.
PROCEDURAY_INLINE bool ray_spheres(pr_real3 o, pr_real3 d, pr_real radius_scale, pr_real t_lo, pr_real t_hi, uint cull,
                                   PROCEDURAY_OUT(pr_real) t_hit, PROCEDURAY_OUT(pr_real3) normal) {
  return ray_spheres(o, d, spheres_sample(), radius_scale, t_lo, t_hi, cull, t_hit, normal);
}

#endif
