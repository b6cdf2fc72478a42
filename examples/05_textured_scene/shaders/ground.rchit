#version 460
// The ground, y = 0: its texture (tiles) at uv = xz * ground_scale, at the mip level whose texel
// matches the ray's footprint there, times the material; flag_albedo shows the texture unlit.
#include "surface.glsl"

// The record is a shaderRecordEXT block, not a Material value: copy its members.
Material record_material() {
  return Material(arguments.albedo, arguments.diffuse, arguments.specular, arguments.shininess, arguments.reflectance,
                  arguments.id);
}

void main() {
  vec3 p = gl_WorldRayOriginEXT + gl_HitTEXT * gl_WorldRayDirectionEXT;
  vec2 uv = p.xz * constants.ground_scale;
  float texel = 1.0 / (constants.ground_scale * float(textureSize(ground, 0).x));  // world units
  float lod = max(0.0, log2(constants.camera.pixel_angle * gl_HitTEXT / texel));
  vec3 albedo = textureLod(ground, uv, lod).rgb;
  if ((constants.flags & flag_albedo) != 0u) {
    payload.colour = albedo;
    payload.id = arguments.id;
    return;
  }
  Material m = record_material();
  m.albedo *= albedo;
  shade(p, vec3(0.0, 1.0, 0.0), m);
}
