#version 460
// hit.threshold over the knobs' threshold at this hit, in world units (constants.knobs are the
// field's): red 0.5 where they agree, so a test reads the ratio from the image.
void main() {
  float t = gl_HitTEXT * length(gl_WorldRayDirectionEXT);
  MarchKnobs k = constants.knobs;
  float expected = uint(k.threshold_mode) == 1u ? k.threshold : max(k.epsilon, k.threshold * constants.camera.pixel_angle * t);
  payload.rgb = vec3(0.5 * hit.threshold / expected, 0.0, 1.0);
}
