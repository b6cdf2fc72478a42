// The body of the analytic and volumetric intersection shaders (the SDFs are distance fields,
// whose intersection the library writes): the record's primitive, intersected in local
// (= object) space with the knobs from `constants`, reported when valid for this ray
// (t in [gl_RayTminEXT, gl_RayTmaxEXT], cull flags honoured: the sample's IsAValidHit).
// The march follows the primitive's own knobs, constants.knobs[arguments.object_id].
// Marching runs along the unit object-space direction: world lengths in the knobs are divided
// by the instance's scale; the footprint term is an angle and needs none. It reports FieldHit,
// as the fields do (threshold: the knobs' at the hit, 0 for analytic hits). With per-pixel
// outputs it adds its evaluations and sets the exhausted and NaN flags.
#ifndef D3D12_INTERSECT_GLSL
#define D3D12_INTERSECT_GLSL

#include "primitives/d3d12_knobs.glsl"

void intersect_record_primitive() {
  vec3 o = gl_ObjectRayOriginEXT;
  vec3 d = gl_ObjectRayDirectionEXT;
  uint cull = 0u;
  if ((gl_IncomingRayFlagsEXT & gl_RayFlagsCullBackFacingTrianglesEXT) != 0u) cull |= hit_cull_back;
  if ((gl_IncomingRayFlagsEXT & gl_RayFlagsCullFrontFacingTrianglesEXT) != 0u) cull |= hit_cull_front;
  float len = max(length(d), 1.0e-30);
  float world_per_object = max(length(gl_WorldRayDirectionEXT) / len, 1.0e-20);
  MarchKnobs k = constants.knobs[arguments.object_id];
  float t;
  vec3 n;
  float steps;
  bool found = d3d12_intersect_knobs(arguments.kind, arguments.params, arguments.spin, constants.time, o, d,
                                     gl_RayTminEXT, gl_RayTmaxEXT, cull, k, world_per_object,
                                     constants.camera.pixel_angle, t, n, steps);
  output_steps(uint(steps) + (found && arguments.kind > primitive_metaballs ? march_normal_evaluations(k) : 0u));
#ifdef PROCEDURAY_OUTPUTS
  // Marches that ran out of steps (the metaballs' fixed march never does: its steps are fixed).
  if (!found && arguments.kind >= primitive_metaballs && steps >= float(k.max_steps)) output_flags(output_flag_exhausted);
  if (found && (isnan(t) || any(isnan(n)))) output_flags(output_flag_nan);
#endif
  if (!found) return;
  hit.normal = n;
  hit.steps = steps;
  hit.threshold = steps > 0.0 ? march_knobs_threshold(k, constants.camera.pixel_angle, t) : 0.0;
  reportIntersectionEXT(t, 0u);
}

#endif
