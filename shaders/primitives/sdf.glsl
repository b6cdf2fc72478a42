// Signed distance primitives of the D3D12 sample (after Inigo Quilez's distance functions),
// each inside the box [-1, 1]^3 at scale 1, with the Lipschitz bound its sphere tracing
// divides steps by (1 for exact distances and for min / max / repetition of them).
//
//   float d = sdf_distance(sdf_cog, p, params);          // params.x: scale in (0, 1]
//   float k = 1.0f / sdf_lipschitz(sdf_cog, params);     // MarchSettings::step_scale
//
// params.x scales the primitive (d(p / s) * s keeps the bound); params.y is the twist rate
// (radians per unit height) of the twisted torus and the iteration count of the fractal
// pyramid. Guards: atan(0, 0) and pow of negatives never happen; every function is finite for
// finite p. Written to common/compat.glsl's rules (compiles as C++ against GLM).
#ifndef PROCEDURAY_PRIMITIVES_SDF_GLSL
#define PROCEDURAY_PRIMITIVES_SDF_GLSL

#include "../common/compat.glsl"

PROCEDURAY_CONST uint sdf_mini_spheres = 3u;
PROCEDURAY_CONST uint sdf_round_cube = 4u;
PROCEDURAY_CONST uint sdf_square_torus = 5u;
PROCEDURAY_CONST uint sdf_twisted_torus = 6u;
PROCEDURAY_CONST uint sdf_cog = 7u;
PROCEDURAY_CONST uint sdf_cylinder = 8u;
PROCEDURAY_CONST uint sdf_fractal_pyramid = 9u;

PROCEDURAY_INLINE pr_real sdf_sphere(pr_real3 p, pr_real r) { return length(p) - r; }

PROCEDURAY_INLINE pr_real sdf_box(pr_real3 p, pr_real3 half_size) {
  pr_real3 q = abs(p) - half_size;
  return length(max(q, pr_real3(PR(0.0)))) + min(max(q.x, max(q.y, q.z)), PR(0.0));
}

/// A box of half size b with edges rounded by r (its outside distance is exact).
PROCEDURAY_INLINE pr_real sdf_round_box(pr_real3 p, pr_real3 b, pr_real r) { return sdf_box(p, b) - r; }

/// Torus in the xz plane: ring radius t.x, tube radius t.y.
PROCEDURAY_INLINE pr_real sdf_torus(pr_real3 p, pr_real2 t) {
  pr_real2 q = pr_real2(length(pr_real2(p.x, p.z)) - t.x, p.y);
  return length(q) - t.y;
}

/// The 8-norm of q: a rounded square; <= the 2-norm, so distances built on it stay 1-Lipschitz.
PROCEDURAY_INLINE pr_real sdf_length8(pr_real2 q) {
  pr_real2 a = abs(q);
  pr_real m = max(a.x, a.y);
  if (!(m > PR(0.0))) return PR(0.0);
  pr_real2 r = a / m;  // in [0, 1]: r^8 cannot overflow
  pr_real2 r2 = r * r;
  pr_real2 r4 = r2 * r2;
  return m * pow(r4.x * r4.x + r4.y * r4.y, PR(0.125));
}

/// Torus with a square-ish (8-norm) tube.
PROCEDURAY_INLINE pr_real sdf_torus82(pr_real3 p, pr_real2 t) {
  pr_real2 q = pr_real2(length(pr_real2(p.x, p.z)) - t.x, p.y);
  return sdf_length8(q) - t.y;
}

/// Capped cylinder about y: radius h.x, half height h.y.
PROCEDURAY_INLINE pr_real sdf_capped_cylinder(pr_real3 p, pr_real2 h) {
  pr_real2 d = abs(pr_real2(length(pr_real2(p.x, p.z)), p.y)) - h;
  return min(max(d.x, d.y), PR(0.0)) + length(max(d, pr_real2(PR(0.0))));
}

/// p rotated about y by angle k * p.y (the twist).
PROCEDURAY_INLINE pr_real3 sdf_twist(pr_real3 p, pr_real k) {
  pr_real c = cos(k * p.y);
  pr_real s = sin(k * p.y);
  return pr_real3(c * p.x - s * p.z, p.y, s * p.x + c * p.z);
}

/// A 4 x 4 x 4 grid of spheres (cell 0.5), cut to the box.
PROCEDURAY_INLINE pr_real sdf_mini_spheres_distance(pr_real3 p) {
  pr_real3 q = mod(p, pr_real3(PR(0.5))) - pr_real3(PR(0.25));  // own cell's centre is the nearest: exact
  return max(sdf_sphere(q, PR(0.17)), sdf_box(p, pr_real3(PR(0.95))));
}

/// A rounded cube intersected with a sphere.
PROCEDURAY_INLINE pr_real sdf_round_cube_distance(pr_real3 p) {
  return max(sdf_round_box(p, pr_real3(PR(0.55)), PR(0.25)), sdf_sphere(p, PR(0.98)));
}

/// A torus standing in the xy plane, twisted about y by k radians per unit height.
PROCEDURAY_INLINE pr_real sdf_twisted_torus_distance(pr_real3 p, pr_real k) {
  pr_real3 q = sdf_twist(p, k);
  return sdf_torus(pr_real3(q.x, q.z, q.y), pr_real2(PR(0.6), PR(0.2)));
}

