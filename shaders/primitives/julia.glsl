// Quaternion Julia set (the 3D slice w = 0 of {z : z_{n+1} = z_n^2 + c stays bounded}),
// optionally cut by a plane, as a distance estimate for sphere tracing.
//
//   float d = julia_distance(p, c, 10u);                      // > 0 outside, 0 inside
//   float d_cut = julia_cut_distance(p, c, 10u, plane);       // keeps dot(plane.xyz, p) <= plane.w
//   float d_cuts = julia_cuts_distance(p, c, 10u, cuts.plane[0], cuts.plane[1], cuts.count);   // proceduray::CutPlanes
//   uint face = julia_cut_face(p, c, 10u, cuts.plane[0], cuts.plane[1], cuts.count);   // the plane p lies on, or 2
//   vec4 c = julia_animated_c(time);                          // the constant at a given time
//
// The estimate is Hart, Sandin and Kauffman's (1989): d = 0.5 |z| ln|z| / |z'|, with the
// derivative z' carried as a quaternion (z' <- 2 z z', z'_0 = 1), so it is a lower bound of
// the distance only asymptotically: march with a step scale <= 1. Points whose orbit does not
// escape within `iterations` are inside the truncated set and get 0, which also makes the cut
// face exact: there max(0, d_plane) = d_plane. The bailout |z| > 16 keeps ln|z| > 0, and |z'|
// is floored, so no log of <= 0 and no division by 0. Quaternions are vec4(real part, i, j, k).
#ifndef PROCEDURAY_PRIMITIVES_JULIA_GLSL
#define PROCEDURAY_PRIMITIVES_JULIA_GLSL

#include "../common/compat.glsl"

/// Quaternion product a b.
PROCEDURAY_INLINE pr_real4 quat_mul(pr_real4 a, pr_real4 b) {
  return pr_real4(a.x * b.x - a.y * b.y - a.z * b.z - a.w * b.w,
              a.x * b.y + a.y * b.x + a.z * b.w - a.w * b.z,
              a.x * b.z - a.y * b.w + a.z * b.x + a.w * b.y,
              a.x * b.w + a.y * b.z - a.z * b.y + a.w * b.x);
}

/// Quaternion square a a (cheaper than quat_mul(a, a)).
PROCEDURAY_INLINE pr_real4 quat_square(pr_real4 a) {
  return pr_real4(a.x * a.x - a.y * a.y - a.z * a.z - a.w * a.w, PR(2.0) * a.x * a.y, PR(2.0) * a.x * a.z, PR(2.0) * a.x * a.w);
}

/// Escape radius: |z| beyond it diverges; large enough that the estimate is accurate.
PROCEDURAY_CONST pr_real julia_bailout = PR(16.0);

/// Distance estimate to the Julia set of c after `iterations` steps (0 inside).
PROCEDURAY_INLINE pr_real julia_distance(pr_real3 p, pr_real4 c, uint iterations) {
  pr_real4 z = pr_real4(p.x, p.y, p.z, PR(0.0));
  pr_real4 dz = pr_real4(PR(1.0), PR(0.0), PR(0.0), PR(0.0));
  bool escaped = false;
  for (uint i = 0u; i < iterations; ++i) {
    dz = PR(2.0) * quat_mul(z, dz);
    z = quat_square(z) + c;
    if (dot(z, z) > julia_bailout * julia_bailout) {
      escaped = true;
      break;
    }
  }
  if (!escaped) return PR(0.0);
  pr_real r = length(z);
  return PR(0.5) * r * log(r) / max(length(dz), PR(1.0e-20));
}

/// The Julia set intersected with the half-space dot(plane.xyz, p) <= plane.w (plane.xyz unit).
PROCEDURAY_INLINE pr_real julia_cut_distance(pr_real3 p, pr_real4 c, uint iterations, pr_real4 plane) {
  pr_real d_plane = dot(pr_real3(plane.x, plane.y, plane.z), p) - plane.w;
  return max(julia_distance(p, c, iterations), d_plane);
}

/// Signed distance to the half-space dot(plane.xyz, p) <= plane.w (plane.xyz unit).
PROCEDURAY_INLINE pr_real julia_plane_distance(pr_real3 p, pr_real4 plane) {
  return dot(pr_real3(plane.x, plane.y, plane.z), p) - plane.w;
}

/// The Julia set cut by the first `count` (0 to 2) of two planes (proceduray::CutPlanes): data
/// from a uniform or record, so a cut moves without a shader edit.
PROCEDURAY_INLINE pr_real julia_cuts_distance(pr_real3 p, pr_real4 c, uint iterations, pr_real4 cut0, pr_real4 cut1, uint count) {
  pr_real d = julia_distance(p, c, iterations);
  if (count >= 1u) d = max(d, julia_plane_distance(p, cut0));
  if (count >= 2u) d = max(d, julia_plane_distance(p, cut1));
  return d;
}

/// Which cut face p lies on (0 or 1: its plane's distance is the largest term of
/// julia_cuts_distance, so the normal there is the plane's, exactly), or 2 when none.
PROCEDURAY_INLINE uint julia_cut_face(pr_real3 p, pr_real4 c, uint iterations, pr_real4 cut0, pr_real4 cut1, uint count) {
  pr_real d = julia_distance(p, c, iterations);
  pr_real d0 = count >= 1u ? julia_plane_distance(p, cut0) : d - PR(1.0);
  pr_real d1 = count >= 2u ? julia_plane_distance(p, cut1) : d - PR(1.0);
  if (d0 >= d && d0 >= d1) return 0u;
  if (d1 >= d && d1 > d0) return 1u;
  return 2u;
}

/// The animated constant: c(0) = (-0.2, 0.6, 0.2, 0.2), moving on a small loop around it.
PROCEDURAY_INLINE pr_real4 julia_animated_c(pr_real time) {
  return pr_real4(-PR(0.2), PR(0.6), PR(0.2), PR(0.2)) +
         PR(0.1) * pr_real4(sin(PR(0.9) * time), cos(PR(0.7) * time) - PR(1.0), sin(PR(1.3) * time), PR(0.5) * sin(PR(0.5) * time));
}

#endif
