#version 460
// Every primitive: the local normal from the intersection shader, the record's material,
// Phong, shadow and reflection. Flags NaN or infinity in what the intersection reported.
// A counted miss (flag_count_misses) shows the sky and passes its marching steps on.
#include "surface.glsl"
#include "marching/knobs.glsl"

void main() {
  if (gl_HitKindEXT == counted_miss_kind) {  // flag_count_misses: a miss that carries its steps
    payload.colour = constants.sky_colour;
    payload.object_id = 0u;
    payload.steps = hit.steps;
    payload.nonfinite |= (isnan(hit.steps) || isinf(hit.steps)) ? 1u : 0u;
    return;
  }
  vec3 p = gl_WorldRayOriginEXT + gl_HitTEXT * gl_WorldRayDirectionEXT;
  bool bad = nonfinite3(hit.normal) || isnan(hit.steps) || isinf(hit.steps) || isnan(gl_HitTEXT) || isinf(gl_HitTEXT);
  vec3 n = safe_normalize(transpose(mat3(gl_WorldToObjectEXT)) * hit.normal, -gl_WorldRayDirectionEXT);
#ifdef PROCEDURAY_OUTPUTS
  if (payload.depth == 0u) output_hit(n);  // the camera ray's hit (reflections reuse this shader)
#endif
  // Marched surfaces are found within this threshold: secondary rays start twice as far out.
  float threshold = march_knobs_threshold(constants.knobs[arguments.object_id], constants.camera.pixel_angle, gl_HitTEXT);
  vec3 colour = shade_surface(p, n, arguments.albedo, arguments.reflectance, hit.steps > 0.0 ? 2.0 * threshold : 0.0);
  payload.nonfinite |= (bad || nonfinite3(colour)) ? 1u : 0u;
  payload.colour = colour;
  payload.object_id = arguments.object_id;
  payload.steps = hit.steps;
}
