// What every generated distance-field intersection shader shares (scene/field.hpp writes them):
// clip the ray to the field's box, its knobs (proceduray_fields.data[i]) as MarchSettings at
// this ray's scale, and the report of t within [gl_RayTminEXT, gl_RayTmaxEXT] with FieldHit.
// Intersection stages only; after the generated declarations (MarchKnobs, `hit` with a normal
// and steps like FieldHit, the output helpers). A hand-written intersection may use it too.
//
//   FieldSettings f = proceduray_fields.data[0];
//   FieldMarch fm;
//   if (!field_march_begin(box_min, box_max, f.knobs, f.pixel_angle, lipschitz, fm)) return;
//   uint iterations = march_iterations(f.knobs, fm.footprint);
//   float s; uint steps;
//   bool found = gyroid_march_trace(fm.o, fm.u, fm.range.x, fm.range.y, fm.m, iterations, s, steps);
//   vec3 p = fm.o + s * fm.u;
//   vec3 n = found ? gyroid_march_normal(uint(f.knobs.normal), p, field_normal_offset(f.knobs, fm.m, p, s), iterations)
//                  : vec3(0.0, 1.0, 0.0);
//   field_march_report(found, s / fm.len, steps, fm.m, n, march_normal_evaluations(f.knobs));
//
// Marching runs in object space along the unit direction u = d / |d|, so distances are
// object-space lengths s = t |d|. World lengths in the knobs (epsilon, an absolute threshold)
// are divided by the instance's scale; the footprint term threshold * pixel_angle * t is an
// angle times a distance and needs no scaling. The footprint uses this ray's own t (an
// intersection shader cannot read the payload), so for reflection rays it is finer than the
// pixel's true cone: more accurate, never coarser.
#ifndef PROCEDURAY_MARCHING_FIELD_GLSL
#define PROCEDURAY_MARCHING_FIELD_GLSL

#include "field_march.glsl"

/// True for a ray of which only whether it hits is read: it stops at its first hit, runs no closest
/// hit, is opaque (no any-hit reads the attributes) and culls nothing (the normal decides no face):
/// a shadow ray. Its march skips the crossing's bisection (the crossing found is the same, so is
/// the answer, but where the crossing lies within float rounding of the ray's tmax) and the
/// normal's evaluations.
bool field_hit_only() {
  uint f = gl_IncomingRayFlagsEXT;
  uint needed = gl_RayFlagsTerminateOnFirstHitEXT | gl_RayFlagsSkipClosestHitShaderEXT | gl_RayFlagsOpaqueEXT;
  uint cull = gl_RayFlagsCullBackFacingTrianglesEXT | gl_RayFlagsCullFrontFacingTrianglesEXT;
  return (f & needed) == needed && (f & cull) == 0u;
}

/// Clips the ray to [box_min, box_max] (false: it misses the box) and sets up fm for knobs k at
/// pixel_angle radians per pixel, for a field with Lipschitz bound `lipschitz`.
bool field_march_begin(vec3 box_min, vec3 box_max, MarchKnobs k, float pixel_angle, float lipschitz, out FieldMarch fm) {
  // Drivers may report AABB hits outside the box (it may be enlarged): the setup clips to our own.
  if (!field_march_setup(gl_ObjectRayOriginEXT, gl_ObjectRayDirectionEXT, gl_RayTminEXT, gl_RayTmaxEXT,
                         length(gl_WorldRayDirectionEXT), box_min, box_max, k, pixel_angle, lipschitz, fm)) {
    return false;
  }
  if (fm.m.hit_rule == march_hit_refined && field_hit_only()) fm.m.hit_rule = march_hit_unrefined;
  return true;
}

/// Flags a march whose first point is inside: the generated shader's one extra evaluation,
/// made only when outputs are asked for (#ifdef PROCEDURAY_OUTPUTS).
void field_march_started(float first_distance) {
#ifdef PROCEDURAY_OUTPUTS
  if (first_distance < 0.0) output_flags(output_flag_started_inside);
#endif
}

/// Whether the ray's cull flags drop a hit with this object-space normal. Vulkan culls triangles
/// only; a field honours the flags as a triangle would, taking the side its normal faces (a back
/// face: the normal along the ray), as the D3D12 sample's procedural hits do.
bool field_hit_culled(vec3 normal) {
  bool back = dot(normal, gl_ObjectRayDirectionEXT) > 0.0;
  uint flags = gl_IncomingRayFlagsEXT;
  return back ? (flags & gl_RayFlagsCullBackFacingTrianglesEXT) != 0u
              : (flags & gl_RayFlagsCullFrontFacingTrianglesEXT) != 0u;
}

/// Reports the march's hit at t (when found, in range and not culled) with `normal` and the
/// march's evaluations (FieldHit::steps) and the threshold there, in world units
/// (FieldHit::threshold); the steps output counts the normal's evaluations as well.
void field_march_report(bool found, float t, uint steps, MarchSettings m, vec3 normal, uint normal_evaluations) {
  output_steps(steps);
#ifdef PROCEDURAY_OUTPUTS
  if (!found && steps >= m.max_steps) output_flags(output_flag_exhausted);
#endif
  if (!found || !t_in_range(t, gl_RayTminEXT, gl_RayTmaxEXT) || field_hit_culled(normal)) return;
  output_steps(normal_evaluations);
#ifdef PROCEDURAY_OUTPUTS
  if (isnan(t) || any(isnan(normal))) output_flags(output_flag_nan);
#endif
  hit.normal = normal;
  hit.steps = float(steps);  // the march's; the outputs' steps count the normal's too
  // The threshold at the hit in world units: object lengths times the instance's scale.
  float len = length(gl_ObjectRayDirectionEXT);
  hit.threshold = march_epsilon(m, t * len) * length(gl_WorldRayDirectionEXT) / len;
  reportIntersectionEXT(t, 0u);
}

#endif
