// A marcher for one distance function, generated from this file: sphere tracing with run-time
// knobs, fixed steps, the crossing's refinement and difference normals (the rule is
// marching/sphere_trace.glsl's header), with the distance and what it reads passed as
// parameters: no shader state, no callback found by name. No include guard: include it once per
// distance function, after defining three names it consumes (and #undefs):
//
//   struct Bulb { uint iterations; };                               // what the distance reads besides p
//   float bulb_distance(vec3 p, Bulb b) { return mandelbulb_distance(p, b.iterations); }
//   #define PROCEDURAY_MARCHER bulb                   // prefix of the generated functions
//   #define PROCEDURAY_MARCHER_FIELD Bulb             // the distance's second parameter
//   #define PROCEDURAY_MARCHER_DISTANCE bulb_distance // pr_real f(pr_real3 p, FIELD q)
//   #include "marching/marcher.glsl"
//   float s; uint steps;
//   if (bulb_trace(o, u, s_lo, s_hi, m, Bulb(8u), s, steps)) {        // sphere_trace's rule
//     vec3 n = bulb_normal(march_normal_central, o + s * u, h, Bulb(8u));   // or march_knobs_normal_method(k)
//   }
//
// Generated, with P the prefix and F the field type (all also in C++, as static members of the
// including class template, common/compat.glsl):
//   bool  P_trace(o, u, s_lo, s_hi, MarchSettings m, F q, out s_hit, out steps)    sphere tracing, or fixed steps
//   bool  P_fixed_march(o, u, s_lo, s_hi, MarchSettings m, F q, out s_hit, out steps)
//   pr_real  P_refine(o, u, a, b, side, after_long_step, MarchSettings m, F q, inout steps)
//   pr_real3 P_central_normal(p, h, F q), P_tetrahedral_normal(p, h, F q)             unit gradients
//   pr_real3 P_normal(uint method, p, h, F q)     march_normal_tetrahedral (2) or central (anything else)
//   uint  P_normal_evaluations(uint method)    4 or 6
// Why: GLSL has no function parameters; generating the marcher per distance function is how the
// function becomes one, and the field struct carries what used to sit in module-scope variables
// (a fractal's iteration count, a shape's kind), so each call is pure and the C++ mirror of a
// file can run on every core.
#ifndef PROCEDURAY_MARCHER
#error "marching/marcher.glsl: define PROCEDURAY_MARCHER (the prefix), PROCEDURAY_MARCHER_FIELD (the distance's second parameter's type) and PROCEDURAY_MARCHER_DISTANCE (pr_real f(pr_real3 p, FIELD q)) before including it"
#endif

#include "sphere_trace.glsl"

#define PROCEDURAY_MARCHER_FN(suffix) PROCEDURAY_CAT(PROCEDURAY_MARCHER, suffix)

/// The crossing lies in (a, b]: a on the start's side (side * distance > 0), b not. Narrows
/// it per m.hit_rule and returns the start-side end. `after_long_step`: b was reached by a
/// step longer than a probe, so the crossing is most likely just behind b (an exact bound lands
/// on the surface; an estimate overshoots a little): one probe a threshold back saves
/// bisecting the whole step.
PROCEDURAY_INLINE pr_real PROCEDURAY_MARCHER_FN(_refine)(pr_real3 o, pr_real3 u, pr_real a, pr_real b, pr_real side, bool after_long_step,
                                                     MarchSettings m, PROCEDURAY_MARCHER_FIELD q,
                                                     PROCEDURAY_INOUT(uint) steps) {
  if (m.hit_rule == march_hit_unrefined) return a;
  pr_real back = b - march_epsilon(m, b);
  if (after_long_step && back - a > march_epsilon(m, a) && steps < m.max_steps) {
    pr_real db = side * PROCEDURAY_MARCHER_DISTANCE(o + back * u, q);
    steps += 1u;
    if (db <= PR(0.0)) b = back;
    else a = back;
  }
  while (steps < m.max_steps && b - a > march_refine_fraction * march_epsilon(m, a)) {
    pr_real mid = PR(0.5) * (a + b);
    if (!(mid > a && mid < b)) break;  // the bracket is down to adjacent floats
    pr_real dm = side * PROCEDURAY_MARCHER_DISTANCE(o + mid * u, q);
    steps += 1u;
    if (dm <= PR(0.0)) b = mid;
    else a = mid;
  }
  return a;
}

