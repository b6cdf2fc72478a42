// A distance field's march set up from a ray in object space, in any stage: the box clip, the
// unit direction, the knobs as MarchSettings at the ray's scale, the normal's offset. The
// intersection shaders (marching/field.glsl) call it with the ray's built-ins; a compute shader
// marching the same field (tools/bench/shaders/instances.comp) with its own ray, so both march alike.
//
//   FieldMarch fm;
//   if (field_march_setup(o_object, d_object, t_min, t_max, length(d_world), box_min, box_max, knobs,
//                         pixel_angle, lipschitz, fm)) {
//     bool found = gyroid_march_trace(fm.o, fm.u, fm.range.x, fm.range.y, fm.m, iterations, s, steps);
//     float t = s / fm.len;   // the ray's parameter
//   }
#ifndef PROCEDURAY_MARCHING_FIELD_MARCH_GLSL
#define PROCEDURAY_MARCHING_FIELD_MARCH_GLSL

#include "../common/ray.glsl"
#include "knobs.glsl"

/// A march's frame: object-space origin o and unit direction u, |d| (t = s / len), the range
/// (s_lo, s_hi) inside the box, the settings, and a pixel footprint at the box entry (world
/// units, for by-distance iterations).
struct FieldMarch {
  vec3 o;
  vec3 u;
  float len;
  vec2 range;
  MarchSettings m;
  float footprint;
};

/// The ray o + t d (object space) over [t0, t1], whose world direction is world_length long,
/// clipped to [box_min, box_max] (false: it misses the box), with fm set up for knobs k at
/// pixel_angle radians per pixel, for a field with Lipschitz bound `lipschitz`.
bool field_march_setup(vec3 o, vec3 d, float t0, float t1, float world_length, vec3 box_min, vec3 box_max, MarchKnobs k,
                       float pixel_angle, float lipschitz, out FieldMarch fm) {
  fm.o = o;
  if (!ray_clip_aabb(fm.o, d, box_min, box_max, t0, t1)) return false;
  fm.len = length(d);
  if (!(fm.len > 0.0)) return false;
  fm.u = d / fm.len;
  fm.range = vec2(t0 * fm.len, t1 * fm.len);
  float world_per_object = max(world_length / fm.len, 1.0e-20);
  fm.m = march_settings(k, world_per_object, pixel_angle, lipschitz);
  fm.footprint = pixel_angle * max(t0, 0.0) * world_length;
  return true;
}

/// The difference normal's offset at p, a hit at s: the knobs' normal_scale thresholds, at
/// least 1e-5 object units.
float field_normal_offset(MarchKnobs k, MarchSettings m, vec3 p, float s) {
  return march_knobs_normal_offset(k, p, max(march_epsilon(m, s), 1.0e-5));
}

#endif
