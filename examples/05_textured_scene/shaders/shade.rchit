#version 460
// The mirror sphere: the intersection's object-space normal, made world-space.
#include "surface.glsl"

// The record is a shaderRecordEXT block, not a Material value: copy its members.
Material record_material() {
  return Material(arguments.albedo, arguments.diffuse, arguments.specular, arguments.shininess, arguments.reflectance,
                  arguments.id);
}

void main() { shade(gl_WorldRayOriginEXT + gl_HitTEXT * gl_WorldRayDirectionEXT, world_normal(hit.normal), record_material()); }
