#version 460
// Counts this plane and traces on from just past it: a cycle (the ray's own closest hit), so the
// nesting is as deep as the stack of planes unless the depth counter stops it.
void main() {
  const vec3 at = gl_WorldRayOriginEXT + gl_WorldRayDirectionEXT * gl_HitTEXT;
  const Colour counted = Colour(payload.rgb + vec3(1.0, 0.0, 0.0));
  payload = trace_primary(at, 1e-3, gl_WorldRayDirectionEXT, 1e30, counted);
}
