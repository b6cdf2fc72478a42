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

const uint sdf_mini_spheres = 3u;
const uint sdf_round_cube = 4u;
const uint sdf_square_torus = 5u;
const uint sdf_twisted_torus = 6u;
const uint sdf_cog = 7u;
const uint sdf_cylinder = 8u;
const uint sdf_fractal_pyramid = 9u;

PROCEDURAY_INLINE float sdf_sphere(vec3 p, float r) { return length(p) - r; }

PROCEDURAY_INLINE float sdf_box(vec3 p, vec3 half_size) {
  vec3 q = abs(p) - half_size;
  return length(max(q, vec3(0.0f))) + min(max(q.x, max(q.y, q.z)), 0.0f);
}

/// A box of half size b with edges rounded by r (its outside distance is exact).
PROCEDURAY_INLINE float sdf_round_box(vec3 p, vec3 b, float r) { return sdf_box(p, b) - r; }

/// Torus in the xz plane: ring radius t.x, tube radius t.y.
PROCEDURAY_INLINE float sdf_torus(vec3 p, vec2 t) {
  vec2 q = vec2(length(vec2(p.x, p.z)) - t.x, p.y);
  return length(q) - t.y;
}

/// The 8-norm of q: a rounded square; <= the 2-norm, so distances built on it stay 1-Lipschitz.
PROCEDURAY_INLINE float sdf_length8(vec2 q) {
  vec2 a = abs(q);
  float m = max(a.x, a.y);
  if (!(m > 0.0f)) return 0.0f;
  vec2 r = a / m;  // in [0, 1]: r^8 cannot overflow
  vec2 r2 = r * r;
  vec2 r4 = r2 * r2;
  return m * pow(r4.x * r4.x + r4.y * r4.y, 0.125f);
}

/// Torus with a square-ish (8-norm) tube.
PROCEDURAY_INLINE float sdf_torus82(vec3 p, vec2 t) {
  vec2 q = vec2(length(vec2(p.x, p.z)) - t.x, p.y);
  return sdf_length8(q) - t.y;
}

/// Capped cylinder about y: radius h.x, half height h.y.
PROCEDURAY_INLINE float sdf_capped_cylinder(vec3 p, vec2 h) {
  vec2 d = abs(vec2(length(vec2(p.x, p.z)), p.y)) - h;
  return min(max(d.x, d.y), 0.0f) + length(max(d, vec2(0.0f)));
}

/// p rotated about y by angle k * p.y (the twist).
PROCEDURAY_INLINE vec3 sdf_twist(vec3 p, float k) {
  float c = cos(k * p.y);
  float s = sin(k * p.y);
  return vec3(c * p.x - s * p.z, p.y, s * p.x + c * p.z);
}

/// A 4 x 4 x 4 grid of spheres (cell 0.5), cut to the box.
PROCEDURAY_INLINE float sdf_mini_spheres_distance(vec3 p) {
  vec3 q = mod(p, vec3(0.5f)) - vec3(0.25f);  // own cell's centre is the nearest: exact
  return max(sdf_sphere(q, 0.17f), sdf_box(p, vec3(0.95f)));
}

/// A rounded cube intersected with a sphere.
PROCEDURAY_INLINE float sdf_round_cube_distance(vec3 p) {
  return max(sdf_round_box(p, vec3(0.55f), 0.25f), sdf_sphere(p, 0.98f));
}

/// A torus standing in the xy plane, twisted about y by k radians per unit height.
PROCEDURAY_INLINE float sdf_twisted_torus_distance(vec3 p, float k) {
  vec3 q = sdf_twist(p, k);
  return sdf_torus(vec3(q.x, q.z, q.y), vec2(0.6f, 0.2f));
}

/// A gear lying in the xz plane: disc, twelve teeth, axle hole.
PROCEDURAY_INLINE float sdf_cog_distance(vec3 p) {
  float rho = length(vec2(p.x, p.z));
  float sector = 6.28318531f / 12.0f;
  float a = rho > 1.0e-20f ? atan(p.z, p.x) : 0.0f;  // atan(0, 0) is undefined
  float a_local = mod(a + 0.5f * sector, sector) - 0.5f * sector;
  vec3 q = vec3(rho * cos(a_local) - 0.8f, p.y, rho * sin(a_local));  // in the tooth's frame
  float body = min(sdf_capped_cylinder(p, vec2(0.7f, 0.15f)), sdf_box(q, vec3(0.12f, 0.15f, 0.07f)));
  return max(body, -sdf_capped_cylinder(p, vec2(0.25f, 0.3f)));
}

