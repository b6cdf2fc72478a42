// Closed-form ray hits in double, for the primitives that have one (sphere, axis-aligned box):
// the ground truth there, and the check on the searchers of ground_truth.hpp elsewhere.
//
//   using namespace proceduray::accuracy;
//   const glm::dvec3 o(0.0, 0.0, -1.0e6), d(0.0, 0.0, 1.0);
//   Result s = intersect_sphere(o, d, glm::dvec3(0.0), 1.0, 0.0, 2.0e6);    // t = 1e6 - 1, normal (0, 0, -1)
//   Result b = intersect_box(glm::dvec3(0.0), d, glm::dvec3(-1.0), glm::dvec3(1.0), 0.0, 10.0);
//   b.starts_inside;  // true: the origin is inside, so b is the exit, t = 1 with normal (0, 0, 1)
//
// Both report the first boundary point in [t_lo, t_hi] (an entry at exactly t_lo counts), with
// the outward unit normal there; from inside that is the exit, and starts_inside is set, as the
// searchers report it. `dir` need not be unit length. Bad input throws UsageError as the
// searchers do (and a radius <= 0, a box with min > max, non-finite centre or bounds).
//
// Sphere: the roots use q = -(b + sign(b) sqrt(D)) with the Haines et al. discriminant
// D = |dir|^2 (r^2 - |f - (f.dir / |dir|^2) dir|^2), f = origin - centre (Ray Tracing Gems ch. 7):
// b^2 - a c cancels catastrophically for a far or small sphere (at distance 1e6 it loses ~1e-4
// of a unit sphere's D), and neither root then subtracts nearly equal numbers. The normal is
// (closest point of the line) -+ sqrt(D) / |dir|^2 dir, which has no cancellation either, unlike
// origin + t dir - centre.
// Box: the slab test without IEEE infinities (the shaders cannot count on them, and a reference
// should not lean on what the measured code cannot): a zero component, +0 or -0, makes the ray
// parallel to that slab (inside for every t or for none), and a plane whose t would overflow
// (a denormal component) is known to lie beyond the t range without dividing.
#pragma once

#include <algorithm>
#include <cmath>
#include <string_view>

#include <glm/glm.hpp>

#include "proceduray/accuracy/ground_truth.hpp"

