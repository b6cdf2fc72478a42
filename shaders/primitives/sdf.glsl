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

PROCEDURAY_INLINE real sdf_sphere(real3 p, real r) { return length(p) - r; }

PROCEDURAY_INLINE real sdf_box(real3 p, real3 half_size) {
  real3 q = abs(p) - half_size;
  return length(max(q, real3(R(0.0)))) + min(max(q.x, max(q.y, q.z)), R(0.0));
}

/// A box of half size b with edges rounded by r (its outside distance is exact).
PROCEDURAY_INLINE real sdf_round_box(real3 p, real3 b, real r) { return sdf_box(p, b) - r; }

/// Torus in the xz plane: ring radius t.x, tube radius t.y.
PROCEDURAY_INLINE real sdf_torus(real3 p, real2 t) {
  real2 q = real2(length(real2(p.x, p.z)) - t.x, p.y);
  return length(q) - t.y;
}

/// The 8-norm of q: a rounded square; <= the 2-norm, so distances built on it stay 1-Lipschitz.
PROCEDURAY_INLINE real sdf_length8(real2 q) {
  real2 a = abs(q);
  real m = max(a.x, a.y);
  if (!(m > R(0.0))) return R(0.0);
  real2 r = a / m;  // in [0, 1]: r^8 cannot overflow
  real2 r2 = r * r;
  real2 r4 = r2 * r2;
  return m * pow(r4.x * r4.x + r4.y * r4.y, R(0.125));
}

/// Torus with a square-ish (8-norm) tube.
PROCEDURAY_INLINE real sdf_torus82(real3 p, real2 t) {
  real2 q = real2(length(real2(p.x, p.z)) - t.x, p.y);
  return sdf_length8(q) - t.y;
}

/// Capped cylinder about y: radius h.x, half height h.y.
PROCEDURAY_INLINE real sdf_capped_cylinder(real3 p, real2 h) {
  real2 d = abs(real2(length(real2(p.x, p.z)), p.y)) - h;
  return min(max(d.x, d.y), R(0.0)) + length(max(d, real2(R(0.0))));
}

/// p rotated about y by angle k * p.y (the twist).
PROCEDURAY_INLINE real3 sdf_twist(real3 p, real k) {
  real c = cos(k * p.y);
  real s = sin(k * p.y);
  return real3(c * p.x - s * p.z, p.y, s * p.x + c * p.z);
}

/// A 4 x 4 x 4 grid of spheres (cell 0.5), cut to the box.
PROCEDURAY_INLINE real sdf_mini_spheres_distance(real3 p) {
  real3 q = mod(p, real3(R(0.5))) - real3(R(0.25));  // own cell's centre is the nearest: exact
  return max(sdf_sphere(q, R(0.17)), sdf_box(p, real3(R(0.95))));
}

/// A rounded cube intersected with a sphere.
PROCEDURAY_INLINE real sdf_round_cube_distance(real3 p) {
  return max(sdf_round_box(p, real3(R(0.55)), R(0.25)), sdf_sphere(p, R(0.98)));
}

/// A torus standing in the xy plane, twisted about y by k radians per unit height.
PROCEDURAY_INLINE real sdf_twisted_torus_distance(real3 p, real k) {
  real3 q = sdf_twist(p, k);
  return sdf_torus(real3(q.x, q.z, q.y), real2(R(0.6), R(0.2)));
}

/// A gear lying in the xz plane: disc, twelve teeth, axle hole.
PROCEDURAY_INLINE real sdf_cog_distance(real3 p) {
  real rho = length(real2(p.x, p.z));
  real sector = R(6.28318531) / R(12.0);
  real a = rho > R(1.0e-20) ? atan(p.z, p.x) : R(0.0);  // atan(0, 0) is undefined
  real a_local = mod(a + R(0.5) * sector, sector) - R(0.5) * sector;
  real3 q = real3(rho * cos(a_local) - R(0.8), p.y, rho * sin(a_local));  // in the tooth's frame
  real body = min(sdf_capped_cylinder(p, real2(R(0.7), R(0.15))), sdf_box(q, real3(R(0.12), R(0.15), R(0.07))));
  return max(body, -sdf_capped_cylinder(p, real2(R(0.25), R(0.3))));
}