/// Fixed steps (m.fixed_steps of them, equal, across [s_lo, s_hi]) and the crossing refined:
/// the D3D12 sample's volumetric march, for any bound. It never trusts the distance's size, so
/// it suits functions that are not bounds at all; it steps over any part thinner than a step.
/// The start rule is sphere_trace's (inside an SDF: the exit; on or inside an estimate that is
/// 0 there: a miss). `steps` counts evaluations and never exceeds m.max_steps.
PROCEDURAY_INLINE bool PROCEDURAY_MARCHER_FN(_fixed_march)(pr_real3 o, pr_real3 u, pr_real s_lo, pr_real s_hi, MarchSettings m,
                                                          PROCEDURAY_MARCHER_FIELD q, PROCEDURAY_OUT(pr_real) s_hit,
                                                          PROCEDURAY_OUT(uint) steps) {
  s_hit = s_lo;
  steps = 0u;
  if (!(s_hi >= s_lo) || m.max_steps == 0u) return false;
  pr_real d0 = PROCEDURAY_MARCHER_DISTANCE(o + s_lo * u, q);
  steps = 1u;
  if (d0 == PR(0.0) || !(d0 == d0)) return false;  // on the surface, or NaN
  pr_real side = d0 > PR(0.0) ? PR(1.0) : -PR(1.0);
  uint n = max(m.fixed_steps, 1u);
  pr_real ds = (s_hi - s_lo) / pr_real(n);
  pr_real a = s_lo;
  for (uint i = 1u; i <= n && steps < m.max_steps; ++i) {
    pr_real b = i == n ? s_hi : s_lo + pr_real(i) * ds;
    pr_real d = side * PROCEDURAY_MARCHER_DISTANCE(o + b * u, q);
    steps += 1u;
    if (d <= PR(0.0)) {
      s_hit = PROCEDURAY_MARCHER_FN(_refine)(o, u, a, b, side, false, m, q, steps);
      return true;
    }
    a = b;
  }
  return false;
}

/// Marches o + s u for s in [s_lo, s_hi]; true with the last point on the start's side before
/// the first sign change found: outside, or inside for a march that starts in an SDF and
/// reports the exit (see the header). `steps` counts distance evaluations, on a hit and on a
/// miss, probes and bisection included, and never exceeds m.max_steps.
PROCEDURAY_INLINE bool PROCEDURAY_MARCHER_FN(_trace)(pr_real3 o, pr_real3 u, pr_real s_lo, pr_real s_hi, MarchSettings m,
                                                    PROCEDURAY_MARCHER_FIELD q, PROCEDURAY_OUT(pr_real) s_hit,
                                                    PROCEDURAY_OUT(uint) steps) {
  if (m.fixed_steps > 0u) return PROCEDURAY_MARCHER_FN(_fixed_march)(o, u, s_lo, s_hi, m, q, s_hit, steps);
  // w: the relaxation in force; 1 from the first failed overlap test on (Keinert et al. keep
  // it there: where spheres stopped overlapping the ray is near a surface or grazing one).
  pr_real w = clamp(m.over_relaxation, PR(1.0), PR(1.99));
  pr_real k = m.step_scale > PR(0.0) ? m.step_scale : PR(1.0);
  pr_real probe = m.probe > PR(0.0) ? min(max(m.probe, PR(1.0)), PR(8.0)) : march_probe_scale;
  pr_real s = s_lo;
  pr_real previous_radius = PR(0.0);  // scaled distance at the previous point: no surface within it
  pr_real step = PR(0.0);             // the step that led to s
  bool relaxed = false;           // that step was w * previous_radius, w > 1 (a probe is not)
  pr_real outside = s_lo;            // the last point evaluated on the start's side (side * distance > 0)
  pr_real side = PR(1.0);             // -1 when the march starts inside and looks for the exit
  s_hit = s_lo;
  steps = 0u;
  while (steps < m.max_steps) {
    if (s > s_hi) {
      // A relaxed step may have jumped past a surface just before s_hi (a thin part near the
      // AABB's exit): retry from the plain step's end before calling it a miss.
      if (relaxed) {
        s -= step - previous_radius;
        step = previous_radius;
        relaxed = false;
        w = PR(1.0);
        continue;
      }
      return false;
    }
    pr_real d = PROCEDURAY_MARCHER_DISTANCE(o + s * u, q);
    steps += 1u;
    if (steps == 1u && d <= PR(0.0)) {
      // Starts inside: look for the exit on the negated bound, if it has one (see the header).
      if (!(d < PR(0.0))) return false;
      side = -PR(1.0);
      w = PR(1.0);  // relaxation is for the approach from outside; the exit marches plainly
    }
    d = side * d;
    pr_real r = k * d;
    // The unbounding spheres of the previous point (radius previous_radius) and this one (|r|)
    // leave no gap on the ray only if they overlap; after a relaxed step that does not hold, or
    // d <= 0 (inside), a surface may lie in the gap: go back to the plain step's end, w = 1.
    if (relaxed && (d <= PR(0.0) || abs(r) + previous_radius < step)) {
      s -= step - previous_radius;
      step = previous_radius;
      relaxed = false;
      w = PR(1.0);
      continue;
    }
    if (d <= PR(0.0)) {
      // Crossed: the surface lies in (outside, s] (the first point is never here: see above).
      s_hit = PROCEDURAY_MARCHER_FN(_refine)(o, u, outside, s, side, true, m, q, steps);
      return true;
    }
    outside = s;
    previous_radius = r;
    pr_real threshold = march_epsilon(m, s);
    if (d < threshold && m.hit_rule == march_hit_classic && side > PR(0.0)) {
      s_hit = s;  // the classic rule: below the threshold is a hit, crossing or not
      return true;
    }
    if (d < threshold) {
      // Near a surface or grazing one: probe on for an inside point instead of stopping here
      // (see the header); a probe past s_hi stops there once.
      step = max(r, clamp(probe * d, march_probe_min * threshold, threshold));
      relaxed = false;
      pr_real next = s + step;
      if (!(next > s)) next = s + threshold;  // below the float spacing at s: a whole threshold
      s = s < s_hi && next > s_hi ? s_hi : next;
    } else {
      step = w * r;
      relaxed = w > PR(1.0);
      s += step;
    }
  }
  return false;  // out of steps: a miss by definition
}

