// Metaballs (blobs): the isosurface F(p) = threshold of a potential field summed over point
// sources, each with the quintic falloff f(x) = 1 - (6x^5 - 15x^4 + 10x^3), x = |p - c| / R,
// zero beyond the influence radius R. Two marches, both in [s_lo, s_hi] along a unit u:
//   metaball_method_fixed      the D3D12 sample's: `steps` equal steps, then bisection of the
//                              first sign change (thin necks narrower than a step are missed);
//   metaball_method_lipschitz  steps of max(|F - threshold| / L, epsilon(s)), L = count * 1.875 / R
//                              the field's Lipschitz bound (|f'| <= 1.875 at x = 1/2): no step
//                              longer than epsilon crosses the surface; the crossing is bisected.
//                              (Stopping where the bound falls below epsilon instead would accept
//                              near misses within L * epsilon of the threshold: fat silhouettes.)
//
//   float s; vec3 n; uint steps;
//   if (metaballs_march(o, u, s_lo, s_hi, 0.6f, 0.25f, time, metaball_method_fixed, 128u, m, s, n, steps)) ...
//
// Normals are analytic: -grad F, normalised. A ray starting inside finds where it leaves.
// R must be > 0 (the host rejects 0); here R <= 0 returns a miss, never a NaN.
#ifndef PROCEDURAY_PRIMITIVES_METABALLS_GLSL
#define PROCEDURAY_PRIMITIVES_METABALLS_GLSL

#include "../common/compat.glsl"
#include "../common/ray.glsl"
#include "../marching/sphere_trace.glsl"

PROCEDURAY_CONST uint metaball_count = 3u;
PROCEDURAY_CONST uint metaball_method_fixed = 0u;
PROCEDURAY_CONST uint metaball_method_lipschitz = 1u;
/// Bisection iterations after the fixed march brackets the surface.
PROCEDURAY_CONST uint metaball_bisections = 10u;

/// Source i at `time` seconds: each moves on its own slow path within |c| < 0.45.
PROCEDURAY_INLINE real3 metaball_centre(uint i, real time) {
  if (i == 0u) return real3(-R(0.3) + R(0.15) * sin(R(1.1) * time), -R(0.25), -R(0.1));
  if (i == 1u) return real3(R(0.3), -R(0.05) + R(0.2) * cos(R(0.9) * time), R(0.15));
  return real3(R(0.2) * sin(R(0.7) * time + R(1.0)), R(0.3), -R(0.15) * cos(R(1.3) * time));
}

/// The falloff of one source at x = distance / R; 1 at the centre, 0 from x = 1 on.
PROCEDURAY_INLINE real metaball_falloff(real x) {
  if (x >= R(1.0)) return R(0.0);
  real x3 = x * x * x;
  return R(1.0) - x3 * (x * (R(6.0) * x - R(15.0)) + R(10.0));
}

/// F(p): the summed potential.
PROCEDURAY_INLINE real metaball_field(real3 p, real radius, real time) {
  real f = R(0.0);
  for (uint i = 0u; i < metaball_count; ++i) f += metaball_falloff(length(p - metaball_centre(i, time)) / radius);
  return f;
}

/// grad F(p), analytic: f'(x) / R * (p - c) / |p - c| = -30 x (1 - x)^2 / R^2 * (p - c), no division by |p - c|.
PROCEDURAY_INLINE real3 metaball_gradient(real3 p, real radius, real time) {
  real3 g = real3(R(0.0));
  for (uint i = 0u; i < metaball_count; ++i) {
    real3 v = p - metaball_centre(i, time);
    real x = length(v) / radius;
    if (x < R(1.0)) g += (-R(30.0) * x * (R(1.0) - x) * (R(1.0) - x) / (radius * radius)) * v;
  }
  return g;
}

/// Lipschitz bound of F: each source's slope is at most 1.875 / R.
PROCEDURAY_INLINE real metaball_lipschitz(real radius) { return real(metaball_count) * R(1.875) / radius; }

/// First crossing of F = threshold along o + s u (u unit) in [s_lo, s_hi]; m gives epsilon(s)
/// and, for the Lipschitz method, max_steps; `steps` is the number of field evaluations.
PROCEDURAY_INLINE bool metaballs_march(real3 o, real3 u, real s_lo, real s_hi, real radius, real threshold, real time,
                                       uint method, uint fixed_steps, MarchSettings m, PROCEDURAY_OUT(real) s_hit,
                                       PROCEDURAY_OUT(real3) normal, PROCEDURAY_OUT(uint) steps) {
  s_hit = s_lo;
  normal = real3(R(0.0), R(1.0), R(0.0));
  steps = 0u;
  if (!(radius > R(0.0)) || !(s_hi >= s_lo)) return false;
  bool found = false;
  real start_value = metaball_field(o + s_lo * u, radius, time) - threshold;
  steps = 1u;
  bool start_inside = start_value > R(0.0);
  if (method == metaball_method_lipschitz) {
    real lipschitz = metaball_lipschitz(radius);
    real a = s_lo;  // last point on the start's side
    real s = s_lo;
    real v = start_value;
    for (uint i = 0u; i < m.max_steps; ++i) {
      // No surface within |v| / L of o + s u; below the threshold the march takes epsilon(s)
      // steps, so a crossing is bracketed by [a, s] and bisected as the fixed march does.
      s = a + max(abs(v) / lipschitz, march_epsilon(m, a));
      if (s > s_hi) break;
      v = metaball_field(o + s * u, radius, time) - threshold;
      steps += 1u;
      if ((v > R(0.0)) != start_inside) {
        found = true;
        break;
      }
      a = s;
    }
    if (found) {
      real b = s;
      for (uint k = 0u; k < metaball_bisections; ++k) {
        real mid = R(0.5) * (a + b);
        real vm = metaball_field(o + mid * u, radius, time) - threshold;
        steps += 1u;
        if ((vm > R(0.0)) != start_inside) b = mid;
        else a = mid;
      }
      s_hit = b;
    }
  } else {
    uint n = max(fixed_steps, 1u);
    real ds = (s_hi - s_lo) / real(n);
    real a = s_lo;
    for (uint i = 1u; i <= n; ++i) {
      real b = s_lo + real(i) * ds;
      real v = metaball_field(o + b * u, radius, time) - threshold;
      steps += 1u;
      if ((v > R(0.0)) != start_inside) {
        for (uint k = 0u; k < metaball_bisections; ++k) {  // keep a on the start's side, b across
          real mid = R(0.5) * (a + b);
          real vm = metaball_field(o + mid * u, radius, time) - threshold;
          steps += 1u;
          if ((vm > R(0.0)) != start_inside) b = mid;
          else a = mid;
        }
        s_hit = b;
        found = true;
        break;
      }
      a = b;
    }
  }
  if (!found) return false;
  normal = safe_normalize(-metaball_gradient(o + s_hit * u, radius, time), -u);
  return true;
}

#endif
