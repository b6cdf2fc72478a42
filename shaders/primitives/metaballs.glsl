// Metaballs (blobs): the isosurface F(p) = threshold of a potential field summed over point
// sources, each with the quintic falloff f(x) = 1 - (6x^5 - 15x^4 + 10x^3), x = |p - c| / R,
// zero beyond the influence radius R. Three marches, all in [s_lo, s_hi] along a unit u:
//   metaball_method_fixed      the D3D12 sample's: `steps` equal steps, then bisection of the
//                              first sign change (thin necks narrower than a step are missed);
//   metaball_method_lipschitz  steps of max(|F - threshold| / L, epsilon(s)), L = count * 1.875 / R
//                              the field's Lipschitz bound (|f'| <= 1.875 at x = 1/2): no step
//                              longer than epsilon crosses the surface; the crossing is bisected.
//                              (Stopping where the bound falls below epsilon instead would accept
//                              near misses within L * epsilon of the threshold: fat silhouettes.)
//   metaball_method_segment    segment tracing (Galin et al. 2020): the same steps, but L is the
//                              field's Lipschitz bound over the next segment only (each source's
//                              slope over the distances the segment takes, 0 for a source it does
//                              not reach), and the segment grows by metaball_segment_growth per
//                              step: long steps where one ball's flank is all the ray sees.
// Every march ends with metaball_bisections bisections of the crossing (none when m.hit_rule is
// march_hit_unrefined: then the last point on the start's side is reported).
//
//   float s; vec3 n; uint steps;
//   MetaballList balls = metaballs_at(constants.blob, time);   // any balls (metaball_motion.glsl), or
//   MetaballList three = metaball_sample(0.6f, time);          // the D3D12 sample's three, radius 0.6
//   if (metaballs_march(o, u, s_lo, s_hi, balls, 0.25f, metaball_method_segment, 128u, m, s, n, steps)) ...
//   metaballs_march(o, u, s_lo, s_hi, 0.6f, 0.25f, time, ...)  // the sample's, as before
//
// The balls are data: a MetaballList holds up to metaball_max sources (centre, radius) at one
// time; proceduray::Metaballs (march/metaballs.hpp) is the uniform or record form with motion,
// and proceduray::metaballs_bounds gives its box. Each source has its own radius; the Lipschitz
// bound is count * 1.875 / (smallest radius), exact for equal radii.
//
// Normals are analytic: -grad F, normalised. A ray starting inside finds where it leaves.
// R must be > 0 (the host rejects 0); here a list with a radius <= 0, or no ball, is a miss, never a NaN.
#ifndef PROCEDURAY_PRIMITIVES_METABALLS_GLSL
#define PROCEDURAY_PRIMITIVES_METABALLS_GLSL

#include "../common/compat.glsl"
#include "../common/ray.glsl"
#include "../marching/sphere_trace.glsl"

PROCEDURAY_CONST uint metaball_count = 3u;  // the D3D12 sample's
/// Sources a MetaballList holds (proceduray::max_metaballs).
PROCEDURAY_CONST uint metaball_max = 8u;
PROCEDURAY_CONST uint metaball_method_fixed = 0u;
PROCEDURAY_CONST uint metaball_method_lipschitz = 1u;
PROCEDURAY_CONST uint metaball_method_segment = 2u;
/// Segment tracing: the next segment is this many times the last step (Galin et al. use 2).
PROCEDURAY_CONST pr_real metaball_segment_growth = PR(2.0);
/// Bisection iterations after the fixed march brackets the surface.
PROCEDURAY_CONST uint metaball_bisections = 10u;

/// Sources at one time: ball[i].xyz the centre, ball[i].w the radius; the first `count` count.
struct MetaballList {
  pr_real4 ball[metaball_max];
  uint count;
};

/// Source i of the D3D12 sample at `time` seconds: each moves on its own slow path within |c| < 0.45.
PROCEDURAY_INLINE pr_real3 metaball_centre(uint i, pr_real time) {
  if (i == 0u) return pr_real3(-PR(0.3) + PR(0.15) * sin(PR(1.1) * time), -PR(0.25), -PR(0.1));
  if (i == 1u) return pr_real3(PR(0.3), -PR(0.05) + PR(0.2) * cos(PR(0.9) * time), PR(0.15));
  return pr_real3(PR(0.2) * sin(PR(0.7) * time + PR(1.0)), PR(0.3), -PR(0.15) * cos(PR(1.3) * time));
}

