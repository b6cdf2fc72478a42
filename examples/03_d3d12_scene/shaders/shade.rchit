#version 460
// Every primitive: the local normal from the intersection shader, the record's material,
// Phong, shadow and reflection. Flags NaN or infinity in what the intersection reported.
#include "surface.glsl"

void main() {
  vec3 p = gl_WorldRayOriginEXT + gl_HitTEXT * gl_WorldRayDirectionEXT;
  bool bad = nonfinite3(hit.normal) || isnan(hit.steps) || isinf(hit.steps) || isnan(gl_HitTEXT) || isinf(gl_HitTEXT);
  vec3 n = safe_normalize(transpose(mat3(gl_WorldToObjectEXT)) * hit.normal, -gl_WorldRayDirectionEXT);
#ifdef PROCEDURAY_OUTPUTS
  if (payload.depth == 0u) output_hit(n);  // the camera ray's hit (reflections reuse this shader)
#endif
  // A marched hit lies within hit.threshold of the surface: secondary rays start twice as far out.
  vec3 colour = shade_surface(p, n, arguments.albedo, arguments.reflectance, 2.0 * hit.threshold);
  payload.nonfinite |= (bad || nonfinite3(colour)) ? 1u : 0u;
  payload.colour = colour;
  payload.object_id = arguments.object_id;
  payload.steps = hit.steps;
}
