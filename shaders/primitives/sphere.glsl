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

PROCEDURAY_INLINE bool ray_sphere(vec3 origin, vec3 direction, vec3 centre, float radius, PROCEDURAY_OUT(float) t_near,
                                  PROCEDURAY_OUT(float) t_far) {
  vec3 f = origin - centre;
  float a = dot(direction, direction);
  float b = dot(f, direction);
  t_near = 0.0f;
  t_far = 0.0f;
  if (!(a > 0.0f)) return false;  // zero direction: no line, and b / a would be NaN
  vec3 closest = f - (b / a) * direction;  // from the centre to the line's closest point
  float disc = a * (radius * radius - dot(closest, closest));
  if (disc < 0.0f) return false;
  float q = -(b + (b >= 0.0f ? 1.0f : -1.0f) * sqrt(disc));
  if (q == 0.0f) return true;  // tangent ray through the origin's foot: both roots are 0
  float c = dot(f, f) - radius * radius;
  float ta = c / q;
  float tb = q / a;
  t_near = min(ta, tb);
  t_far = max(ta, tb);
  return true;
}

#endif
