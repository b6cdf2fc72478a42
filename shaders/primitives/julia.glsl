// Quaternion Julia set (the 3D slice w = 0 of {z : z_{n+1} = z_n^2 + c stays bounded}),
// optionally cut by a plane, as a distance estimate for sphere tracing.
//
//   float d = julia_distance(p, c, 10u);                      // > 0 outside, 0 inside
//   float d_cut = julia_cut_distance(p, c, 10u, plane);       // keeps dot(plane.xyz, p) <= plane.w
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
PROCEDURAY_INLINE vec4 quat_mul(vec4 a, vec4 b) {
  return vec4(a.x * b.x - a.y * b.y - a.z * b.z - a.w * b.w,
              a.x * b.y + a.y * b.x + a.z * b.w - a.w * b.z,
              a.x * b.z - a.y * b.w + a.z * b.x + a.w * b.y,
              a.x * b.w + a.y * b.z - a.z * b.y + a.w * b.x);
}

/// Quaternion square a a (cheaper than quat_mul(a, a)).
PROCEDURAY_INLINE vec4 quat_square(vec4 a) {
  return vec4(a.x * a.x - a.y * a.y - a.z * a.z - a.w * a.w, 2.0f * a.x * a.y, 2.0f * a.x * a.z, 2.0f * a.x * a.w);
}

/// Escape radius: |z| beyond it diverges; large enough that the estimate is accurate.
const float julia_bailout = 16.0f;

/// Distance estimate to the Julia set of c after `iterations` steps (0 inside).
PROCEDURAY_INLINE float julia_distance(vec3 p, vec4 c, uint iterations) {
  vec4 z = vec4(p.x, p.y, p.z, 0.0f);
  vec4 dz = vec4(1.0f, 0.0f, 0.0f, 0.0f);
  bool escaped = false;
  for (uint i = 0u; i < iterations; ++i) {
    dz = 2.0f * quat_mul(z, dz);
    z = quat_square(z) + c;
    if (dot(z, z) > julia_bailout * julia_bailout) {
      escaped = true;
      break;
    }
  }
  if (!escaped) return 0.0f;
  float r = length(z);
  return 0.5f * r * log(r) / max(length(dz), 1.0e-20f);
}

/// The Julia set intersected with the half-space dot(plane.xyz, p) <= plane.w (plane.xyz unit).
PROCEDURAY_INLINE float julia_cut_distance(vec3 p, vec4 c, uint iterations, vec4 plane) {
  float d_plane = dot(vec3(plane.x, plane.y, plane.z), p) - plane.w;
  return max(julia_distance(p, c, iterations), d_plane);
}

/// The animated constant: c(0) = (-0.2, 0.6, 0.2, 0.2), moving on a small loop around it.
PROCEDURAY_INLINE vec4 julia_animated_c(float time) {
  return vec4(-0.2f, 0.6f, 0.2f, 0.2f) +
         0.1f * vec4(sin(0.9f * time), cos(0.7f * time) - 1.0f, sin(1.3f * time), 0.5f * sin(0.5f * time));
}

#endif
