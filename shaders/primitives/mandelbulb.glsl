// The power-8 Mandelbulb (White and Nylander's z <- z^8 + p in spherical coordinates) as a
// distance estimate for sphere tracing.
//
//   float d = mandelbulb_distance(p, 8u);                 // > 0 outside, 0 inside
//   uint n = mandelbulb_animated_iterations(8u, time);    // n(0) = 8, then 7, ..., 1, 8, ...
//
// d = 0.5 |z| ln|z| / |dz| with the running derivative |dz| <- 8 |z|^7 |dz| + 1. Points whose
// orbit stays within the bailout radius 2 are inside the truncated set and get 0. NaN guards:
// the bailout keeps ln|z| >= ln 2 > 0; |dz| >= 1; powers are products (no pow of a negative
// or of 0); acos gets a clamped argument; atan(x, z) is not called with both 0 (undefined in
// GLSL); z = 0 (r = 0) maps to z^8 = 0 without angles. The set lies within radius ~1.2.
#ifndef PROCEDURAY_PRIMITIVES_MANDELBULB_GLSL
#define PROCEDURAY_PRIMITIVES_MANDELBULB_GLSL

#include "../common/compat.glsl"

/// Escape radius of the orbit.
PROCEDURAY_CONST pr_real mandelbulb_bailout = PR(2.0);

/// Distance estimate to the power-8 Mandelbulb after `iterations` steps (0 inside).
PROCEDURAY_INLINE pr_real mandelbulb_distance(pr_real3 p, uint iterations) {
  pr_real3 z = p;
  pr_real dr = PR(1.0);
  pr_real r = length(z);
  for (uint i = 0u; i < iterations && r <= mandelbulb_bailout; ++i) {
    pr_real r2 = r * r;
    pr_real r4 = r2 * r2;
    dr = PR(8.0) * r4 * r2 * r * dr + PR(1.0);
    pr_real3 zn = pr_real3(PR(0.0));
    if (r > PR(0.0)) {
      pr_real theta = PR(8.0) * acos(clamp(z.y / r, -PR(1.0), PR(1.0)));
      pr_real phi = (z.x == PR(0.0) && z.z == PR(0.0)) ? PR(0.0) : PR(8.0) * atan(z.x, z.z);
      zn = (r4 * r4) * pr_real3(sin(theta) * sin(phi), cos(theta), sin(theta) * cos(phi));
    }
    z = zn + p;
    r = length(z);
  }
  if (r <= mandelbulb_bailout) return PR(0.0);
  return PR(0.5) * r * log(r) / dr;
}

/// Iteration count at `time`: starts at max_iterations and steps down by one twice a second,
/// wrapping back to max_iterations after 1 (the report's animated Mandelbulb).
PROCEDURAY_INLINE uint mandelbulb_animated_iterations(uint max_iterations, pr_real time) {
  uint n = max(max_iterations, 1u);
  uint k = uint(min(max(time, PR(0.0)) * PR(2.0), PR(1.0e9)));  // clamped: out-of-range float-to-uint is undefined
  return n - k % n;
}

#endif