/// A gear lying in the xz plane: disc, twelve teeth, axle hole.
PROCEDURAY_INLINE pr_real sdf_cog_distance(pr_real3 p) {
  pr_real rho = length(pr_real2(p.x, p.z));
  pr_real sector = PR(6.28318531) / PR(12.0);
  pr_real a = rho > PR(1.0e-20) ? atan(p.z, p.x) : PR(0.0);  // atan(0, 0) is undefined
  pr_real a_local = mod(a + PR(0.5) * sector, sector) - PR(0.5) * sector;
  pr_real3 q = pr_real3(rho * cos(a_local) - PR(0.8), p.y, rho * sin(a_local));  // in the tooth's frame
  pr_real body = min(sdf_capped_cylinder(p, pr_real2(PR(0.7), PR(0.15))), sdf_box(q, pr_real3(PR(0.12), PR(0.15), PR(0.07))));
  return max(body, -sdf_capped_cylinder(p, pr_real2(PR(0.25), PR(0.3))));
}

/// Four upright cylinders on a 2 x 2 grid (cell 1), cut to the box.
PROCEDURAY_INLINE pr_real sdf_cylinder_distance(pr_real3 p) {
  pr_real3 q = pr_real3(mod(p.x, PR(1.0)) - PR(0.5), p.y, mod(p.z, PR(1.0)) - PR(0.5));
  return max(sdf_capped_cylinder(q, pr_real2(PR(0.3), PR(0.9))), sdf_box(p, pr_real3(PR(0.95))));
}

/// The square pyramid with apex (0, 1, 0) and base y = -1 (corners (+-1, -1, +-1)): the
/// largest of its face-plane distances (a lower bound of the distance, 1-Lipschitz).
PROCEDURAY_INLINE pr_real sdf_pyramid_planes(pr_real3 p) {
  const pr_real inv_sqrt5 = PR(0.4472136);
  pr_real side = max(PR(2.0) * abs(p.x), PR(2.0) * abs(p.z)) + p.y - PR(1.0);
  return max(side * inv_sqrt5, -PR(1.0) - p.y);
}

/// Vertex k of the pyramid: 0 the apex, 1 to 4 the base corners.
PROCEDURAY_INLINE pr_real3 sdf_pyramid_vertex(int k) {
  if (k == 0) return pr_real3(PR(0.0), PR(1.0), PR(0.0));
  return pr_real3((k & 1) != 0 ? PR(1.0) : -PR(1.0), -PR(1.0), k > 2 ? PR(1.0) : -PR(1.0));
}

/// Sierpinski pyramid: the pyramid is the union of five half-size copies at its vertices,
/// `iterations` levels deep. Each level follows the copy of the nearest vertex and bounds the
/// other four by their pyramids' planes, so the result is a lower bound of the distance to the
/// union: following one copy alone overestimates near fold seams (7 of 3000 random points in
/// the CPU test), where the march may step across thin parts (24 pixels of a 64x64 view on an
/// H100 disagreed with the CPU). Steps of this bound never cross the surface.
PROCEDURAY_INLINE pr_real sdf_fractal_pyramid_distance(pr_real3 p, uint iterations) {
  pr_real scale = PR(1.0);
  pr_real others = PR(3.0e38);  // lower bound over the copies not followed
  pr_real3 z = p;
  for (uint i = 0u; i < iterations; ++i) {
    int nearest = 0;
    pr_real best = PR(3.0e38);
    for (int k = 0; k < 5; ++k) {
      pr_real3 e = z - sdf_pyramid_vertex(k);
      pr_real d2 = dot(e, e);
      if (d2 < best) { best = d2; nearest = k; }
    }
    for (int k = 0; k < 5; ++k) {
      if (k != nearest) others = min(others, PR(0.5) * scale * sdf_pyramid_planes(PR(2.0) * z - sdf_pyramid_vertex(k)));
    }
    z = PR(2.0) * z - sdf_pyramid_vertex(nearest);
    scale *= PR(0.5);
  }
  return min(sdf_pyramid_planes(z) * scale, others);
}

/// The distance of primitive `kind` at local point p.
PROCEDURAY_INLINE pr_real sdf_distance(uint kind, pr_real3 p, pr_real4 params) {
  pr_real s = params.x > PR(0.0) ? params.x : PR(1.0);
  pr_real3 q = p / s;
  pr_real d;
  if (kind == sdf_mini_spheres) d = sdf_mini_spheres_distance(q);
  else if (kind == sdf_round_cube) d = sdf_round_cube_distance(q);
  else if (kind == sdf_square_torus) d = sdf_torus82(q, pr_real2(PR(0.7), PR(0.2)));
  else if (kind == sdf_twisted_torus) d = sdf_twisted_torus_distance(q, params.y);
  else if (kind == sdf_cog) d = sdf_cog_distance(q);
  else if (kind == sdf_cylinder) d = sdf_cylinder_distance(q);
  else d = sdf_fractal_pyramid_distance(q, uint(clamp(params.y, PR(0.0), PR(8.0))));
  return d * s;
}

/// Lipschitz bound of sdf_distance(kind, ., params): sphere tracing steps d / L never cross the surface.
PROCEDURAY_INLINE pr_real sdf_lipschitz(uint kind, pr_real4 params) {
  // The twist's Jacobian is a rotation plus k * rho in one column: |J| <= 1 + |k| rho, rho <= sqrt(2) in the box.
  if (kind == sdf_twisted_torus) return PR(1.0) + abs(params.y) * PR(1.4142136);
  return PR(1.0);
}

#endif
