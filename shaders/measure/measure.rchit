#version 460
// The field's hit as the measuring scene's outputs: t, the world normal, ids.
void main() {
  payload.hit = 1u;
  output_hit(normalize(hit.normal * mat3(gl_WorldToObjectEXT)));
}
