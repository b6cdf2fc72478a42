// The D3D12 procedural-geometry sample's primitives behind one call: analytic (box, several
// spheres), volumetric (metaballs) and signed distance (sdf.glsl's seven), in local space
// where the primitive's AABB is [-1, 1]^3.
//
//   float t; vec3 n; float steps;
//   if (d3d12_intersect(kind, params, spin, time, o, d, gl_RayTminEXT, gl_RayTmaxEXT, cull, m,
//                       metaball_method, metaball_steps, d3d12_sdf_march_default(), t, n, steps))
//     reportIntersectionEXT(t, 0u);
//
// Each primitive: clips the ray to its own AABB first (drivers may report hits of an enlarged
// box), turns the ray by -spin about y (animation without acceleration-structure work: the
// primitive must fit its AABB at every angle), intersects, and accepts only a hit whose t is in
// [t_lo, t_hi] and whose facing the cull bits allow (common/hit.glsl). Normals are unit, outward,
// in local space: analytic for box, spheres and metaballs; central differences of the
// distance, with the offset tied to the hit threshold at the hit's distance, for SDFs. `steps`
// counts distance or field evaluations (0 for analytic primitives). Marching runs along the
// unit direction, so epsilon and footprint in `m` are local lengths; m.step_scale is multiplied
// by 1 / sdf_lipschitz (unless D3d12SdfMarch::lipschitz_steps is 0). metaball_method is one of
// metaballs.glsl's; d3d12_knobs.glsl calls this with a geometry's MarchKnobs.
//
// The SDFs are marched by the marcher generated here for sdf.glsl's distances (prefix d3d12_sdf,
// field D3d12Sdf: the kind and its params), so the file keeps no state of its own.
#ifndef PROCEDURAY_PRIMITIVES_D3D12_PRIMITIVES_GLSL
#define PROCEDURAY_PRIMITIVES_D3D12_PRIMITIVES_GLSL

#include "../common/compat.glsl"
#include "../common/hit.glsl"
#include "../common/ray.glsl"
#include "../marching/sphere_trace.glsl"
#include "box.glsl"
#include "sdf.glsl"
#include "spheres.glsl"

/// Primitive kinds: the analytic and volumetric ones here, the SDFs (3 to 9) in sdf.glsl.
PROCEDURAY_CONST uint primitive_box = 0u;
PROCEDURAY_CONST uint primitive_spheres = 1u;
PROCEDURAY_CONST uint primitive_metaballs = 2u;
PROCEDURAY_CONST uint primitive_kind_count = 10u;

/// How the SDFs are marched beyond `m` (d3d12_knobs.glsl fills it from a geometry's knobs).
struct D3d12SdfMarch {
  uint lipschitz_steps;  // 1: steps divided by the SDF's Lipschitz bound; 0: plain sphere tracing (overshoots where L > 1)
  uint normal_method;    // march_normal_central (1) or march_normal_tetrahedral (2)
  pr_real normal_scale;     // the differences' offset, in hit thresholds
};

/// Lipschitz steps and central normals at the threshold: the sample's own way.
PROCEDURAY_INLINE D3d12SdfMarch d3d12_sdf_march_default() {
#ifdef __cplusplus
  D3d12SdfMarch s{};
#else
  D3d12SdfMarch s;
#endif
  s.lipschitz_steps = 1u;
  s.normal_method = march_normal_central;
  s.normal_scale = PR(1.0);
  return s;
}

/// What an SDF's distance reads besides p: which of sdf.glsl's shapes, and its parameters.
struct D3d12Sdf {
  uint kind;
  pr_real4 params;
};

PROCEDURAY_INLINE pr_real d3d12_sdf_distance(pr_real3 p, D3d12Sdf f) { return sdf_distance(f.kind, p, f.params); }

#define PROCEDURAY_MARCHER d3d12_sdf
#define PROCEDURAY_MARCHER_FIELD D3d12Sdf
#define PROCEDURAY_MARCHER_DISTANCE d3d12_sdf_distance
#include "../marching/marcher.glsl"
#include "metaballs.glsl"

/// v turned by angle a about the y axis.
PROCEDURAY_INLINE pr_real3 rotate_y(pr_real3 v, pr_real a) {
  pr_real c = cos(a);
  pr_real s = sin(a);
  return pr_real3(c * v.x + s * v.z, v.y, -s * v.x + c * v.z);
}

PROCEDURAY_INLINE bool d3d12_intersect(uint kind, pr_real4 params, pr_real spin, pr_real time, pr_real3 o, pr_real3 d, pr_real t_lo,
                                       pr_real t_hi, uint cull, MarchSettings m, uint metaball_method,
                                       uint metaball_steps, D3d12SdfMarch sdf_march, PROCEDURAY_OUT(pr_real) t_hit,
                                       PROCEDURAY_OUT(pr_real3) normal, PROCEDURAY_OUT(pr_real) steps) {
  t_hit = PR(0.0);
  normal = pr_real3(PR(0.0), PR(1.0), PR(0.0));
  steps = PR(0.0);
  pr_real t0 = t_lo;
  pr_real t1 = t_hi;
  if (!ray_clip_aabb(o, d, pr_real3(-PR(1.0)), pr_real3(PR(1.0)), t0, t1)) return false;
  pr_real angle = spin * time;
  pr_real3 ro = rotate_y(o, -angle);
  pr_real3 rd = rotate_y(d, -angle);
  pr_real t = PR(0.0);
  pr_real3 n = pr_real3(PR(0.0), PR(1.0), PR(0.0));
  if (kind == primitive_box) {
    if (!ray_box(ro, rd, -pr_real3(params.x, params.y, params.z), pr_real3(params.x, params.y, params.z), t0, t1, cull, t, n))
      return false;
  } else if (kind == primitive_spheres) {
    if (!ray_spheres(ro, rd, params.x, t0, t1, cull, t, n)) return false;
  } else {
    pr_real len = length(rd);
    if (!(len > PR(0.0))) return false;
    pr_real3 u = rd / len;
    pr_real s = PR(0.0);
    uint count = 0u;
    if (kind == primitive_metaballs) {
      bool hit = metaballs_march(ro, u, t0 * len, t1 * len, params.x, params.y, time, metaball_method, metaball_steps,
                                 m, s, n, count);
      steps = pr_real(count);
      if (!hit) return false;
    } else {
#ifdef __cplusplus
      D3d12Sdf field{kind, params};
#else
      D3d12Sdf field = D3d12Sdf(kind, params);
#endif
      MarchSettings ms = m;
      ms.step_scale = m.step_scale > PR(0.0) ? m.step_scale : PR(1.0);
      if (sdf_march.lipschitz_steps != 0u) ms.step_scale /= sdf_lipschitz(kind, params);
      bool hit = d3d12_sdf_trace(ro, u, t0 * len, t1 * len, ms, field, s, count);
      steps = pr_real(count);
      if (!hit) return false;
      // Central differences at the threshold: smooth SDFs blur to second order only (the
      // tetrahedral form's first-order blur cost 7 to 30 degrees on the small parts at 96x64).
      pr_real3 p = ro + s * u;
      pr_real h = normal_offset(sdf_march.normal_scale * max(march_epsilon(ms, s), PR(1.0e-5)), p);
      n = d3d12_sdf_normal(sdf_march.normal_method, p, h, field);
    }
    t = s / len;
    if (!hit_is_valid(t, t0, t1, rd, n, cull)) return false;
  }
  t_hit = t;
  normal = rotate_y(n, angle);
  return true;
}

#endif
