// Sphere tracing (Hart 1996) with run-time knobs, optional over-relaxation (Keinert et al.
// 2014), and normals by tetrahedral differences.
//
//   float march_distance(vec3 p) { return mandelbulb_distance(p, iterations); }  // define first
//   #include "marching/sphere_trace.glsl"
//   MarchSettings m = MarchSettings(max_steps, epsilon, footprint, step_scale, over_relaxation);
//   float s; uint steps;
//   if (sphere_trace(o, u, s_lo, s_hi, m, s, steps)) { vec3 n = tetrahedral_normal(o + s * u, march_epsilon(m, s)); }
//
// The includer defines `real march_distance(real3 p)` (float and vec3 in GLSL; see
// common/compat.glsl for C++): a signed distance bound, positive outside. `u` must be unit length, so s is a distance in the same units as march_distance.
// Knobs (MarchSettings, all run-time values):
//   max_steps       distance evaluations at most; when they run out the march reports a MISS,
//                   never its last point, so a silhouette ray that cannot converge leaves a
//                   hole rather than a wrong surface.
//   epsilon         absolute hit threshold (floor); keep it above the float spacing at |p|.
//   footprint       threshold growth per unit distance: k * pixel_angle for a hit within k
//                   pixel footprints; the threshold is max(epsilon, footprint * s).
//   step_scale      steps are step_scale * distance: 1 / Lipschitz bound, or a fudge < 1 for
//                   estimates (fractals) that may overshoot.
//   over_relaxation w in [1, 2) (clamped to [1, 1.99]); 1 is plain sphere tracing. Keinert et
//                   al. 2014: steps of w * distance; when the unbounding spheres of two
//                   successive points stop overlapping (|d_prev| + |d| < step, or d < 0) the
//                   surface may have been skipped, so the march goes back to the plain step's
//                   end and continues with w = 1; likewise when a relaxed step leaves [s_lo, s_hi].
#ifndef PROCEDURAY_MARCHING_SPHERE_TRACE_GLSL
#define PROCEDURAY_MARCHING_SPHERE_TRACE_GLSL

#include "../common/compat.glsl"

#ifndef __cplusplus
/// The distance bound to march; defined by the includer (before or after this file). No
/// prototype in C++: a class-scope inclusion may not declare a member twice, and there the
/// definition may follow; a namespace-scope includer defines it before including this file.
real march_distance(real3 p);
#endif

/// Run-time knobs of one march (see the header).
struct MarchSettings {
  uint max_steps;
  real epsilon;
  real footprint;
  real step_scale;
  real over_relaxation;
};

/// The hit threshold at distance s along the ray.
PROCEDURAY_INLINE real march_epsilon(MarchSettings m, real s) { return max(m.epsilon, m.footprint * s); }

/// Marches o + s u for s in [s_lo, s_hi]; true with the first s whose distance is below the
/// threshold. `steps` counts distance evaluations, on a hit and on a miss.
PROCEDURAY_INLINE bool sphere_trace(real3 o, real3 u, real s_lo, real s_hi, MarchSettings m,
                                    PROCEDURAY_OUT(real) s_hit, PROCEDURAY_OUT(uint) steps) {
  // w: the relaxation in force; 1 from the first failed overlap test on (Keinert et al. keep
  // it there: where spheres stopped overlapping the ray is near a surface or grazing one).
  real w = clamp(m.over_relaxation, R(1.0), R(1.99));
  real k = m.step_scale > R(0.0) ? m.step_scale : R(1.0);
  real s = s_lo;
  real previous_radius = R(0.0);  // scaled distance at the previous point: no surface within it
  real step = R(0.0);             // the step that led to s (w * previous_radius)
  s_hit = s_lo;
  steps = 0u;
  while (steps < m.max_steps) {
    if (s > s_hi) {
      // A relaxed step may have jumped past a surface just before s_hi (a thin part near the
      // AABB's exit): retry from the plain step's end before calling it a miss.
      if (step > previous_radius) {
        s -= step - previous_radius;
        step = previous_radius;
        w = R(1.0);
        continue;
      }
      return false;
    }
    real r = k * march_distance(o + s * u);
    steps += 1u;
    // The unbounding spheres of the previous point (radius previous_radius) and this one (|r|)
    // leave no gap on the ray only if they overlap; after a relaxed step that does not hold, or
    // r < 0 (inside), a surface may lie in the gap: go back to the plain step's end, w = 1.
    if (step > previous_radius && (r < R(0.0) || abs(r) + previous_radius < step)) {
      s -= step - previous_radius;
      step = previous_radius;
      w = R(1.0);
      continue;
    }
    if (r < march_epsilon(m, s)) {
      s_hit = s;
      return true;
    }
    previous_radius = r;
    step = w * r;
    s += step;
  }
  return false;  // out of steps: a miss by definition
}

/// Unit gradient of march_distance at p from four samples at the tetrahedron's vertices
/// (Quilez); h is the sample offset, tied by the caller to the hit threshold at p.
PROCEDURAY_INLINE real3 tetrahedral_normal(real3 p, real h) {
  real3 a = real3(R(1.0), -R(1.0), -R(1.0));
  real3 b = real3(-R(1.0), -R(1.0), R(1.0));
  real3 c = real3(-R(1.0), R(1.0), -R(1.0));
  real3 e = real3(R(1.0), R(1.0), R(1.0));
  real3 g = a * march_distance(p + h * a) + b * march_distance(p + h * b) + c * march_distance(p + h * c) +
           e * march_distance(p + h * e);
  real len2 = dot(g, g);
  return len2 > R(1.0e-30) ? g * inversesqrt(len2) : real3(R(0.0), R(1.0), R(0.0));
}

#endif
