// The power-8 Mandelbulb (White and Nylander's z <- z^8 + p in spherical coordinates) as a
// distance estimate for sphere tracing, in a trigonometry-free form.
//
//   float d = mandelbulb_distance(p, 8u);                 // > 0 outside, 0 inside
//   uint n = mandelbulb_animated_iterations(8u, time);    // n(0) = 8, then 7, ..., 1, 8, ...
//   vec3 z8 = mandelbulb_power8(z);                       // the map's z^8
//
// d = 0.5 |z| ln|z| / |dz| with the running derivative |dz| <- 8 |z|^7 |dz| + 1. Points whose
// orbit stays within the bailout radius 2 are inside the truncated set and get 0.
//
// z^8 without angles: with theta from +y (cos = y / r, sin = rho / r, rho = |(x, z)|) and phi
// = atan(x, z), (cos 8a, sin 8a) is the unit complex number (cos a, sin a) squared three
// times, so z^8 = r^8 (sin 8theta sin 8phi, cos 8theta, sin 8theta cos 8phi) takes six
// complex squarings, one square root and two divisions. Why: the Vulkan spec bounds sin and cos
// only inside [-pi, pi] and acos, atan not at all, where the angle form evaluated them at 8
// theta; this form is exact arithmetic up to rounding, and cheaper.
//
// NaN guards: the bailout keeps ln|z| >= ln 2 > 0; |dz| >= 1; powers are products; r = 0 maps
// to 0 and rho = 0 (the y axis, where phi is undefined) to (0, r^8 cos 8theta, 0), the angle
// form's limit. The set lies within radius ~1.2.
#ifndef PROCEDURAY_PRIMITIVES_MANDELBULB_GLSL
#define PROCEDURAY_PRIMITIVES_MANDELBULB_GLSL

#include "../common/compat.glsl"

/// Escape radius of the orbit.
PROCEDURAY_CONST pr_real mandelbulb_bailout = PR(2.0);

/// (a + b i)^8 by three complex squarings.
PROCEDURAY_INLINE pr_real2 mandelbulb_complex_pow8(pr_real2 c) {
  for (uint i = 0u; i < 3u; ++i) c = pr_real2(c.x * c.x - c.y * c.y, PR(2.0) * c.x * c.y);
  return c;
}

/// z^8 in the bulb's spherical power (theta from +y, phi = atan(x, z)), without trigonometry.
PROCEDURAY_INLINE pr_real3 mandelbulb_power8(pr_real3 z) {
  pr_real r = length(z);
  if (!(r > PR(0.0))) return pr_real3(PR(0.0));
  pr_real rho = length(pr_real2(z.x, z.z));
  pr_real r2 = r * r;
  pr_real r4 = r2 * r2;
  pr_real2 theta8 = mandelbulb_complex_pow8(pr_real2(z.y, rho) / r);  // (cos 8theta, sin 8theta)
  if (!(rho > PR(0.0))) return pr_real3(PR(0.0), r4 * r4 * theta8.x, PR(0.0));
  pr_real2 phi8 = mandelbulb_complex_pow8(pr_real2(z.z, z.x) / rho);  // (cos 8phi, sin 8phi)
  return (r4 * r4) * pr_real3(theta8.y * phi8.y, theta8.x, theta8.y * phi8.x);
}

/// Distance estimate to the power-8 Mandelbulb after `iterations` steps (0 inside).
PROCEDURAY_INLINE pr_real mandelbulb_distance(pr_real3 p, uint iterations) {
  pr_real3 z = p;
  pr_real dr = PR(1.0);
  pr_real r = length(z);
  for (uint i = 0u; i < iterations && r <= mandelbulb_bailout; ++i) {
    pr_real r2 = r * r;
    pr_real r4 = r2 * r2;
    dr = PR(8.0) * r4 * r2 * r * dr + PR(1.0);
    z = mandelbulb_power8(z) + p;
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