/// Four upright cylinders on a 2 x 2 grid (cell 1), cut to the box.
PROCEDURAY_INLINE float sdf_cylinder_distance(vec3 p) {
  vec3 q = vec3(mod(p.x, 1.0f) - 0.5f, p.y, mod(p.z, 1.0f) - 0.5f);
  return max(sdf_capped_cylinder(q, vec2(0.3f, 0.9f)), sdf_box(p, vec3(0.95f)));
}

/// The square pyramid with apex (0, 1, 0) and base y = -1 (corners (+-1, -1, +-1)): the
/// largest of its face-plane distances (a lower bound of the distance, 1-Lipschitz).
PROCEDURAY_INLINE float sdf_pyramid_planes(vec3 p) {
  const float inv_sqrt5 = 0.4472136f;
  float side = max(2.0f * abs(p.x), 2.0f * abs(p.z)) + p.y - 1.0f;
  return max(side * inv_sqrt5, -1.0f - p.y);
}

/// Vertex k of the pyramid: 0 the apex, 1 to 4 the base corners.
PROCEDURAY_INLINE vec3 sdf_pyramid_vertex(int k) {
  if (k == 0) return vec3(0.0f, 1.0f, 0.0f);
  return vec3((k & 1) != 0 ? 1.0f : -1.0f, -1.0f, k > 2 ? 1.0f : -1.0f);
}

/// Sierpinski pyramid: the pyramid is the union of five half-size copies at its vertices,
/// `iterations` levels deep. Each level follows the copy of the nearest vertex and bounds the
/// other four by their pyramids' planes, so the result is a lower bound of the distance to the
/// union: following one copy alone overestimates near fold seams (7 of 3000 random points in
/// the CPU test), where the march may step across thin parts (24 pixels of a 64x64 view on an
/// H100 disagreed with the CPU). Steps of this bound never cross the surface.
PROCEDURAY_INLINE float sdf_fractal_pyramid_distance(vec3 p, uint iterations) {
  float scale = 1.0f;
  float others = 3.0e38f;  // lower bound over the copies not followed
  vec3 z = p;
  for (uint i = 0u; i < iterations; ++i) {
    int nearest = 0;
    float best = 3.0e38f;
    for (int k = 0; k < 5; ++k) {
      vec3 e = z - sdf_pyramid_vertex(k);
      float d2 = dot(e, e);
      if (d2 < best) { best = d2; nearest = k; }
    }
    for (int k = 0; k < 5; ++k) {
      if (k != nearest) others = min(others, 0.5f * scale * sdf_pyramid_planes(2.0f * z - sdf_pyramid_vertex(k)));
    }
    z = 2.0f * z - sdf_pyramid_vertex(nearest);
    scale *= 0.5f;
  }
  return min(sdf_pyramid_planes(z) * scale, others);
}

/// The distance of primitive `kind` at local point p.
PROCEDURAY_INLINE float sdf_distance(uint kind, vec3 p, vec4 params) {
  float s = params.x > 0.0f ? params.x : 1.0f;
  vec3 q = p / s;
  float d;
  if (kind == sdf_mini_spheres) d = sdf_mini_spheres_distance(q);
  else if (kind == sdf_round_cube) d = sdf_round_cube_distance(q);
  else if (kind == sdf_square_torus) d = sdf_torus82(q, vec2(0.7f, 0.2f));
  else if (kind == sdf_twisted_torus) d = sdf_twisted_torus_distance(q, params.y);
  else if (kind == sdf_cog) d = sdf_cog_distance(q);
  else if (kind == sdf_cylinder) d = sdf_cylinder_distance(q);
  else d = sdf_fractal_pyramid_distance(q, uint(clamp(params.y, 0.0f, 8.0f)));
  return d * s;
}

/// Lipschitz bound of sdf_distance(kind, ., params): sphere tracing steps d / L never cross the surface.
PROCEDURAY_INLINE float sdf_lipschitz(uint kind, vec4 params) {
  // The twist's Jacobian is a rotation plus k * rho in one column: |J| <= 1 + |k| rho, rho <= sqrt(2) in the box.
  if (kind == sdf_twisted_torus) return 1.0f + abs(params.y) * 1.4142136f;
  return 1.0f;
}

#endif
