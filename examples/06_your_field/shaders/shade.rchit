#version 460
// Lambert from the field's normal (FieldHit::normal is object space: into world space here).
void main() {
  vec3 n = normalize(hit.normal * mat3(gl_WorldToObjectEXT));
  float light = max(dot(n, normalize(frame.light)), 0.0);
  payload.colour = arguments.albedo * (0.15 + 0.85 * light);
}
