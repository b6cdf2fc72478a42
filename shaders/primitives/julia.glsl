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
// is floored, so no log of <= 0 and no division by 0. Quaternions are vec4(real, i, j, k).
#ifndef PROCEDURAY_PRIMITIVES_JULIA_GLSL
#define PROCEDURAY_PRIMITIVES_JULIA_GLSL

#include "../common/compat.glsl"

/// Quaternion product a b.
PROCEDURAY_INLINE real4 quat_mul(real4 a, real4 b) {
  return real4(a.x * b.x - a.y * b.y - a.z * b.z - a.w * b.w,
              a.x * b.y + a.y * b.x + a.z * b.w - a.w * b.z,
              a.x * b.z - a.y * b.w + a.z * b.x + a.w * b.y,
              a.x * b.w + a.y * b.z - a.z * b.y + a.w * b.x);
}

/// Quaternion square a a (cheaper than quat_mul(a, a)).
PROCEDURAY_INLINE real4 quat_square(real4 a) {
  return real4(a.x * a.x - a.y * a.y - a.z * a.z - a.w * a.w, R(2.0) * a.x * a.y, R(2.0) * a.x * a.z, R(2.0) * a.x * a.w);
}

/// Escape radius: |z| beyond it diverges; large enough that the estimate is accurate.
PROCEDURAY_CONST real julia_bailout = R(16.0);

/// Distance estimate to the Julia set of c after `iterations` steps (0 inside).
PROCEDURAY_INLINE real julia_distance(real3 p, real4 c, uint iterations) {
  real4 z = real4(p.x, p.y, p.z, R(0.0));
  real4 dz = real4(R(1.0), R(0.0), R(0.0), R(0.0));
  bool escaped = false;
  for (uint i = 0u; i < iterations; ++i) {
    dz = R(2.0) * quat_mul(z, dz);
    z = quat_square(z) + c;
    if (dot(z, z) > julia_bailout * julia_bailout) {
      escaped = true;
      break;
    }
  }
  if (!escaped) return R(0.0);
  real r = length(z);
  return R(0.5) * r * log(r) / max(length(dz), R(1.0e-20));
}

/// The Julia set intersected with the half-space dot(plane.xyz, p) <= plane.w (plane.xyz unit).
PROCEDURAY_INLINE real julia_cut_distance(real3 p, real4 c, uint iterations, real4 plane) {
  real d_plane = dot(real3(plane.x, plane.y, plane.z), p) - plane.w;
  return max(julia_distance(p, c, iterations), d_plane);
}

/// Signed distance to the half-space dot(plane.xyz, p) <= plane.w (plane.xyz unit).
PROCEDURAY_INLINE real julia_plane_distance(real3 p, real4 plane) {
  return dot(real3(plane.x, plane.y, plane.z), p) - plane.w;
}

/// The Julia set cut by the first `count` (0 to 2) of two planes (proceduray::CutPlanes): data
/// from a uniform or record, so a cut moves without a shader edit.
PROCEDURAY_INLINE real julia_cuts_distance(real3 p, real4 c, uint iterations, real4 cut0, real4 cut1, uint count) {
  real d = julia_distance(p, c, iterations);
  if (count >= 1u) d = max(d, julia_plane_distance(p, cut0));
  if (count >= 2u) d = max(d, julia_plane_distance(p, cut1));
  return d;
}

/// Which cut face p lies on (0 or 1: its plane's distance is the largest term of
/// julia_cuts_distance, so the normal there is the plane's, exactly), or 2 when none.
PROCEDURAY_INLINE uint julia_cut_face(real3 p, real4 c, uint iterations, real4 cut0, real4 cut1, uint count) {
  real d = julia_distance(p, c, iterations);
  real d0 = count >= 1u ? julia_plane_distance(p, cut0) : d - R(1.0);
  real d1 = count >= 2u ? julia_plane_distance(p, cut1) : d - R(1.0);
  if (d0 >= d && d0 >= d1) return 0u;
  if (d1 >= d && d1 > d0) return 1u;
  return 2u;
}

/// The animated constant: c(0) = (-0.2, 0.6, 0.2, 0.2), moving on a small loop around it.
PROCEDURAY_INLINE real4 julia_animated_c(real time) {
  return real4(-R(0.2), R(0.6), R(0.2), R(0.2)) +
         R(0.1) * real4(sin(R(0.9) * time), cos(R(0.7) * time) - R(1.0), sin(R(1.3) * time), R(0.5) * sin(R(0.5) * time));
}

#endif
