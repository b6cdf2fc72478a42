#version 460
// texture_test.cpp: the floor shows texture `layer` of `grounds` at uv = (x, z) / 12 + 0.5 (one
// copy across the floor), `repeat` times over, at the mip level whose texel matches the pixel's
// footprint on the floor (camera.pixel_angle * t).
void main() {
  vec3 p = gl_WorldRayOriginEXT + gl_WorldRayDirectionEXT * gl_HitTEXT;
  vec2 uv = (p.xz / 12.0 + 0.5) * arguments.repeat;
  float texel = 12.0 / (arguments.repeat * float(textureSize(grounds[0], 0).x));
  float lod = max(0.0, log2(constants.camera.pixel_angle * gl_HitTEXT / texel));
  vec4 c = arguments.layer == 0u ? textureLod(grounds[0], uv, lod) : textureLod(grounds[1], uv, lod);
  payload.rgb = c.rgb;
}