/// Unit gradient of the distance at p from four samples at the tetrahedron's vertices
/// (Quilez); h is the sample offset, tied by the caller to the hit threshold at p.
PROCEDURAY_INLINE pr_real3 PROCEDURAY_MARCHER_FN(_tetrahedral_normal)(pr_real3 p, pr_real h, PROCEDURAY_MARCHER_FIELD q) {
  pr_real3 a = pr_real3(PR(1.0), -PR(1.0), -PR(1.0));
  pr_real3 b = pr_real3(-PR(1.0), -PR(1.0), PR(1.0));
  pr_real3 c = pr_real3(-PR(1.0), PR(1.0), -PR(1.0));
  pr_real3 e = pr_real3(PR(1.0), PR(1.0), PR(1.0));
  pr_real3 g = a * PROCEDURAY_MARCHER_DISTANCE(p + h * a, q) + b * PROCEDURAY_MARCHER_DISTANCE(p + h * b, q) + c * PROCEDURAY_MARCHER_DISTANCE(p + h * c, q) +
           e * PROCEDURAY_MARCHER_DISTANCE(p + h * e, q);
  pr_real len2 = dot(g, g);
  return len2 > PR(1.0e-30) ? g * inversesqrt(len2) : pr_real3(PR(0.0), PR(1.0), PR(0.0));
}

/// Central differences: 6 evaluations to tetrahedral's 4, error ~0.14 (h/r)^2 not ~0.5 h/r; prefer it at large h.
PROCEDURAY_INLINE pr_real3 PROCEDURAY_MARCHER_FN(_central_normal)(pr_real3 p, pr_real h, PROCEDURAY_MARCHER_FIELD q) {
  pr_real3 x = pr_real3(h, PR(0.0), PR(0.0));
  pr_real3 y = pr_real3(PR(0.0), h, PR(0.0));
  pr_real3 z = pr_real3(PR(0.0), PR(0.0), h);
  pr_real3 g = pr_real3(PROCEDURAY_MARCHER_DISTANCE(p + x, q) - PROCEDURAY_MARCHER_DISTANCE(p - x, q), PROCEDURAY_MARCHER_DISTANCE(p + y, q) - PROCEDURAY_MARCHER_DISTANCE(p - y, q),
                  PROCEDURAY_MARCHER_DISTANCE(p + z, q) - PROCEDURAY_MARCHER_DISTANCE(p - z, q));
  pr_real len2 = dot(g, g);
  return len2 > PR(1.0e-30) ? g * inversesqrt(len2) : pr_real3(PR(0.0), PR(1.0), PR(0.0));
}

PROCEDURAY_INLINE pr_real3 PROCEDURAY_MARCHER_FN(_normal)(uint method, pr_real3 p, pr_real h, PROCEDURAY_MARCHER_FIELD q) {
  return method == march_normal_tetrahedral ? PROCEDURAY_MARCHER_FN(_tetrahedral_normal)(p, h, q)
                                            : PROCEDURAY_MARCHER_FN(_central_normal)(p, h, q);
}

PROCEDURAY_INLINE uint PROCEDURAY_MARCHER_FN(_normal_evaluations)(uint method) {
  return method == march_normal_tetrahedral ? 4u : 6u;
}

#undef PROCEDURAY_MARCHER_FN
#undef PROCEDURAY_MARCHER
#undef PROCEDURAY_MARCHER_FIELD
#undef PROCEDURAY_MARCHER_DISTANCE
