// d3d12_intersect driven by a geometry's MarchKnobs (proceduray/march/knobs.hpp): the method,
// threshold, steps, refinement and normal chosen per geometry at run time.
//
//   // after the generated declarations (MarchKnobs) and `#include "primitives/d3d12_knobs.glsl"`:
//   if (d3d12_intersect_knobs(kind, params, spin, time, o, d, gl_RayTminEXT, gl_RayTmaxEXT, cull,
//                             constants.knobs[id], world_per_object, pixel_angle, t, n, steps)) ...
//
// Methods: SDFs take sphere (steps of the distance), lipschitz and relaxed (steps of distance /
// sdf_lipschitz) and fixed; metaballs take lipschitz (the field's global bound), segment (Galin
// et al.'s per-segment bound) and fixed (k.fixed_steps across the box). The analytic kinds
// ignore the knobs. `steps` adds no normal evaluations: march_normal_evaluations(k) tells them.
#ifndef PROCEDURAY_PRIMITIVES_D3D12_KNOBS_GLSL
#define PROCEDURAY_PRIMITIVES_D3D12_KNOBS_GLSL

#include "d3d12_primitives.glsl"
#include "../marching/knobs.glsl"

PROCEDURAY_INLINE bool d3d12_intersect_knobs(uint kind, pr_real4 params, pr_real spin, pr_real time, pr_real3 o, pr_real3 d,
                                             pr_real t_lo, pr_real t_hi, uint cull, MarchKnobs k, pr_real world_per_object,
                                             pr_real pixel_angle, PROCEDURAY_OUT(pr_real) t_hit,
                                             PROCEDURAY_OUT(pr_real3) normal, PROCEDURAY_OUT(pr_real) steps) {
  MarchSettings m = march_settings(k, world_per_object, pixel_angle, PR(1.0));  // L per kind: d3d12_intersect
  m.step_scale = pr_real(k.step_scale);
  D3d12SdfMarch sdf = d3d12_sdf_march_default();
  sdf.lipschitz_steps = uint(k.method) == march_method_lipschitz || uint(k.method) == march_method_relaxed ? 1u : 0u;
  sdf.normal_method = uint(k.normal) == march_normal_tetrahedral ? march_normal_tetrahedral : march_normal_central;
  sdf.normal_scale = pr_real(k.normal_scale);
  uint metaball = uint(k.method) == march_method_segment ? metaball_method_segment
                  : (uint(k.method) == march_method_fixed ? metaball_method_fixed : metaball_method_lipschitz);
  return d3d12_intersect(kind, params, spin, time, o, d, t_lo, t_hi, cull, m, metaball, k.fixed_steps, sdf, t_hit,
                         normal, steps);
}

#endif
