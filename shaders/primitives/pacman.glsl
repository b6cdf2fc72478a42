// Pac-man: the unit sphere minus a wedge, by interval CSG (no marching, exact normals).
//
//   float t; vec3 n;
//   if (pacman_intersect(o, d, radians(35.0f), t_lo, t_hi, t, n)) reportIntersectionEXT(t, 0u);
//
// Object space: centre at the origin, radius 1, mouth opening towards +z with its hinge on
// the x axis. The wedge is W = H1 ∩ H2 with H_j = {p : dot(n_j, p) <= 0}, where
// n_1 = (0, cos a, -sin a) and n_2 = (0, -cos a, -sin a) for the half-angle a in (0, pi/2).
// Along the ray, the sphere is one interval [s0, s1] and W another [w0, w1] (each half-space
// gives a half-line; no infinities are needed because W is only asked for inside [s0, s1]).
// Sphere minus wedge is then at most two intervals, [s0, w0] and [w1, s1]; the hit is the
// first of their end points inside [t_lo, t_hi], so a ray starting inside the solid (a
// shadow ray from the inner face) finds where it leaves. `d` need not be unit length.
// Normals point out of the solid: p on the sphere, -n_j on wedge face j.
#ifndef PROCEDURAY_PRIMITIVES_PACMAN_GLSL
#define PROCEDURAY_PRIMITIVES_PACMAN_GLSL

#include "../common/compat.glsl"
#include "sphere.glsl"

/// Narrows [w0, w1] to where o + t d lies in {dot(n, p) <= 0}; `face` records which plane bounds it.
PROCEDURAY_INLINE void pacman_clip_half_space(pr_real3 o, pr_real3 d, pr_real3 n, int id, PROCEDURAY_INOUT(pr_real) w0,
                                              PROCEDURAY_INOUT(pr_real) w1, PROCEDURAY_INOUT(int) face0,
                                              PROCEDURAY_INOUT(int) face1) {
  pr_real dn = dot(n, d);
  pr_real on = dot(n, o);
  if (abs(dn) <= PR(1.0e-20)) {  // parallel to the plane: inside for every t, or for none
    if (on > PR(0.0)) w1 = w0 - PR(1.0);
    return;
  }
  pr_real t = -on / dn;
  if (dn > PR(0.0)) {
    if (t < w1) { w1 = t; face1 = id; }
  } else {
    if (t > w0) { w0 = t; face0 = id; }
  }
}

/// First boundary of sphere-minus-wedge with t in [t_lo, t_hi]: its t and outward object-space normal.
PROCEDURAY_INLINE bool pacman_intersect(pr_real3 o, pr_real3 d, pr_real half_angle, pr_real t_lo, pr_real t_hi,
                                        PROCEDURAY_OUT(pr_real) t_hit, PROCEDURAY_OUT(pr_real3) normal) {
  t_hit = PR(0.0);
  normal = pr_real3(PR(0.0), PR(0.0), PR(1.0));
  pr_real s0, s1;
  if (!ray_sphere(o, d, pr_real3(PR(0.0)), PR(1.0), s0, s1)) return false;
  pr_real c = cos(half_angle);
  pr_real s = sin(half_angle);
  pr_real3 n1 = pr_real3(PR(0.0), c, -s);
  pr_real3 n2 = pr_real3(PR(0.0), -c, -s);
  pr_real w0 = s0;
  pr_real w1 = s1;
  int face0 = 0;  // 0: the sphere bounds the wedge interval; 1, 2: plane n_1, n_2
  int face1 = 0;
  pacman_clip_half_space(o, d, n1, 1, w0, w1, face0, face1);
  pacman_clip_half_space(o, d, n2, 2, w0, w1, face0, face1);
  bool wedge = w0 < w1;
  // Candidate boundary points in ray order, each with its face (0 sphere, 1 or 2 a plane).
  pr_real ts[4];
  int faces[4];
  int count = 0;
  if (!wedge) {
    ts[0] = s0; faces[0] = 0;
    ts[1] = s1; faces[1] = 0;
    count = 2;
  } else {
    if (w0 > s0) {  // solid before the wedge: [s0, w0]
      ts[count] = s0; faces[count] = 0; count += 1;
      ts[count] = w0; faces[count] = face0; count += 1;
    }
    if (w1 < s1) {  // solid after the wedge: [w1, s1]
      ts[count] = w1; faces[count] = face1; count += 1;
      ts[count] = s1; faces[count] = 0; count += 1;
    }
  }
  for (int i = 0; i < count; ++i) {
    if (ts[i] >= t_lo && ts[i] <= t_hi) {
      t_hit = ts[i];
      pr_real3 p = o + ts[i] * d;
      normal = faces[i] == 1 ? -n1 : (faces[i] == 2 ? -n2 : p);
      if (faces[i] == 0) normal = dot(p, p) > PR(1.0e-30) ? normal * inversesqrt(dot(p, p)) : pr_real3(PR(0.0), PR(0.0), PR(1.0));
      return true;
    }
  }
  return false;
}

#endif
