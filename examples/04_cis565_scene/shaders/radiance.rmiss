#version 460
// The sky, brighter toward the horizon.
void main() {
  float up = clamp(gl_WorldRayDirectionEXT.y, 0.0, 1.0);
  payload.colour = mix(vec3(1.0), constants.sky.rgb, sqrt(up));
  payload.id = 0u;
}
