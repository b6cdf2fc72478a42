#version 460
void main() {
  output_hit(normalize(hit.normal));
  payload.rgb = vec3(1.0);
}
