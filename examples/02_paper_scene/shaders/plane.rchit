#version 460
// The ground: two triangles in the object-space plane y = 0, checkered in object space, so the
// checker stays on the plane when the scene is drawn relative to another origin (world.hpp).
#include "surface.glsl"

void main() {
  vec3 p = gl_WorldRayOriginEXT + gl_HitTEXT * gl_WorldRayDirectionEXT;
  vec3 n = safe_normalize(transpose(mat3(gl_WorldToObjectEXT)) * vec3(0.0, 1.0, 0.0), vec3(0.0, 1.0, 0.0));
#ifdef PROCEDURAY_OUTPUTS
  if (payload.depth == 0u) output_hit(n);
#endif
  vec3 albedo = arguments.albedo;
  if (arguments.checker_size > 0.0) {
    vec3 q = gl_WorldToObjectEXT * vec4(p, 1.0);
    ivec2 cell = ivec2(floor(q.xz / arguments.checker_size));
    if (((cell.x + cell.y) & 1) != 0) albedo = arguments.albedo_alt;
  }
  vec3 colour = shade_surface(p, n, albedo, 0.0);
  payload.colour = colour;
  payload.object_id = arguments.object_id;
  payload.steps = 0.0;
}
