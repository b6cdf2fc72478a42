// Whitted-style shading, one light at a time: Phong, a hard shadow ray, and a Schlick-weighted
// mirror reflection (Whitted 1980; the report's and the D3D12 sample's closest-hit shaders).
// shading/lights.glsl loops it over a Lights block.
//
//   #include "shading/whitted.glsl"
//   // The scene's rays, traced through its generated functions:
//   float whitted_visibility(vec3 origin, vec3 direction, float dist) {
//     return trace_shadow(origin, 0.0, direction, dist, ShadowPayload(1u)).occluded != 0u ? 0.0 : 1.0;
//   }
//   vec3 whitted_reflection(vec3 origin, vec3 direction, float weight) { ... trace_radiance(...).colour; }
//
//   WhittedMaterial m = WhittedMaterial(albedo, 0.9, 0.4, 40.0, 0.25);   // diffuse, specular, shininess, reflectance
//   vec3 v = -gl_WorldRayDirectionEXT;  n = whitted_facing(n, v);
//   vec3 colour = ambient * m.albedo + whitted_direct(origin, n, v, l, dist, light_colour, m, true);
//   colour = whitted_reflect(colour, origin, n, v, whitted_fresnel(m, n, v), payload.weight, min_weight);
//
// Why the two callbacks: GLSL has no function pointers, and which ray is the shadow ray (its
// payload, its flags, whether it starts behind the surface) is the scene's. GLSL gets them as
// prototypes here, so the includer may define them after the include, or not at all when it
// calls neither whitted_direct nor whitted_reflect (a shader that only returns terms for a
// raygen loop to trace calls whitted_phong and whitted_fresnel). C++ (tests, through proceduray/shader/glsl_cpp.hpp) defines them first, or as members.
#ifndef PROCEDURAY_SHADING_WHITTED_GLSL
#define PROCEDURAY_SHADING_WHITTED_GLSL

#include "../common/compat.glsl"
#include "phong.glsl"

/// A surface as Whitted shading sees it.
struct WhittedMaterial {
  pr_real3 albedo;
  pr_real diffuse;      // Phong's diffuse weight
  pr_real specular;     // Phong's specular weight
  pr_real shininess;    // Phong's exponent, at least 1
  pr_real reflectance;  // Fresnel reflectance at normal incidence; 0: no reflection ray
};

#ifndef __cplusplus
/// 1 when nothing lies between origin and origin + dist * direction, else 0: the scene's shadow ray.
float whitted_visibility(vec3 origin, vec3 direction, float dist);
/// The colour a reflection ray brings back; `weight` is its share of the pixel (for cut-offs).
vec3 whitted_reflection(vec3 origin, vec3 direction, float weight);
#endif

/// n turned to the side v (toward the viewer) is on: a ray may hit either side of a surface.
PROCEDURAY_INLINE pr_real3 whitted_facing(pr_real3 n, pr_real3 v) { return dot(n, v) < PR(0.0) ? -n : n; }

/// Phong of one light (unit direction l toward it) on material m; traces nothing.
PROCEDURAY_INLINE pr_real3 whitted_phong(pr_real3 n, pr_real3 v, pr_real3 l, pr_real3 light_colour, WhittedMaterial m) {
  return phong(m.albedo, n, l, v, light_colour, m.diffuse, m.specular, m.shininess);
}

/// whitted_phong times the light's visibility: a shadow ray from `origin` when `shadows`, none
/// when the light is behind the surface.
PROCEDURAY_INLINE pr_real3 whitted_direct(pr_real3 origin, pr_real3 n, pr_real3 v, pr_real3 l, pr_real dist, pr_real3 light_colour,
                                       WhittedMaterial m, bool shadows) {
  pr_real visible = PR(1.0);
  if (shadows) visible = dot(n, l) > PR(0.0) ? whitted_visibility(origin, l, dist) : PR(0.0);
  return visible * whitted_phong(n, v, l, light_colour, m);
}

/// The reflection's share of the colour: Schlick's Fresnel, 0 for a material that does not reflect.
PROCEDURAY_INLINE pr_real whitted_fresnel(WhittedMaterial m, pr_real3 n, pr_real3 v) {
  return m.reflectance > PR(0.0) ? schlick_fresnel(m.reflectance, dot(n, v)) : PR(0.0);
}

/// `colour` mixed with the reflection from origin along reflect(-v, n), by f. Models no more than
/// the pixel shows: a reflection adding under min_weight of the pixel (weight * f) is not traced.
PROCEDURAY_INLINE pr_real3 whitted_reflect(pr_real3 colour, pr_real3 origin, pr_real3 n, pr_real3 v, pr_real f, pr_real weight,
                                        pr_real min_weight) {
  if (!(f > PR(0.0)) || weight * f < min_weight) return colour;
  return mix(colour, whitted_reflection(origin, reflect(-v, n), weight * f), f);
}

#endif
