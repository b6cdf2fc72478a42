#version 460
// A bead: a sphere coloured by its slot on the ring, found from where its instance sits.
#include "surface.glsl"

// The record is a shaderRecordEXT block, not a Material value: copy its members.
Material record_material() {
  return Material(arguments.albedo, arguments.diffuse, arguments.specular, arguments.shininess, arguments.reflectance,
                  arguments.id);
}

void main() {
  vec3 centre = gl_ObjectToWorldEXT[3];
  float turn = atan(centre.z - 2.6, centre.x / 3.2) / 6.2831853;  // the ring: x = 3.2 cos a, z = 2.6 + sin a
  float hue = fract(turn + 1.0);
  Material m = record_material();
  m.albedo = clamp(abs(fract(hue + vec3(0.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0) - 1.0, 0.0, 1.0) * 0.8 + 0.15;
  shade(gl_WorldRayOriginEXT + gl_HitTEXT * gl_WorldRayDirectionEXT, world_normal(hit.normal), m);
}
