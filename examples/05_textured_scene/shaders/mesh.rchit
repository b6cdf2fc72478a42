#version 460
// The torus from the OBJ file: the normal interpolated from its vertices (MeshRef<ObjVertex>,
// read at the hit's barycentrics), or with flag_flat the triangle's own face normal.
#include "surface.glsl"

hitAttributeEXT vec2 bary;

void main() {
  vec3 p = gl_WorldRayOriginEXT + gl_HitTEXT * gl_WorldRayDirectionEXT;
  vec3 n;
  if ((constants.flags & flag_flat) != 0u) {
    uvec3 t = triangle_indices(arguments.mesh, gl_PrimitiveID);
    vec3 a = vertex(arguments.mesh, t.x).position, b = vertex(arguments.mesh, t.y).position;
    n = cross(b - a, vertex(arguments.mesh, t.z).position - a);
  } else {
    n = interpolate(arguments.mesh, gl_PrimitiveID, bary).normal;
  }
  shade(p, world_normal(n), arguments.material);
}
