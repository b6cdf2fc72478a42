#version 460
// Spheres and the blob: the intersection's object-space normal, made world-space.
#include "surface.glsl"

void main() {
  vec3 p = gl_WorldRayOriginEXT + gl_HitTEXT * gl_WorldRayDirectionEXT;
  // Normals take the inverse transpose of the object-to-world transform.
  shade(p, safe_normalize(transpose(mat3(gl_WorldToObjectEXT)) * hit.normal, -gl_WorldRayDirectionEXT));
}
