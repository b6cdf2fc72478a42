#version 460
// The ground: two triangles at y = 0, checkered in world space, reflective.
#include "surface.glsl"

void main() {
  vec3 p = gl_WorldRayOriginEXT + gl_HitTEXT * gl_WorldRayDirectionEXT;
  vec3 n = safe_normalize(transpose(mat3(gl_WorldToObjectEXT)) * vec3(0.0, 1.0, 0.0), vec3(0.0, 1.0, 0.0));
#ifdef PROCEDURAY_OUTPUTS
  if (payload.depth == 0u) output_hit(n);
#endif
  vec3 albedo = arguments.albedo;
  if (arguments.checker > 0.0) {
    ivec2 cell = ivec2(floor(vec2(p.x, p.z) / arguments.checker));
    if (((cell.x + cell.y) & 1) != 0) albedo *= 0.45;
  }
  vec3 colour = shade_surface(p, n, albedo, arguments.reflectance, 0.0);
  payload.nonfinite |= nonfinite3(colour) ? 1u : 0u;
  payload.colour = colour;
  payload.object_id = arguments.object_id;
  payload.steps = 0.0;
}
