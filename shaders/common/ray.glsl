// Ray utilities every intersection and hit shader needs: clipping a ray to a box without
// IEEE infinities, the t range test, NaN-free normalisation, and secondary-ray origins.
//
//   float t0 = gl_RayTminEXT, t1 = gl_RayTmaxEXT;
//   if (!ray_clip_aabb(o, d, box_min, box_max, t0, t1)) return;   // [t0, t1] now inside the box
//   if (t_in_range(t, gl_RayTminEXT, gl_RayTmaxEXT)) reportIntersectionEXT(t, 0u);
//   vec3 n = safe_normalize(v, vec3(0.0f, 1.0f, 0.0f));
//   vec3 origin = offset_ray_origin(hit_point, geometric_normal);   // float (also in C++)
//
// Why no infinities: the usual slab test divides by direction components and relies on
// 1/0 = inf. Vulkan does not promise IEEE infinities (without SignedZeroInfNanPreserve a
// driver may flush them, and 0 * inf is NaN anyway), so a direction component below
// `ray_parallel_epsilon` in magnitude is treated as parallel: the ray is inside that slab
// for every t, or for none. Every quotient formed is then finite for boxes within 1e6.
#ifndef PROCEDURAY_COMMON_RAY_GLSL
#define PROCEDURAY_COMMON_RAY_GLSL

#include "compat.glsl"

/// Direction components at or below this magnitude count as parallel to the slab.
PROCEDURAY_CONST pr_real ray_parallel_epsilon = PR(1.0e-20);

/// One slab of the clip: narrows [t_near, t_far] to the t where o + t d lies in [lo, hi].
PROCEDURAY_INLINE bool ray_clip_slab(pr_real o, pr_real d, pr_real lo, pr_real hi, PROCEDURAY_INOUT(pr_real) t_near,
                                     PROCEDURAY_INOUT(pr_real) t_far) {
  if (abs(d) <= ray_parallel_epsilon) return o >= lo && o <= hi;  // parallel: all t or none
  pr_real inv = PR(1.0) / d;
  pr_real ta = (lo - o) * inv;
  pr_real tb = (hi - o) * inv;
  t_near = max(t_near, min(ta, tb));
  t_far = min(t_far, max(ta, tb));
  return t_near <= t_far;
}

/// Clips [t_near, t_far] to the box; false when nothing is left. An origin on a face counts as inside.
PROCEDURAY_INLINE bool ray_clip_aabb(pr_real3 o, pr_real3 d, pr_real3 box_min, pr_real3 box_max, PROCEDURAY_INOUT(pr_real) t_near,
                                     PROCEDURAY_INOUT(pr_real) t_far) {
  return ray_clip_slab(o.x, d.x, box_min.x, box_max.x, t_near, t_far) &&
         ray_clip_slab(o.y, d.y, box_min.y, box_max.y, t_near, t_far) &&
         ray_clip_slab(o.z, d.z, box_min.z, box_max.z, t_near, t_far);
}

/// Whether t is a hit the ray accepts (the D3D12 sample's IsInRange): t_min <= t <= t_max.
PROCEDURAY_INLINE bool t_in_range(pr_real t, pr_real t_min, pr_real t_max) { return t >= t_min && t <= t_max; }

/// v / |v|, or `fallback` when |v| is too small to divide by (normalize(0) is NaN).
PROCEDURAY_INLINE pr_real3 safe_normalize(pr_real3 v, pr_real3 fallback) {
  pr_real len2 = dot(v, v);
  return len2 > PR(1.0e-30) ? v * inversesqrt(len2) : fallback;
}

/// Moves a hit point off its surface along the geometric normal `n` (pointing to the side the
/// new ray leaves on), so a shadow or reflection ray does not hit the surface it starts on.
/// The offset is a fixed number of float ulps of each coordinate, so it works at any distance
/// from the origin; near the origin, where ulps are tiny, a small absolute offset is used
/// instead (the method of Waechter and Binder, Ray Tracing Gems ch. 6). The price is a contact
/// leak: an occluder nearer the surface than the offset (up to int_scale = 256 ulps of the
/// largest coordinate, or float_scale = 2^-16 near the origin) is stepped over.
/// Float only, in C++ too (vec3, not pr_real3): the offset counts float ulps, and a double
/// version would need other constants. In C++ floatBitsToInt / intBitsToFloat are GLM's (its
/// GLSL core functions, same semantics), so a class-template includer instantiates this
/// member in both precisions without error, and it always works in float.
PROCEDURAY_INLINE vec3 offset_ray_origin(vec3 p, vec3 n) {
  const float near_origin = PR(1.0) / PR(32.0);
  const float float_scale = PR(1.0) / PR(65536.0);
  const float int_scale = PR(256.0);
  ivec3 of_i = ivec3(int_scale * n);
  vec3 p_i = vec3(intBitsToFloat(floatBitsToInt(p.x) + (p.x < PR(0.0) ? -of_i.x : of_i.x)),
                  intBitsToFloat(floatBitsToInt(p.y) + (p.y < PR(0.0) ? -of_i.y : of_i.y)),
                  intBitsToFloat(floatBitsToInt(p.z) + (p.z < PR(0.0) ? -of_i.z : of_i.z)));
  return vec3(abs(p.x) < near_origin ? p.x + float_scale * n.x : p_i.x,
              abs(p.y) < near_origin ? p.y + float_scale * n.y : p_i.y,
              abs(p.z) < near_origin ? p.z + float_scale * n.z : p_i.z);
}

#endif
