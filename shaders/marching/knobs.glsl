// A geometry's MarchKnobs (proceduray/march/knobs.hpp, declared by the generated GLSL) turned
// into what the marches take: MarchSettings, the normal, the fractal's iteration count.
//
//   // after the generated declarations (MarchKnobs) and a marcher (marching/marcher.glsl, prefix bulb):
//   #include "marching/knobs.glsl"
//   MarchKnobs k = knobs.data[arguments.object_id];
//   MarchSettings m = march_settings(k, world_per_object, constants.camera.pixel_angle, lipschitz);
//   if (bulb_trace(o, u, s_lo, s_hi, m, field, s, steps)) {
//     vec3 p = o + s * u;
//     n = bulb_normal(uint(k.normal), p, march_knobs_normal_offset(k, p, march_epsilon(m, s)), field);
//   }
//
// Marching runs in object space along a unit direction; `world_per_object` (world length per
// object length) turns the world-unit knobs (absolute threshold, epsilon) into object units.
// The footprint term is an angle and needs none. `lipschitz` is the geometry's bound L (1 for
// an exact SDF or an estimate): lipschitz and relaxed steps are distance / L, sphere steps
// assume L = 1. The method codes equal MarchMethod's (a test compiles this file as C++).
#ifndef PROCEDURAY_MARCHING_KNOBS_GLSL
#define PROCEDURAY_MARCHING_KNOBS_GLSL

#include "../common/compat.glsl"
#include "sphere_trace.glsl"

PROCEDURAY_CONST uint march_method_sphere = 0u;
PROCEDURAY_CONST uint march_method_relaxed = 1u;
PROCEDURAY_CONST uint march_method_lipschitz = 2u;
PROCEDURAY_CONST uint march_method_segment = 3u;
PROCEDURAY_CONST uint march_method_fixed = 4u;
PROCEDURAY_CONST uint march_threshold_footprint = 0u;
PROCEDURAY_CONST uint march_threshold_absolute = 1u;
PROCEDURAY_CONST uint march_iterations_fixed = 0u;
PROCEDURAY_CONST uint march_iterations_by_distance = 1u;
/// What march_settings clamps to, whatever memory holds (knobs written without validate()): the
/// host's march_max_steps_limit and march_min_step_scale (march/knobs.hpp), so no value hangs a frame.
PROCEDURAY_CONST uint march_steps_cap = 65536u;
PROCEDURAY_CONST float march_step_scale_floor = 1.0 / 1024.0;

/// The MarchSettings of knobs k for a ray whose object space has world_per_object world units per unit.
PROCEDURAY_INLINE MarchSettings march_settings(MarchKnobs k, pr_real world_per_object, pr_real pixel_angle, pr_real lipschitz) {
#ifdef __cplusplus
  MarchSettings m{};
#else
  MarchSettings m;
#endif
  pr_real scale = world_per_object > PR(0.0) ? world_per_object : PR(1.0);
  bool absolute = uint(k.threshold_mode) == march_threshold_absolute;
  // Clamped, not trusted: 0xFFFFFFFF steps of 1e-30 would never end the dispatch; 0 would hide
  // the object (validate() refuses both on the host; memory written past it lands here).
  m.max_steps = min(max(k.max_steps, 1u), march_steps_cap);
  m.epsilon = pr_real(absolute ? k.threshold : k.epsilon) / scale;
  m.footprint = absolute ? PR(0.0) : pr_real(k.threshold) * pixel_angle;
  bool bounded = uint(k.method) == march_method_lipschitz || uint(k.method) == march_method_relaxed;
  pr_real step_scale = pr_real(k.step_scale) >= pr_real(march_step_scale_floor) ? min(pr_real(k.step_scale), PR(1.0))
                                                                                 : pr_real(march_step_scale_floor);  // NaN too
  m.step_scale = step_scale / (bounded && lipschitz > PR(0.0) ? lipschitz : PR(1.0));
  m.over_relaxation = uint(k.method) == march_method_relaxed ? pr_real(k.relaxation) : PR(1.0);
  m.fixed_steps = uint(k.method) == march_method_fixed ? max(k.fixed_steps, 1u) : 0u;
  m.hit_rule = k.refine == 2u ? march_hit_classic : (k.refine != 0u ? march_hit_refined : march_hit_unrefined);
  m.probe = pr_real(k.probe);
  return m;
}

/// The hit threshold of knobs k at distance t, in world units (pixel_angle: radians per pixel):
/// how far from the surface a hit may lie, e.g. to offset secondary rays.
PROCEDURAY_INLINE pr_real march_knobs_threshold(MarchKnobs k, pr_real pixel_angle, pr_real t) {
  if (uint(k.threshold_mode) == march_threshold_absolute) return pr_real(k.threshold);
  return max(pr_real(k.epsilon), pr_real(k.threshold) * pixel_angle * t);
}

/// The offset the knobs' difference normal (a marcher's P_normal(k.normal, p, h, field)) takes at
/// p: normal_scale thresholds, and at least normal_offset's float spacings. Analytic normals are
/// the geometry's own: not here.
PROCEDURAY_INLINE pr_real march_knobs_normal_offset(MarchKnobs k, pr_real3 p, pr_real threshold) {
  return normal_offset(pr_real(k.normal_scale) * threshold, p);
}

/// Distance evaluations the knobs' normal takes.
PROCEDURAY_INLINE uint march_normal_evaluations(MarchKnobs k) {
  return uint(k.normal) == march_normal_tetrahedral ? 4u : (uint(k.normal) == march_normal_central ? 6u : 0u);
}

/// A fractal's iteration count where a pixel footprint is `footprint` world units wide: all of
/// them up to iteration_detail, one fewer per doubling beyond (at least 1); fixed mode: all.
PROCEDURAY_INLINE uint march_iterations(MarchKnobs k, pr_real footprint) {
  uint n = max(k.iterations, 1u);
  if (uint(k.iteration_mode) != march_iterations_by_distance || !(footprint > pr_real(k.iteration_detail))) return n;
  pr_real doublings = ceil(log2(footprint / pr_real(k.iteration_detail)));
  uint drop = uint(min(doublings, pr_real(n - 1u)));
  return n - drop;
}

#endif
