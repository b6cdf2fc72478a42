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

PROCEDURAY_INLINE bool ray_sphere(pr_real3 origin, pr_real3 direction, pr_real3 centre, pr_real radius, PROCEDURAY_OUT(pr_real) t_near,
                                  PROCEDURAY_OUT(pr_real) t_far) {
  pr_real3 f = origin - centre;
  pr_real a = dot(direction, direction);
  pr_real b = dot(f, direction);
  t_near = PR(0.0);
  t_far = PR(0.0);
  if (!(a > PR(0.0))) return false;  // zero direction: no line, and b / a would be NaN
  pr_real3 closest = f - (b / a) * direction;  // from the centre to the line's closest point
  pr_real disc = a * (radius * radius - dot(closest, closest));
  if (disc < PR(0.0)) return false;
  pr_real q = -(b + (b >= PR(0.0) ? PR(1.0) : -PR(1.0)) * sqrt(disc));
  if (q == PR(0.0)) return true;  // tangent ray through the origin's foot: both roots are 0
  pr_real c = dot(f, f) - radius * radius;
  pr_real ta = c / q;
  pr_real tb = q / a;
  t_near = min(ta, tb);
  t_far = max(ta, tb);
  return true;
}

#endif
