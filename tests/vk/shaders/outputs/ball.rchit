#version 460
// White where the ball is; its t, normal and ids through the generated helper.
void main() {
  output_hit(normalize(hit.normal));
  payload.rgb = vec3(1.0);
}