/// The D3D12 sample's three sources at `time`, all of radius `radius`.
PROCEDURAY_INLINE MetaballList metaball_sample(pr_real radius, pr_real time) {
  MetaballList list;
  for (uint i = 0u; i < metaball_max; ++i) list.ball[i] = pr_real4(PR(0.0));
  for (uint i = 0u; i < metaball_count; ++i) {
    pr_real3 c = metaball_centre(i, time);
    list.ball[i] = pr_real4(c.x, c.y, c.z, radius);
  }
  list.count = metaball_count;
  return list;
}

/// Centre and radius of source i.
PROCEDURAY_INLINE pr_real3 metaball_position(MetaballList b, uint i) { return pr_real3(b.ball[i].x, b.ball[i].y, b.ball[i].z); }
/// The sources that count: at most metaball_max.
PROCEDURAY_INLINE uint metaball_used(MetaballList b) { return min(b.count, metaball_max); }

/// The smallest radius, or 0 when a radius is not positive or there is no source (then: no surface).
PROCEDURAY_INLINE pr_real metaball_min_radius(MetaballList b) {
  uint n = metaball_used(b);
  if (n == 0u) return PR(0.0);
  pr_real r = b.ball[0].w;
  for (uint i = 1u; i < n; ++i) r = min(r, b.ball[i].w);
  return r > PR(0.0) ? r : PR(0.0);
}

/// The falloff of one source at x = distance / R; 1 at the centre, 0 from x = 1 on.
PROCEDURAY_INLINE pr_real metaball_falloff(pr_real x) {
  if (x >= PR(1.0)) return PR(0.0);
  pr_real x3 = x * x * x;
  return PR(1.0) - x3 * (x * (PR(6.0) * x - PR(15.0)) + PR(10.0));
}

/// F(p): the summed potential.
PROCEDURAY_INLINE pr_real metaball_field(pr_real3 p, MetaballList b) {
  pr_real f = PR(0.0);
  for (uint i = 0u; i < metaball_used(b); ++i) f += metaball_falloff(length(p - metaball_position(b, i)) / b.ball[i].w);
  return f;
}
PROCEDURAY_INLINE pr_real metaball_field(pr_real3 p, pr_real radius, pr_real time) { return metaball_field(p, metaball_sample(radius, time)); }

/// grad F(p), analytic: f'(x) / R * (p - c) / |p - c| = -30 x (1 - x)^2 / R^2 * (p - c), no division by |p - c|.
PROCEDURAY_INLINE pr_real3 metaball_gradient(pr_real3 p, MetaballList b) {
  pr_real3 g = pr_real3(PR(0.0));
  for (uint i = 0u; i < metaball_used(b); ++i) {
    pr_real radius = b.ball[i].w;
    pr_real3 v = p - metaball_position(b, i);
    pr_real x = length(v) / radius;
    if (x < PR(1.0)) g += (-PR(30.0) * x * (PR(1.0) - x) * (PR(1.0) - x) / (radius * radius)) * v;
  }
  return g;
}
PROCEDURAY_INLINE pr_real3 metaball_gradient(pr_real3 p, pr_real radius, pr_real time) {
  return metaball_gradient(p, metaball_sample(radius, time));
}

/// Lipschitz bound of F: each source's slope is at most 1.875 / its radius <= 1.875 / the smallest.
PROCEDURAY_INLINE pr_real metaball_lipschitz(MetaballList b) {
  return pr_real(metaball_used(b)) * PR(1.875) / metaball_min_radius(b);
}
PROCEDURAY_INLINE pr_real metaball_lipschitz(pr_real radius) { return pr_real(metaball_count) * PR(1.875) / radius; }

/// Bound on R |f'(x)| = 30 x^2 (1 - x)^2 for x in [lo, hi]: 1.875 at x = 1/2, rising before, falling after, 0 from 1 on.
PROCEDURAY_INLINE pr_real metaball_slope_bound(pr_real lo, pr_real hi) {
  if (lo >= PR(1.0)) return PR(0.0);
  pr_real b = min(hi, PR(1.0));
  if (lo <= PR(0.5) && b >= PR(0.5)) return PR(1.875);
  pr_real x = b < PR(0.5) ? b : lo;
  return PR(30.0) * x * x * (PR(1.0) - x) * (PR(1.0) - x);
}

