// Ray-box intersection with the boundary's normal: the slab test without IEEE infinities
// (a direction component at or below ray_parallel_epsilon counts as parallel, as in
// common/ray.glsl), returning the first valid boundary point, entry or exit.
//
//   float t; vec3 n;
//   if (ray_box(o, d, vec3(-0.5f), vec3(0.5f), t_lo, t_hi, cull, t, n)) reportIntersectionEXT(t, 0u);
//
// A ray starting inside the box finds where it leaves (a back face: cull bits may drop it).
// Normals are outward unit axis vectors. `d` need not be unit length.
#ifndef PROCEDURAY_PRIMITIVES_BOX_GLSL
#define PROCEDURAY_PRIMITIVES_BOX_GLSL

#include "../common/compat.glsl"
#include "../common/hit.glsl"
#include "../common/ray.glsl"

/// First boundary point of [box_min, box_max] along o + t d with t in [t_lo, t_hi] that the cull bits accept.
PROCEDURAY_INLINE bool ray_box(pr_real3 o, pr_real3 d, pr_real3 box_min, pr_real3 box_max, pr_real t_lo, pr_real t_hi, uint cull,
                               PROCEDURAY_OUT(pr_real) t_hit, PROCEDURAY_OUT(pr_real3) normal) {
  t_hit = PR(0.0);
  normal = pr_real3(PR(0.0), PR(1.0), PR(0.0));
  pr_real t_near = -PR(3.0e38);  // finite stand-ins for -inf and +inf
  pr_real t_far = PR(3.0e38);
  int near_axis = -1;
  int far_axis = -1;
  for (int i = 0; i < 3; ++i) {
    if (abs(d[i]) <= ray_parallel_epsilon) {
      if (o[i] < box_min[i] || o[i] > box_max[i]) return false;  // parallel and outside the slab
      continue;
    }
    pr_real inv = PR(1.0) / d[i];
    pr_real ta = (box_min[i] - o[i]) * inv;
    pr_real tb = (box_max[i] - o[i]) * inv;
    pr_real lo = min(ta, tb);
    pr_real hi = max(ta, tb);
    if (lo > t_near) { t_near = lo; near_axis = i; }
    if (hi < t_far) { t_far = hi; far_axis = i; }
  }
  if (!(t_near <= t_far)) return false;
  if (near_axis >= 0) {
    pr_real3 n = pr_real3(PR(0.0));
    n[near_axis] = d[near_axis] > PR(0.0) ? -PR(1.0) : PR(1.0);
    if (hit_is_valid(t_near, t_lo, t_hi, d, n, cull)) {
      t_hit = t_near;
      normal = n;
      return true;
    }
  }
  if (far_axis >= 0) {
    pr_real3 n = pr_real3(PR(0.0));
    n[far_axis] = d[far_axis] > PR(0.0) ? PR(1.0) : -PR(1.0);
    if (hit_is_valid(t_far, t_lo, t_hi, d, n, cull)) {
      t_hit = t_far;
      normal = n;
      return true;
    }
  }
  return false;
}

#endif
