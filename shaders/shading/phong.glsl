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
PROCEDURAY_INLINE real3 phong(real3 albedo, real3 n, real3 l, real3 v, real3 light_colour, real diffuse, real specular,
                             real shininess) {
  real n_dot_l = max(dot(n, l), R(0.0));
  real3 r = R(2.0) * dot(n, l) * n - l;  // l mirrored about n
  real spec = n_dot_l > R(0.0) ? pow(max(dot(r, v), R(0.0)), max(shininess, R(1.0))) : R(0.0);
  return light_colour * (diffuse * n_dot_l * albedo + specular * spec * real3(R(1.0)));
}

/// Schlick's Fresnel reflectance for normal-incidence reflectance f0 at cos_theta = dot(n, v).
PROCEDURAY_INLINE real schlick_fresnel(real f0, real cos_theta) {
  real m = clamp(R(1.0) - cos_theta, R(0.0), R(1.0));
  real m2 = m * m;
  return f0 + (R(1.0) - f0) * m2 * m2 * m;
}

#endif
