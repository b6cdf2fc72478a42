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

const uint metaball_count = 3u;
const uint metaball_method_fixed = 0u;
const uint metaball_method_lipschitz = 1u;
/// Bisection iterations after the fixed march brackets the surface.
const uint metaball_bisections = 10u;

/// Source i at `time` seconds: each moves on its own slow path within |c| < 0.45.
PROCEDURAY_INLINE vec3 metaball_centre(uint i, float time) {
  if (i == 0u) return vec3(-0.3f + 0.15f * sin(1.1f * time), -0.25f, -0.1f);
  if (i == 1u) return vec3(0.3f, -0.05f + 0.2f * cos(0.9f * time), 0.15f);
  return vec3(0.2f * sin(0.7f * time + 1.0f), 0.3f, -0.15f * cos(1.3f * time));
}

/// The falloff of one source at x = distance / R; 1 at the centre, 0 from x = 1 on.
PROCEDURAY_INLINE float metaball_falloff(float x) {
  if (x >= 1.0f) return 0.0f;
  float x3 = x * x * x;
  return 1.0f - x3 * (x * (6.0f * x - 15.0f) + 10.0f);
}

/// F(p): the summed potential.
PROCEDURAY_INLINE float metaball_field(vec3 p, float radius, float time) {
  float f = 0.0f;
  for (uint i = 0u; i < metaball_count; ++i) f += metaball_falloff(length(p - metaball_centre(i, time)) / radius);
  return f;
}

/// grad F(p), analytic: f'(x) / R * (p - c) / |p - c| = -30 x (1 - x)^2 / R^2 * (p - c), no division by |p - c|.
PROCEDURAY_INLINE vec3 metaball_gradient(vec3 p, float radius, float time) {
  vec3 g = vec3(0.0f);
  for (uint i = 0u; i < metaball_count; ++i) {
    vec3 v = p - metaball_centre(i, time);
    float x = length(v) / radius;
    if (x < 1.0f) g += (-30.0f * x * (1.0f - x) * (1.0f - x) / (radius * radius)) * v;
  }
  return g;
}

/// Lipschitz bound of F: each source's slope is at most 1.875 / R.
PROCEDURAY_INLINE float metaball_lipschitz(float radius) { return float(metaball_count) * 1.875f / radius; }

/// First crossing of F = threshold along o + s u (u unit) in [s_lo, s_hi]; m gives epsilon(s)
/// and, for the Lipschitz method, max_steps; `steps` is the number of field evaluations.
PROCEDURAY_INLINE bool metaballs_march(vec3 o, vec3 u, float s_lo, float s_hi, float radius, float threshold, float time,
                                       uint method, uint fixed_steps, MarchSettings m, PROCEDURAY_OUT(float) s_hit,
                                       PROCEDURAY_OUT(vec3) normal, PROCEDURAY_OUT(uint) steps) {
  s_hit = s_lo;
  normal = vec3(0.0f, 1.0f, 0.0f);
  steps = 0u;
  if (!(radius > 0.0f) || !(s_hi >= s_lo)) return false;
  bool found = false;
  float start_value = metaball_field(o + s_lo * u, radius, time) - threshold;
  steps = 1u;
  bool start_inside = start_value > 0.0f;
  if (method == metaball_method_lipschitz) {
    float lipschitz = metaball_lipschitz(radius);
    float a = s_lo;  // last point on the start's side
    float s = s_lo;
    float v = start_value;
    for (uint i = 0u; i < m.max_steps; ++i) {
      // No surface within |v| / L of o + s u; below the threshold the march takes epsilon(s)
      // steps, so a crossing is bracketed by [a, s] and bisected as the fixed march does.
      s = a + max(abs(v) / lipschitz, march_epsilon(m, a));
      if (s > s_hi) break;
      v = metaball_field(o + s * u, radius, time) - threshold;
      steps += 1u;
      if ((v > 0.0f) != start_inside) {
        found = true;
        break;
      }
      a = s;
    }
    if (found) {
      float b = s;
      for (uint k = 0u; k < metaball_bisections; ++k) {
        float mid = 0.5f * (a + b);
        float vm = metaball_field(o + mid * u, radius, time) - threshold;
        steps += 1u;
        if ((vm > 0.0f) != start_inside) b = mid;
        else a = mid;
      }
      s_hit = b;
    }
  } else {
    uint n = max(fixed_steps, 1u);
    float ds = (s_hi - s_lo) / float(n);
    float a = s_lo;
    for (uint i = 1u; i <= n; ++i) {
      float b = s_lo + float(i) * ds;
      float v = metaball_field(o + b * u, radius, time) - threshold;
      steps += 1u;
      if ((v > 0.0f) != start_inside) {
        for (uint k = 0u; k < metaball_bisections; ++k) {  // keep a on the start's side, b across
          float mid = 0.5f * (a + b);
          float vm = metaball_field(o + mid * u, radius, time) - threshold;
          steps += 1u;
          if ((vm > 0.0f) != start_inside) b = mid;
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
