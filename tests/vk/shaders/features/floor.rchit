#version 460
// The floor asks the "tint" callable for its colour, then darkens it when a shadow ray toward
// the light hits something on the "casts_shadow" layer: to 0.35 when the hit was opaque, to
// 0.5 when a cut-out's shadow any-hit accepted it (occluded = 2).
// The generated tint_call and trace_shadow fill the callable index, SBT offsets and payload
// locations from the scene's declarations.
void main() {
  TintCall tint = tint_call(TintCall(arguments.rgb.rgb));
  vec3 p = gl_WorldRayOriginEXT + gl_HitTEXT * gl_WorldRayDirectionEXT;
  Shadow seen = trace_shadow(p + vec3(0.0, 1e-3, 0.0), 0.0, normalize(constants.light.xyz), 1e30, Shadow(1u));
  payload.rgb = tint.colour * (seen.occluded == 2u ? 0.5 : seen.occluded != 0u ? 0.35 : 1.0);
}
