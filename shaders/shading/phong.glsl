// Phong lighting and Schlick's Fresnel approximation, as the report's closest-hit shaders use.
//
//   vec3 c = phong(albedo, n, l, v, light_colour, diffuse, specular, shininess);
//   float f = schlick_fresnel(f0, dot(n, v));     // weight of the reflected colour
//   colour = mix(local, reflected, f);
//
// n, l (towards the light) and v (towards the viewer) are unit vectors. NaN guards: pow gets
// non-negative bases and a positive exponent (pow(0, y <= 0) and pow(x < 0, y) are undefined).
#ifndef PROCEDURAY_SHADING_PHONG_GLSL
#define PROCEDURAY_SHADING_PHONG_GLSL

#include "../common/compat.glsl"

/// Diffuse plus specular reflection of one light; no ambient term.
PROCEDURAY_INLINE vec3 phong(vec3 albedo, vec3 n, vec3 l, vec3 v, vec3 light_colour, float diffuse, float specular,
                             float shininess) {
  float n_dot_l = max(dot(n, l), 0.0f);
  vec3 r = 2.0f * dot(n, l) * n - l;  // l mirrored about n
  float spec = n_dot_l > 0.0f ? pow(max(dot(r, v), 0.0f), max(shininess, 1.0f)) : 0.0f;
  return light_colour * (diffuse * n_dot_l * albedo + specular * spec * vec3(1.0f));
}

/// Schlick's Fresnel reflectance for normal-incidence reflectance f0 at cos_theta = dot(n, v).
PROCEDURAY_INLINE float schlick_fresnel(float f0, float cos_theta) {
  float m = clamp(1.0f - cos_theta, 0.0f, 1.0f);
  float m2 = m * m;
  return f0 + (1.0f - f0) * m2 * m2 * m;
}

#endif