/// Lipschitz bound of F on the segment o + [a, b] u (u unit): per source, the slope bound over
/// the distances from its centre the segment takes (closest point to farthest end), over its
/// radius. Summed in units of the smallest radius, so equal radii give the single-radius sum.
PROCEDURAY_INLINE pr_real metaball_segment_lipschitz(pr_real3 o, pr_real3 u, pr_real a, pr_real b, MetaballList balls) {
  pr_real r_min = metaball_min_radius(balls);
  pr_real l = PR(0.0);
  for (uint i = 0u; i < metaball_used(balls); ++i) {
    pr_real3 c = metaball_position(balls, i);
    pr_real radius = balls.ball[i].w;
    pr_real closest = clamp(dot(c - o, u), a, b);
    pr_real near = length(o + closest * u - c) / radius;
    pr_real far = max(length(o + a * u - c), length(o + b * u - c)) / radius;
    l += metaball_slope_bound(near, far) * (r_min / radius);
  }
  return l / r_min;
}
PROCEDURAY_INLINE pr_real metaball_segment_lipschitz(pr_real3 o, pr_real3 u, pr_real a, pr_real b, pr_real radius, pr_real time) {
  return metaball_segment_lipschitz(o, u, a, b, metaball_sample(radius, time));
}

/// The crossing lies in (a, b]: a on the start's side. Bisects it (unless hit_rule is
/// march_hit_unrefined) and returns the point reported: b, across, when refined; a when not.
PROCEDURAY_INLINE pr_real metaball_refine(pr_real3 o, pr_real3 u, pr_real a, pr_real b, MetaballList balls, pr_real threshold,
                                       bool start_inside, uint hit_rule, PROCEDURAY_INOUT(uint) steps) {
  if (hit_rule == march_hit_unrefined) return a;
  for (uint k = 0u; k < metaball_bisections; ++k) {  // keep a on the start's side, b across
    pr_real mid = PR(0.5) * (a + b);
    pr_real vm = metaball_field(o + mid * u, balls) - threshold;
    steps += 1u;
    if ((vm > PR(0.0)) != start_inside) b = mid;
    else a = mid;
  }
  return b;
}

/// The normal at a crossing: -grad F, turned to -u where the gradient vanishes.
PROCEDURAY_INLINE pr_real3 metaball_normal(pr_real3 p, pr_real3 u, MetaballList balls) {
  return safe_normalize(-metaball_gradient(p, balls), -u);
}

/// The D3D12 sample's march: `count` equal steps across [s_lo, s_hi], then the first sign change
/// bisected (hit_rule: march_hit_refined or march_hit_unrefined). Thin necks narrower than a
/// step are missed. Takes only what it uses: no MarchSettings.
PROCEDURAY_INLINE bool metaballs_march_fixed(pr_real3 o, pr_real3 u, pr_real s_lo, pr_real s_hi, MetaballList balls, pr_real threshold,
                                             uint count, uint hit_rule, PROCEDURAY_OUT(pr_real) s_hit,
                                             PROCEDURAY_OUT(pr_real3) normal, PROCEDURAY_OUT(uint) steps) {
  s_hit = s_lo;
  normal = pr_real3(PR(0.0), PR(1.0), PR(0.0));
  steps = 0u;
  if (!(metaball_min_radius(balls) > PR(0.0)) || !(s_hi >= s_lo)) return false;
  bool start_inside = metaball_field(o + s_lo * u, balls) - threshold > PR(0.0);
  steps = 1u;
  uint n = max(count, 1u);
  pr_real ds = (s_hi - s_lo) / pr_real(n);
  pr_real a = s_lo;
  for (uint i = 1u; i <= n; ++i) {
    pr_real b = s_lo + pr_real(i) * ds;
    pr_real v = metaball_field(o + b * u, balls) - threshold;
    steps += 1u;
    if ((v > PR(0.0)) != start_inside) {
      s_hit = metaball_refine(o, u, a, b, balls, threshold, start_inside, hit_rule, steps);
      normal = metaball_normal(o + s_hit * u, u, balls);
      return true;
    }
    a = b;
  }
  return false;
}

