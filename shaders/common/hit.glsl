// Hit validation as the D3D12 sample's IsAValidHit: a candidate counts only when its t lies
// in the ray's [t_min, t_max] and the ray's cull flags do not reject its facing, so an
// intersection function can try its next candidate instead of reporting one the traversal drops.
//
//   uint cull = 0u;                                              // intersection shader (GLSL):
//   if ((gl_IncomingRayFlagsEXT & gl_RayFlagsCullBackFacingTrianglesEXT) != 0u) cull |= hit_cull_back;
//   if ((gl_IncomingRayFlagsEXT & gl_RayFlagsCullFrontFacingTrianglesEXT) != 0u) cull |= hit_cull_front;
//   if (hit_is_valid(t, gl_RayTminEXT, gl_RayTmaxEXT, d, n, cull)) { ... }   // n: outward normal
//
// Facing follows the normal: dot(d, n) < 0 is front facing (entering), > 0 back facing.
#ifndef PROCEDURAY_COMMON_HIT_GLSL
#define PROCEDURAY_COMMON_HIT_GLSL

#include "compat.glsl"

/// Cull bits: back-facing hits (the ray leaves through the surface) and front-facing hits.
PROCEDURAY_CONST uint hit_cull_back = 1u;
PROCEDURAY_CONST uint hit_cull_front = 2u;

/// Whether the cull bits reject a hit whose outward normal is n for a ray along d.
PROCEDURAY_INLINE bool hit_is_culled(pr_real3 d, pr_real3 n, uint cull) {
  pr_real dn = dot(d, n);
  return ((cull & hit_cull_back) != 0u && dn > PR(0.0)) || ((cull & hit_cull_front) != 0u && dn < PR(0.0));
}

/// t in [t_min, t_max] and not culled.
PROCEDURAY_INLINE bool hit_is_valid(pr_real t, pr_real t_min, pr_real t_max, pr_real3 d, pr_real3 n, uint cull) {
  return t >= t_min && t <= t_max && !hit_is_culled(d, n, cull);
}

#endif
