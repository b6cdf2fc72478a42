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
PROCEDURAY_INLINE pr_real3 phong(pr_real3 albedo, pr_real3 n, pr_real3 l, pr_real3 v, pr_real3 light_colour, pr_real diffuse, pr_real specular,
                             pr_real shininess) {
  pr_real n_dot_l = max(dot(n, l), PR(0.0));
  pr_real3 r = PR(2.0) * dot(n, l) * n - l;  // l mirrored about n
  pr_real spec = n_dot_l > PR(0.0) ? pow(max(dot(r, v), PR(0.0)), max(shininess, PR(1.0))) : PR(0.0);
  return light_colour * (diffuse * n_dot_l * albedo + specular * spec * pr_real3(PR(1.0)));
}

/// Schlick's Fresnel reflectance for normal-incidence reflectance f0 at cos_theta = dot(n, v).
PROCEDURAY_INLINE pr_real schlick_fresnel(pr_real f0, pr_real cos_theta) {
  pr_real m = clamp(PR(1.0) - cos_theta, PR(0.0), PR(1.0));
  pr_real m2 = m * m;
  return f0 + (PR(1.0) - f0) * m2 * m2 * m;
}

#endif