/// Four upright cylinders on a 2 x 2 grid (cell 1), cut to the box.
PROCEDURAY_INLINE real sdf_cylinder_distance(real3 p) {
  real3 q = real3(mod(p.x, R(1.0)) - R(0.5), p.y, mod(p.z, R(1.0)) - R(0.5));
  return max(sdf_capped_cylinder(q, real2(R(0.3), R(0.9))), sdf_box(p, real3(R(0.95))));
}

/// The square pyramid with apex (0, 1, 0) and base y = -1 (corners (+-1, -1, +-1)): the
/// largest of its face-plane distances (a lower bound of the distance, 1-Lipschitz).
PROCEDURAY_INLINE real sdf_pyramid_planes(real3 p) {
  const real inv_sqrt5 = R(0.4472136);
  real side = max(R(2.0) * abs(p.x), R(2.0) * abs(p.z)) + p.y - R(1.0);
  return max(side * inv_sqrt5, -R(1.0) - p.y);
}

/// Vertex k of the pyramid: 0 the apex, 1 to 4 the base corners.
PROCEDURAY_INLINE real3 sdf_pyramid_vertex(int k) {
  if (k == 0) return real3(R(0.0), R(1.0), R(0.0));
  return real3((k & 1) != 0 ? R(1.0) : -R(1.0), -R(1.0), k > 2 ? R(1.0) : -R(1.0));
}

/// Sierpinski pyramid: the pyramid is the union of five half-size copies at its vertices,
/// `iterations` levels deep. Each level follows the copy of the nearest vertex and bounds the
/// other four by their pyramids' planes, so the result is a lower bound of the distance to the
/// union: following one copy alone overestimates near fold seams (7 of 3000 random points in
/// the CPU test), where the march may step across thin parts (24 pixels of a 64x64 view on an
/// H100 disagreed with the CPU). Steps of this bound never cross the surface.
PROCEDURAY_INLINE real sdf_fractal_pyramid_distance(real3 p, uint iterations) {
  real scale = R(1.0);
  real others = R(3.0e38);  // lower bound over the copies not followed
  real3 z = p;
  for (uint i = 0u; i < iterations; ++i) {
    int nearest = 0;
    real best = R(3.0e38);
    for (int k = 0; k < 5; ++k) {
      real3 e = z - sdf_pyramid_vertex(k);
      real d2 = dot(e, e);
      if (d2 < best) { best = d2; nearest = k; }
    }
    for (int k = 0; k < 5; ++k) {
      if (k != nearest) others = min(others, R(0.5) * scale * sdf_pyramid_planes(R(2.0) * z - sdf_pyramid_vertex(k)));
    }
    z = R(2.0) * z - sdf_pyramid_vertex(nearest);
    scale *= R(0.5);
  }
  return min(sdf_pyramid_planes(z) * scale, others);
}

/// The distance of primitive `kind` at local point p.
PROCEDURAY_INLINE real sdf_distance(uint kind, real3 p, real4 params) {
  real s = params.x > R(0.0) ? params.x : R(1.0);
  real3 q = p / s;
  real d;
  if (kind == sdf_mini_spheres) d = sdf_mini_spheres_distance(q);
  else if (kind == sdf_round_cube) d = sdf_round_cube_distance(q);
  else if (kind == sdf_square_torus) d = sdf_torus82(q, real2(R(0.7), R(0.2)));
  else if (kind == sdf_twisted_torus) d = sdf_twisted_torus_distance(q, params.y);
  else if (kind == sdf_cog) d = sdf_cog_distance(q);
  else if (kind == sdf_cylinder) d = sdf_cylinder_distance(q);
  else d = sdf_fractal_pyramid_distance(q, uint(clamp(params.y, R(0.0), R(8.0))));
  return d * s;
}

/// Lipschitz bound of sdf_distance(kind, ., params): sphere tracing steps d / L never cross the surface.
PROCEDURAY_INLINE real sdf_lipschitz(uint kind, real4 params) {
  // The twist's Jacobian is a rotation plus k * rho in one column: |J| <= 1 + |k| rho, rho <= sqrt(2) in the box.
  if (kind == sdf_twisted_torus) return R(1.0) + abs(params.y) * R(1.4142136);
  return R(1.0);
}

#endif
