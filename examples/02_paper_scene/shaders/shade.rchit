#version 460
// Every procedural object: the object-space normal from the intersection shader, the
// material from this hit record, Phong + Schlick-Fresnel, shadow and reflection rays.
#include "surface.glsl"

void main() {
  vec3 p = gl_WorldRayOriginEXT + gl_HitTEXT * gl_WorldRayDirectionEXT;
  // Normals take the inverse transpose of the object-to-world transform.
  vec3 n = safe_normalize(transpose(mat3(gl_WorldToObjectEXT)) * hit.normal, -gl_WorldRayDirectionEXT);
#ifdef PROCEDURAY_OUTPUTS
  if (payload.depth == 0u) output_hit(n);  // the camera ray's hit (reflections reuse this shader)
#endif
  // A marched hit lies within hit.threshold of the surface: secondary rays start twice as far
  // out so they do not find the same surface at once. Analytic hits are exact but for rounding.
  vec3 colour = shade_surface(p, n, arguments.albedo, hit.steps > 0.0 ? 2.0 * hit.threshold : 1.0e-4);
  payload.colour = colour;
  payload.object_id = arguments.object_id;
  payload.steps = hit.steps;
}
