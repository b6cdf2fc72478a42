// Sphere tracing (Hart 1996) with run-time knobs, optional over-relaxation (Keinert et al.
// 2014), and normals by tetrahedral differences.
//
//   float march_distance(vec3 p) { return mandelbulb_distance(p, iterations); }  // define first
//   #include "marching/sphere_trace.glsl"
//   MarchSettings m = MarchSettings(max_steps, epsilon, footprint, step_scale, over_relaxation);
//   float s; uint steps;
//   if (sphere_trace(o, u, s_lo, s_hi, m, s, steps)) { vec3 n = tetrahedral_normal(o + s * u, march_epsilon(m, s)); }
//
// The includer defines `float march_distance(vec3 p)`: a signed distance bound, positive
// outside. `u` must be unit length, so s is a distance in the same units as march_distance.
// Knobs (MarchSettings, all run-time values):
//   max_steps       distance evaluations at most; when they run out the march reports a MISS,
//                   never its last point, so a silhouette ray that cannot converge leaves a
//                   hole rather than a wrong surface.
//   epsilon         absolute hit threshold (floor); keep it above the float spacing at |p|.
//   footprint       threshold growth per unit distance: k * pixel_angle for a hit within k
//                   pixel footprints; the threshold is max(epsilon, footprint * s).
//   step_scale      steps are step_scale * distance: 1 / Lipschitz bound, or a fudge < 1 for
//                   estimates (fractals) that may overshoot.
//   over_relaxation w in [1, 2): steps of w * distance; when the unbounding spheres of two
//                   successive points stop overlapping the surface may have been skipped, so
//                   the march goes back to the plain step and continues with w = 1.
#ifndef PROCEDURAY_MARCHING_SPHERE_TRACE_GLSL
#define PROCEDURAY_MARCHING_SPHERE_TRACE_GLSL

#include "../common/compat.glsl"

/// The distance bound to march; defined by the includer (before or after this file).
PROCEDURAY_INLINE float march_distance(vec3 p);

/// Run-time knobs of one march (see the header).
struct MarchSettings {
  uint max_steps;
  float epsilon;
  float footprint;
  float step_scale;
  float over_relaxation;
};

/// The hit threshold at distance s along the ray.
PROCEDURAY_INLINE float march_epsilon(MarchSettings m, float s) { return max(m.epsilon, m.footprint * s); }

/// Marches o + s u for s in [s_lo, s_hi]; true with the first s whose distance is below the threshold.
PROCEDURAY_INLINE bool sphere_trace(vec3 o, vec3 u, float s_lo, float s_hi, MarchSettings m, PROCEDURAY_OUT(float) s_hit,
                                    PROCEDURAY_OUT(uint) steps) {
  float w = clamp(m.over_relaxation, 1.0f, 1.99f);
  float k = m.step_scale > 0.0f ? m.step_scale : 1.0f;
  float s = s_lo;
  float previous_radius = 0.0f;  // |distance| at the previous point
  float step = 0.0f;             // the step that led to s
  s_hit = s_lo;
  steps = 0u;
  for (uint i = 0u; i < m.max_steps; ++i) {
    if (s > s_hi) return false;
    float r = k * march_distance(o + s * u);
    steps = i + 1u;
    if (w > 1.0f && (r < 0.0f || abs(r) + previous_radius < step)) {
      // The relaxed step may have jumped over the surface: take the plain step instead.
      s -= step - previous_radius;
      step = previous_radius;
      w = 1.0f;
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
PROCEDURAY_INLINE vec3 tetrahedral_normal(vec3 p, float h) {
  vec3 a = vec3(1.0f, -1.0f, -1.0f);
  vec3 b = vec3(-1.0f, -1.0f, 1.0f);
  vec3 c = vec3(-1.0f, 1.0f, -1.0f);
  vec3 e = vec3(1.0f, 1.0f, 1.0f);
  vec3 g = a * march_distance(p + h * a) + b * march_distance(p + h * b) + c * march_distance(p + h * c) +
           e * march_distance(p + h * e);
  float len2 = dot(g, g);
  return len2 > 1.0e-30f ? g * inversesqrt(len2) : vec3(0.0f, 1.0f, 0.0f);
}

#endif
