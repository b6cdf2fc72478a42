#version 460
void main() {
  vec3 n = normalize(transpose(mat3(gl_WorldToObjectEXT)) * hit.normal);
  payload.rgb = arguments.albedo.rgb * (0.2 + 0.8 * max(dot(n, normalize(vec3(1, 1, 1))), 0.0));
}
