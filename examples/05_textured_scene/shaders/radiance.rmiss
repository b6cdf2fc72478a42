#version 460
// The environment: the sky cube map in the ray's direction, for camera rays and reflections alike.
void main() {
  payload.colour = (constants.flags & flag_normals) != 0u ? vec3(0.0) : textureLod(sky, gl_WorldRayDirectionEXT, 0.0).rgb;
  payload.id = 0u;
}
