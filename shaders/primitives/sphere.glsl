// Ray-sphere intersection, robust for far and small spheres.
//
//   float t0, t1;
//   if (ray_sphere(origin, direction, centre, radius, t0, t1)) { ... t0 <= t1 ... }
//
// `direction` need not be normalised (object-space rays are not). The discriminant uses the
// Haines et al. form a * (r^2 - |f - (f.d/a) d|^2) (Ray Tracing Gems, ch. 7), which avoids
// the cancellation of b^2 - ac when the sphere is far away or small, and the roots use the
// stable q = -(b + sign(b) sqrt(disc)) form so neither root subtracts nearly equal numbers.
#ifndef PROCEDURAY_PRIMITIVES_SPHERE_GLSL
#define PROCEDURAY_PRIMITIVES_SPHERE_GLSL

#include "../common/compat.glsl"

PROCEDURAY_INLINE bool ray_sphere(real3 origin, real3 direction, real3 centre, real radius, PROCEDURAY_OUT(real) t_near,
                                  PROCEDURAY_OUT(real) t_far) {
  real3 f = origin - centre;
  real a = dot(direction, direction);
  real b = dot(f, direction);
  t_near = R(0.0);
  t_far = R(0.0);
  if (!(a > R(0.0))) return false;  // zero direction: no line, and b / a would be NaN
  real3 closest = f - (b / a) * direction;  // from the centre to the line's closest point
  real disc = a * (radius * radius - dot(closest, closest));
  if (disc < R(0.0)) return false;
  real q = -(b + (b >= R(0.0) ? R(1.0) : -R(1.0)) * sqrt(disc));
  if (q == R(0.0)) return true;  // tangent ray through the origin's foot: both roots are 0
  real c = dot(f, f) - radius * radius;
  real ta = c / q;
  real tb = q / a;
  t_near = min(ta, tb);
  t_far = max(ta, tb);
  return true;
}

#endif
