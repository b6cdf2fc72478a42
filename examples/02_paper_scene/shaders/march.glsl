// What the paper scene's marched intersection shaders share: clip the ray to the own AABB, the
// object's knobs (constants.knobs[arguments.object_id]) as MarchSettings, and the report of t
// within [gl_RayTminEXT, gl_RayTmaxEXT]. Each shader marches its own distance with the marcher it
// generates (marching/marcher.glsl); with per-pixel outputs the report adds its evaluations (march
// and normal) and sets the exhausted, started-inside and NaN flags.
//
//   #include "march.glsl"
//   void main() {
//     MarchKnobs k = constants.knobs[arguments.object_id];
//     vec3 o, u; float len, footprint; vec2 range; MarchSettings m;
//     if (!paper_march_begin(mandelbulb_aabb_min, mandelbulb_aabb_max, k, o, u, len, range, m, footprint)) return;
//     BulbField b = BulbField(march_iterations(k, footprint));          // what the distance reads
//     paper_march_started(bulb_distance(o + range.x * u, b));            // under #ifdef PROCEDURAY_OUTPUTS
//     float s; uint steps;
//     bool found = bulb_trace(o, u, range.x, range.y, m, b, s, steps);
//     vec3 p = o + s * u;
//     vec3 n = bulb_normal(uint(k.normal), p, paper_normal_offset(k, m, p, s), b);
//     paper_march_report(found, s / len, steps, m, n, march_normal_evaluations(k));
//   }
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

/// Clips the ray to [box_min, box_max] (false: it misses the box) and gives the march its
/// object-space origin o, unit direction u, |d| (t = s / len), the range (s_lo, s_hi), the
/// settings of knobs k at this ray's scale, and a pixel footprint at the box entry (world units,
/// for by-distance iterations).
bool paper_march_begin(vec3 box_min, vec3 box_max, MarchKnobs k, out vec3 o, out vec3 u, out float len,
                       out vec2 range, out MarchSettings m, out float footprint) {
  o = gl_ObjectRayOriginEXT;
  vec3 d = gl_ObjectRayDirectionEXT;
  float t0 = gl_RayTminEXT;
  float t1 = gl_RayTmaxEXT;
  // Drivers may report AABB hits outside the box (it may be enlarged): clip to our own.
  if (!ray_clip_aabb(o, d, box_min, box_max, t0, t1)) return false;
  len = length(d);
  if (!(len > 0.0)) return false;
  u = d / len;
  range = vec2(t0 * len, t1 * len);
  float world_per_object = max(length(gl_WorldRayDirectionEXT) / len, 1.0e-20);
  m = march_settings(k, world_per_object, constants.camera.pixel_angle, 1.0);
  footprint = constants.camera.pixel_angle * max(t0, 0.0) * length(gl_WorldRayDirectionEXT);
  return true;
}

/// Flags a march whose first point is inside: the caller's one extra evaluation, which it makes
/// only when outputs are asked for (#ifdef PROCEDURAY_OUTPUTS).
void paper_march_started(float first_distance) {
#ifdef PROCEDURAY_OUTPUTS
  if (first_distance < 0.0) output_flags(output_flag_started_inside);
#endif
}

/// The difference normal's offset at p, a hit at s: the knobs' normal_scale thresholds.
float paper_normal_offset(MarchKnobs k, MarchSettings m, vec3 p, float s) {
  return march_knobs_normal_offset(k, p, max(march_epsilon(m, s), 1.0e-5));
}

/// Reports the march's hit at t (when found and in range) with `normal`; counts the march's and
/// the normal's evaluations.
void paper_march_report(bool found, float t, uint steps, MarchSettings m, vec3 normal, uint normal_evaluations) {
  output_steps(steps);
#ifdef PROCEDURAY_OUTPUTS
  if (!found && steps >= m.max_steps) output_flags(output_flag_exhausted);
#endif
  if (!found || !t_in_range(t, gl_RayTminEXT, gl_RayTmaxEXT)) return;
  output_steps(normal_evaluations);  // the normal's evaluations (at most)
#ifdef PROCEDURAY_OUTPUTS
  if (isnan(t) || any(isnan(normal))) output_flags(output_flag_nan);
#endif
  hit.normal = normal;
  hit.steps = float(steps);
  reportIntersectionEXT(t, 0u);
}

#endif
