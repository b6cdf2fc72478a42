#version 460
// The floor asks the "tint" callable for its colour, then darkens it when a shadow ray toward
// the light hits something on the "casts_shadow" layer: to 0.35 when the hit was opaque, to
// 0.5 when a cut-out's shadow any-hit accepted it (occluded = 2).
void main() {
  tint_call.colour = arguments.rgb.rgb;
  executeCallableEXT(tint_callable, int(tint_callable));
  vec3 p = gl_WorldRayOriginEXT + gl_HitTEXT * gl_WorldRayDirectionEXT;
  shadow.occluded = 1u;
  traceRayEXT(tlas, shadow_flags, shadow_mask, shadow_ray, ray_count, shadow_ray, p + vec3(0.0, 1e-3, 0.0), 0.0,
              normalize(constants.light.xyz), 1e30, int(shadow_ray));
  payload.rgb = tint_call.colour * (shadow.occluded == 2u ? 0.5 : shadow.occluded != 0u ? 0.35 : 1.0);
}