namespace proceduray::accuracy {

namespace detail {

/// The ray's t at a plane `num` (plane - origin) away along a component `d` != 0, clamped to
/// +-limit where it would lie beyond: |t_lo|, |t_hi| <= limit / 2, so a clamped value stays
/// outside the range, and no division overflows.
inline double plane_t(double num, double d, double limit) {
  // num / limit may round (even to a denormal), but the factor 2 of margin in limit absorbs it.
  if (std::abs(num) / limit > std::abs(d)) return (num < 0.0) == (d < 0.0) ? limit : -limit;
  return num / d;
}

/// A hit at t with `normal`, evaluated once.
inline Result closed_hit(double t, glm::dvec3 normal, bool starts_inside) {
  Result r;
  r.outcome = Outcome::hit;
  r.t = t + 0.0;  // -0 (an origin on a plane, a negative component) reads as 0
  r.normal = normal;
  r.evaluations = 1;
  r.starts_inside = starts_inside;
  return r;
}

}  // namespace detail

/// First boundary point of the sphere (centre, radius) along origin + t dir, t in [t_lo, t_hi].
inline Result intersect_sphere(glm::dvec3 origin, glm::dvec3 dir, glm::dvec3 centre, double radius, double t_lo,
                               double t_hi) {
  constexpr std::string_view call = "intersect_sphere";
  detail::check_ray(call, origin, dir, t_lo, t_hi);
  if (!detail::finite(centre)) {
    detail::refuse(call, "centre " + detail::show(centre) + " is not finite", "pass a finite centre");
  }
  detail::check_positive(call, "radius", radius, "pass the sphere's radius (> 0)");
  Result miss;
  miss.evaluations = 1;
  const glm::dvec3 f = origin - centre;
  if (!detail::finite(f)) {
    detail::refuse(call, "origin " + detail::show(origin) + " and centre " + detail::show(centre) +
                             " are too far apart to subtract in double", "move the origin nearer the sphere");
  }
  const double a = glm::dot(dir, dir);
  const double b = glm::dot(f, dir);
  const glm::dvec3 closest = f - (b / a) * dir;  // centre to the line's closest point
  const double disc = a * (radius * radius - glm::dot(closest, closest));
  if (disc < 0.0) return miss;
  const double root = std::sqrt(disc);
  const double q = -(b + (b >= 0.0 ? root : -root));
  double t0 = 0.0;  // q == 0: b == 0 and D == 0, a tangent at the origin's foot, both roots 0
  double t1 = 0.0;
  if (q != 0.0) {
    const double c = glm::dot(f, f) - radius * radius;
    t0 = std::min(c / q, q / a);
    t1 = std::max(c / q, q / a);
  }
  // Entry and exit points relative to the centre, from the closest point (no cancellation).
  const glm::dvec3 half_chord = (root / a) * dir;
  if (t0 >= t_lo && t0 <= t_hi) return detail::closed_hit(t0, glm::normalize(closest - half_chord), false);
  if (t1 >= t_lo && t1 <= t_hi) {
    const glm::dvec3 out = root > 0.0 ? closest + half_chord : closest;
    return detail::closed_hit(t1, glm::normalize(out), t0 < t_lo && t_lo < t1);
  }
  miss.starts_inside = t0 < t_lo && t_lo < t1;
  return miss;
}

/// First boundary point of the box [box_min, box_max] along origin + t dir, t in [t_lo, t_hi].
inline Result intersect_box(glm::dvec3 origin, glm::dvec3 dir, glm::dvec3 box_min, glm::dvec3 box_max, double t_lo,
                            double t_hi) {
  constexpr std::string_view call = "intersect_box";
  detail::check_ray(call, origin, dir, t_lo, t_hi);
  if (!detail::finite(box_min) || !detail::finite(box_max) || box_min.x > box_max.x || box_min.y > box_max.y ||
      box_min.z > box_max.z) {
    detail::refuse(call, "box [" + detail::show(box_min) + ", " + detail::show(box_max) + "] is not finite with min <= max",
                   "pass finite corners, the smaller one first");
  }
  Result miss;
  miss.evaluations = 1;
  const double limit = 2.0 * std::max({1.0, std::abs(t_lo), std::abs(t_hi)});
  double near = t_lo;  // the range still possible, narrowed slab by slab
  double far = t_hi;
  int near_axis = -1;  // the slab whose plane set `near` (-1: none, t_lo itself)
  int far_axis = -1;
  for (int axis = 0; axis < 3; ++axis) {
    const double o = origin[axis];
    const double d = dir[axis];
    const double to_min = box_min[axis] - o;
    const double to_max = box_max[axis] - o;
    if (!std::isfinite(to_min) || !std::isfinite(to_max)) {
      detail::refuse(call, "origin " + detail::show(origin) + " and the box are too far apart to subtract in double",
                     "move the origin nearer the box");
    }
    if (d == 0.0) {  // +0 and -0 alike: parallel to both planes, inside for every t or for none
      if (to_min > 0.0 || to_max < 0.0) return miss;
      continue;
    }
    const double enter = detail::plane_t(d > 0.0 ? to_min : to_max, d, limit);
    const double leave = detail::plane_t(d > 0.0 ? to_max : to_min, d, limit);
    if (enter >= near) {  // >=: an entry at exactly t_lo is a boundary point in range
      near = enter;
      near_axis = axis;
    }
    if (leave <= far) {
      far = leave;
      far_axis = axis;
    }
  }
  if (near > far) return miss;
  auto face = [&](int axis, double sign) {
    glm::dvec3 n(0.0);
    n[axis] = dir[axis] > 0.0 ? sign : -sign;
    return n;
  };
  if (near_axis >= 0) return detail::closed_hit(near, face(near_axis, -1.0), false);
  // No plane ahead of t_lo entered the box: the point at t_lo is inside; the hit is the exit.
  miss.starts_inside = far > t_lo;
  if (far_axis >= 0) return detail::closed_hit(far, face(far_axis, 1.0), miss.starts_inside);
  return miss;
}

}  // namespace proceduray::accuracy