/// Lipschitz marching (segment: segment tracing) with m's epsilon(s), max_steps and hit_rule.
PROCEDURAY_INLINE bool metaballs_march_lipschitz(pr_real3 o, pr_real3 u, pr_real s_lo, pr_real s_hi, MetaballList balls,
                                                 pr_real threshold, bool segment, MarchSettings m,
                                                 PROCEDURAY_OUT(pr_real) s_hit, PROCEDURAY_OUT(pr_real3) normal,
                                                 PROCEDURAY_OUT(uint) steps) {
  s_hit = s_lo;
  normal = pr_real3(PR(0.0), PR(1.0), PR(0.0));
  steps = 0u;
  if (!(metaball_min_radius(balls) > PR(0.0)) || !(s_hi >= s_lo)) return false;
  pr_real start_value = metaball_field(o + s_lo * u, balls) - threshold;
  steps = 1u;
  bool start_inside = start_value > PR(0.0);
  pr_real lipschitz = metaball_lipschitz(balls);
  pr_real a = s_lo;  // last point on the start's side
  pr_real s = s_lo;
  pr_real v = start_value;
  pr_real length_ahead = s_hi - s_lo;  // segment tracing: the segment the next bound covers
  for (uint i = 0u; i < m.max_steps; ++i) {
    // No surface within |v| / L of o + s u; below the threshold the march takes epsilon(s)
    // steps, so a crossing is bracketed by [a, s] and bisected as the fixed march does.
    pr_real step = abs(v) / lipschitz;
    if (segment) {
      pr_real end = min(a + length_ahead, s_hi);
      pr_real l = metaball_segment_lipschitz(o, u, a, end, balls);
      // The bound holds on [a, end] only: never step past it (no source reaches: the whole segment).
      step = l > PR(0.0) ? min(abs(v) / l, end - a) : end - a;
    }
    step = max(step, march_epsilon(m, a));
    s = a + step;
    if (s > s_hi) break;
    v = metaball_field(o + s * u, balls) - threshold;
    steps += 1u;
    if ((v > PR(0.0)) != start_inside) {
      s_hit = metaball_refine(o, u, a, s, balls, threshold, start_inside, m.hit_rule, steps);
      normal = metaball_normal(o + s_hit * u, u, balls);
      return true;
    }
    a = s;
    length_ahead = metaball_segment_growth * step;
  }
  return false;
}

/// First crossing of F = threshold along o + s u (u unit) in [s_lo, s_hi] by `method` (a
/// metaball_method_*, from the march knobs): the fixed march reads fixed_steps and m.hit_rule,
/// the Lipschitz ones m. `steps` is the number of field evaluations.
PROCEDURAY_INLINE bool metaballs_march(pr_real3 o, pr_real3 u, pr_real s_lo, pr_real s_hi, MetaballList balls, pr_real threshold,
                                       uint method, uint fixed_steps, MarchSettings m, PROCEDURAY_OUT(pr_real) s_hit,
                                       PROCEDURAY_OUT(pr_real3) normal, PROCEDURAY_OUT(uint) steps) {
  if (method == metaball_method_lipschitz || method == metaball_method_segment) {
    return metaballs_march_lipschitz(o, u, s_lo, s_hi, balls, threshold, method == metaball_method_segment, m, s_hit,
                                     normal, steps);
  }
  return metaballs_march_fixed(o, u, s_lo, s_hi, balls, threshold, fixed_steps, m.hit_rule, s_hit, normal, steps);
}
/// The D3D12 sample's three balls of radius `radius` at `time`.
PROCEDURAY_INLINE bool metaballs_march(pr_real3 o, pr_real3 u, pr_real s_lo, pr_real s_hi, pr_real radius, pr_real threshold, pr_real time,
                                       uint method, uint fixed_steps, MarchSettings m, PROCEDURAY_OUT(pr_real) s_hit,
                                       PROCEDURAY_OUT(pr_real3) normal, PROCEDURAY_OUT(uint) steps) {
  return metaballs_march(o, u, s_lo, s_hi, metaball_sample(radius, time), threshold, method, fixed_steps, m, s_hit,
                         normal, steps);
}

#endif
