// What the paper scene's marched intersection shaders share: clip to the own AABB, march with
// the object's knobs (constants.knobs[arguments.object_id]), report t within [gl_RayTminEXT,
// gl_RayTmaxEXT].
// With per-pixel outputs it also adds its evaluations (march and normal) and sets the
// exhausted, started-inside and NaN flags.
//
//   float march_distance(vec3 p) { ... }          // object space
//   void march_prepare(float footprint) { ... }   // per ray, before the march: e.g. the iterations
//   vec3 march_normal(vec3 p, float h) { ... }    // unit, outward; march_knobs_normal(object_knobs, p, h)
//   #include "march.glsl"
//   void main() { march_and_report(mandelbulb_aabb_min, mandelbulb_aabb_max); }
//
// Marching runs in object space along the unit direction u = d / |d|, so distances are
// object-space lengths s = t |d|. World lengths in the knobs (epsilon, an absolute threshold)
// are divided by the instance's scale (world length per object length); the footprint term
// threshold * pixel_angle * t is an angle times a distance and needs no scaling.
// The footprint uses this ray's own t (an intersection shader cannot read the payload), so
// for reflection rays it is finer than the pixel's true cone: more accurate, never coarser.
#ifndef PAPER_MARCH_GLSL
#define PAPER_MARCH_GLSL

#include "common/ray.glsl"
#include "marching/knobs.glsl"

MarchKnobs object_knobs;  // this object's, set by march_and_report
void march_prepare(float footprint);
vec3 march_normal(vec3 p, float h);

void march_and_report(vec3 box_min, vec3 box_max) {
  vec3 o = gl_ObjectRayOriginEXT;
  vec3 d = gl_ObjectRayDirectionEXT;
  float t0 = gl_RayTminEXT;
  float t1 = gl_RayTmaxEXT;
  // Drivers may report AABB hits outside the box (it may be enlarged): clip to our own.
  if (!ray_clip_aabb(o, d, box_min, box_max, t0, t1)) return;
  float len = length(d);
  if (!(len > 0.0)) return;
  vec3 u = d / len;
  float world_per_object = max(length(gl_WorldRayDirectionEXT) / len, 1.0e-20);
  object_knobs = constants.knobs[arguments.object_id];
  // The footprint at the box entry, world units (by-distance iterations): t is world distance.
  march_prepare(constants.camera.pixel_angle * max(t0, 0.0) * length(gl_WorldRayDirectionEXT));
  MarchSettings m = march_settings(object_knobs, world_per_object, constants.camera.pixel_angle, 1.0);
  float s;
  uint steps;
#ifdef PROCEDURAY_OUTPUTS
  // One more evaluation, only when outputs are asked for: does the march start inside?
  if (march_distance(o + t0 * len * u) < 0.0) output_flags(output_flag_started_inside);
#endif
  bool found = sphere_trace(o, u, t0 * len, t1 * len, m, s, steps);
  output_steps(steps);
#ifdef PROCEDURAY_OUTPUTS
  if (!found && steps >= m.max_steps) output_flags(output_flag_exhausted);
#endif
  if (!found) return;
  float t = s / len;
  if (!t_in_range(t, gl_RayTminEXT, gl_RayTmaxEXT)) return;
  hit.normal = march_normal(o + s * u, max(march_epsilon(m, s), 1.0e-5));
  output_steps(march_normal_evaluations(object_knobs));  // the normal's evaluations (at most)
#ifdef PROCEDURAY_OUTPUTS
  if (isnan(t) || any(isnan(hit.normal))) output_flags(output_flag_nan);
#endif
  hit.steps = float(steps);
  reportIntersectionEXT(t, 0u);
}

#endif
