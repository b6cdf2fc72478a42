#version 460
// Sky: constants.sky_colour at the zenith, lighter towards the horizon.
void main() {
  vec3 d = gl_WorldRayDirectionEXT;
  float up = clamp(d.y / max(length(d), 1.0e-30), 0.0, 1.0);
  payload.colour = mix(mix(constants.sky_colour, vec3(1.0), 0.6), constants.sky_colour, sqrt(up));
  payload.object_id = 0u;
  payload.steps = 0.0;
}
