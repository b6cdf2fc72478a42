// Sphere tracing (Hart 1996) with run-time knobs, optional over-relaxation (Keinert et al.
// 2014), or fixed steps; hits confirmed by a sign change and refined by bisection (or not), and
// normals by central or tetrahedral differences. marching/knobs.glsl builds the settings from a
// geometry's MarchKnobs (proceduray/march/knobs.hpp).
//
//   float march_distance(vec3 p) { return mandelbulb_distance(p, iterations); }  // define first
//   #include "marching/sphere_trace.glsl"
//   MarchSettings m = MarchSettings(max_steps, epsilon, footprint, step_scale, over_relaxation, 0u, march_hit_refined);
//   float s; uint steps;
//   if (sphere_trace(o, u, s_lo, s_hi, m, s, steps)) {
//     vec3 p = o + s * u;
//     vec3 n = central_normal(p, normal_offset(march_epsilon(m, s), p));   // or tetrahedral_normal: 4 evaluations
//   }
//
// The includer defines `real march_distance(real3 p)` (float and vec3 in GLSL; see
// common/compat.glsl for C++): a signed distance bound, positive outside, <= 0 inside (the
// SDFs go negative, the fractal estimates return 0). `u` must be unit length, so s is a
// distance in the same units as march_distance.
//
// The hit rule. The classic rule (stop at the first point whose distance is below the
// threshold) stops in front of the surface by up to threshold / cos(incidence), more where
// the estimate underestimates (the Mandelbulb's: a median 1.5 pixel footprints at a threshold
// of half a footprint), and takes a ray that passes within the threshold without entering for
// a hit (fat silhouettes: ~40 % of the fractals' 1-pixel silhouette band were such false
// hits). Here the threshold only says where to look; a hit is a sign change:
//   - below the threshold t the march probes on instead of stopping: steps of
//     march_probe_scale (2) distances, clamped to [march_probe_min (1/64), 1] t and never
//     shorter than the bound's own step, until a point is inside (distance <= 0). Probes are
//     finer where the distance is far below t, i.e. near the surface or a part thinner than t
//     (fractal filaments), which probes a whole t apart would step over; past the bound's
//     step d, a probe of 2 d can step over only a part thinner than d (4 d cost an exact SDF
//     thin parts, 1 d the fractals 30 % more evaluations). The floor bounds what a probe
//     steps over where d is tiny, often near a part other than the one ahead (the Mandelbulb's
//     filaments at 320x240: depth error p99 2.5 footprints with a floor of t / 16, 1.4 with
//     t / 64, for 10 % more evaluations; the D3D12 SDFs' cost did not change). Its price: a
//     ray running within t / 128 of a surface creeps at t / 64 (grazing a flat face at under
//     1e-3 rad it may run out of steps: a miss, see tests/shaders/julia_cut_test.cpp);
//   - the last outside point and the inside one are bisected until the bracket is at most
//     march_refine_fraction (1/32) t long, and the OUTSIDE end is reported: never a point
//     inside, so normals are taken outside the surface. When a long step (not a probe) landed
//     inside, one probe t back comes first: an exact bound lands right on the surface, and
//     the step need not be bisected whole;
//   - a ray whose distance rises above t again without an inside point grazed the surface
//     and marches on: a miss, unless something farther on is hit.
// So hits lie within t / 32 of a crossing, and silhouettes are not fattened. The price: more
// evaluations per hit (probes, ~5 bisections), grazing rays march past the surface instead of
// stopping at it, and a part thinner than the probes along the ray (under t) may be stepped
// over (then the ray hits what lies behind, or misses).
//
// A march whose first point is inside (a ray from inside the object, e.g. a camera in it)
// reports where the ray LEAVES, as the closed forms do (box, sphere, Pac-man), so hit shaders
// and cull flags treat every primitive alike: the exit's normal faces away from the ray (back
// facing). It marches the negated bound, which an SDF provides (distance < 0 inside, as far
// from the surface as outside); the same probe and bisection rule then brackets the exit, and
// the reported point is the last one inside. An estimate that is 0 inside (the fractals) gives
// no way out: that march is a MISS (no exit is claimed, and no hit at the ray's start, which
// would be a wrong surface with an arbitrary normal). A first point exactly on the surface
// (distance 0) is the same miss: a secondary ray started on its surface does not hit it there.
//
// Knobs (MarchSettings, all run-time values):
//   max_steps       distance evaluations at most, probes and bisection included; when they
//                   run out before a sign change the march reports a MISS, never its last
//                   point, so a silhouette ray that cannot converge leaves a hole rather than
//                   a wrong surface (a bisection cut short reports its outside end).
//   epsilon         absolute threshold (floor); keep it above the float spacing at |p|.
//   footprint       threshold growth per unit distance: k * pixel_angle; the threshold is
//                   max(epsilon, footprint * s). It is compared with the UNSCALED distance
//                   and sets where probing starts, the probes' length and the refinement.
//   step_scale      steps are step_scale * distance: 1 / Lipschitz bound, or a fudge < 1 for
//                   estimates (fractals) that may overshoot. It scales steps only, not the
//                   threshold (the classic rule tested step_scale * distance, so a fudge
//                   shrank the threshold too and coupled two unrelated knobs).
//   over_relaxation w in [1, 2) (clamped to [1, 1.99]); 1 is plain sphere tracing. Keinert et
//                   al. 2014: steps of w * distance; when the unbounding spheres of two
//                   successive points stop overlapping (|d_prev| + |d| < step, or d <= 0) the
//                   surface may have been skipped, so the march goes back to the plain step's
//                   end and continues with w = 1; likewise when a relaxed step leaves [s_lo, s_hi].
//                   Probes are never relaxed.
//   fixed_steps     0 for sphere tracing; n > 0 marches n equal steps instead (fixed_march),
//                   whatever the distance says, and refines the first crossing.
//   hit_rule        march_hit_refined: bisect as above; march_hit_unrefined: report the last
//                   outside point as it is (up to one probe, <= the threshold, or one fixed
//                   step short), saving the ~5 bisections.
#ifndef PROCEDURAY_MARCHING_SPHERE_TRACE_GLSL
#define PROCEDURAY_MARCHING_SPHERE_TRACE_GLSL

#include "../common/compat.glsl"

#ifndef __cplusplus
/// The distance bound to march; defined by the includer (before or after this file). No
/// prototype in C++: a class-scope inclusion may not declare a member twice, and there the
/// definition may follow; a namespace-scope includer defines it before including this file.
real march_distance(real3 p);
#endif

/// Run-time knobs of one march (see the header).
struct MarchSettings {
  uint max_steps;
  real epsilon;
  real footprint;
  real step_scale;
  real over_relaxation;
  uint fixed_steps;  // 0: sphere tracing; n > 0: n equal steps across [s_lo, s_hi], then the crossing's refinement
  uint hit_rule;     // march_hit_refined (0) or march_hit_unrefined (1)
};

/// MarchSettings::hit_rule: bisect the crossing to march_refine_fraction of the threshold, or
/// report the last outside point before the first inside one as it is (cheaper, up to one
/// probe or fixed step short of the surface).
PROCEDURAY_CONST uint march_hit_refined = 0u;
PROCEDURAY_CONST uint march_hit_unrefined = 1u;

/// The hit threshold at distance s along the ray.
PROCEDURAY_INLINE real march_epsilon(MarchSettings m, real s) { return max(m.epsilon, m.footprint * s); }

/// Refinement of a confirmed hit: bisection stops once [outside, inside] is at most this
/// fraction of the threshold long (so the reported point is within it of the crossing).
PROCEDURAY_CONST real march_refine_fraction = R(0.03125);

/// Probe length below the threshold: march_probe_scale times the distance, clamped to
/// [march_probe_min, 1] thresholds (see the header).
PROCEDURAY_CONST real march_probe_scale = R(2.0);
PROCEDURAY_CONST real march_probe_min = R(0.015625);

/// The crossing lies in (a, b]: a on the start's side (side * distance > 0), b not. Narrows
/// it per m.hit_rule and returns the start-side end. `after_long_step`: b was reached by a
/// step longer than a probe, so the crossing is most likely just behind b (an exact bound lands
/// on the surface; an estimate overshoots a little): one probe a threshold back saves
/// bisecting the whole step.
PROCEDURAY_INLINE real march_refine(real3 o, real3 u, real a, real b, real side, bool after_long_step, MarchSettings m,
                                    PROCEDURAY_INOUT(uint) steps) {
  if (m.hit_rule == march_hit_unrefined) return a;
  real back = b - march_epsilon(m, b);
  if (after_long_step && back - a > march_epsilon(m, a) && steps < m.max_steps) {
    real db = side * march_distance(o + back * u);
    steps += 1u;
    if (db <= R(0.0)) b = back;
    else a = back;
  }
  while (steps < m.max_steps && b - a > march_refine_fraction * march_epsilon(m, a)) {
    real mid = R(0.5) * (a + b);
    if (!(mid > a && mid < b)) break;  // the bracket is down to adjacent floats
    real dm = side * march_distance(o + mid * u);
    steps += 1u;
    if (dm <= R(0.0)) b = mid;
    else a = mid;
  }
  return a;
}

/// Fixed steps (m.fixed_steps of them, equal, across [s_lo, s_hi]) and the crossing refined:
/// the D3D12 sample's volumetric march, for any bound. It never trusts the distance's size, so
/// it suits functions that are not bounds at all; it steps over any part thinner than a step.
/// The start rule is sphere_trace's (inside an SDF: the exit; on or inside an estimate that is
/// 0 there: a miss). `steps` counts evaluations and never exceeds m.max_steps.
PROCEDURAY_INLINE bool fixed_march(real3 o, real3 u, real s_lo, real s_hi, MarchSettings m,
                                   PROCEDURAY_OUT(real) s_hit, PROCEDURAY_OUT(uint) steps) {
  s_hit = s_lo;
  steps = 0u;
  if (!(s_hi >= s_lo) || m.max_steps == 0u) return false;
  real d0 = march_distance(o + s_lo * u);
  steps = 1u;
  if (d0 == R(0.0) || !(d0 == d0)) return false;  // on the surface, or NaN
  real side = d0 > R(0.0) ? R(1.0) : -R(1.0);
  uint n = max(m.fixed_steps, 1u);
  real ds = (s_hi - s_lo) / real(n);
  real a = s_lo;
  for (uint i = 1u; i <= n && steps < m.max_steps; ++i) {
    real b = i == n ? s_hi : s_lo + real(i) * ds;
    real d = side * march_distance(o + b * u);
    steps += 1u;
    if (d <= R(0.0)) {
      s_hit = march_refine(o, u, a, b, side, false, m, steps);
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
PROCEDURAY_INLINE bool sphere_trace(real3 o, real3 u, real s_lo, real s_hi, MarchSettings m,
                                    PROCEDURAY_OUT(real) s_hit, PROCEDURAY_OUT(uint) steps) {
  if (m.fixed_steps > 0u) return fixed_march(o, u, s_lo, s_hi, m, s_hit, steps);
  // w: the relaxation in force; 1 from the first failed overlap test on (Keinert et al. keep
  // it there: where spheres stopped overlapping the ray is near a surface or grazing one).
  real w = clamp(m.over_relaxation, R(1.0), R(1.99));
  real k = m.step_scale > R(0.0) ? m.step_scale : R(1.0);
  real s = s_lo;
  real previous_radius = R(0.0);  // scaled distance at the previous point: no surface within it
  real step = R(0.0);             // the step that led to s
  bool relaxed = false;           // that step was w * previous_radius, w > 1 (a probe is not)
  real outside = s_lo;            // the last point evaluated on the start's side (side * distance > 0)
  real side = R(1.0);             // -1 when the march starts inside and looks for the exit
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
        w = R(1.0);
        continue;
      }
      return false;
    }
    real d = march_distance(o + s * u);
    steps += 1u;
    if (steps == 1u && d <= R(0.0)) {
      // Starts inside: look for the exit on the negated bound, if it has one (see the header).
      if (!(d < R(0.0))) return false;
      side = -R(1.0);
      w = R(1.0);  // relaxation is for the approach from outside; the exit marches plainly
    }
    d = side * d;
    real r = k * d;
    // The unbounding spheres of the previous point (radius previous_radius) and this one (|r|)
    // leave no gap on the ray only if they overlap; after a relaxed step that does not hold, or
    // d <= 0 (inside), a surface may lie in the gap: go back to the plain step's end, w = 1.
    if (relaxed && (d <= R(0.0) || abs(r) + previous_radius < step)) {
      s -= step - previous_radius;
      step = previous_radius;
      relaxed = false;
      w = R(1.0);
      continue;
    }
    if (d <= R(0.0)) {
      // Crossed: the surface lies in (outside, s] (the first point is never here: see above).
      s_hit = march_refine(o, u, outside, s, side, true, m, steps);
      return true;
    }
    outside = s;
    previous_radius = r;
    real threshold = march_epsilon(m, s);
    if (d < threshold) {
      // Near a surface or grazing one: probe on for an inside point instead of stopping here
      // (see the header); a probe past s_hi stops there once.
      step = max(r, clamp(march_probe_scale * d, march_probe_min * threshold, threshold));
      relaxed = false;
      real next = s + step;
      if (!(next > s)) next = s + threshold;  // below the float spacing at s: a whole threshold
      s = s < s_hi && next > s_hi ? s_hi : next;
    } else {
      step = w * r;
      relaxed = w > R(1.0);
      s += step;
    }
  }
  return false;  // out of steps: a miss by definition
}

/// Unit gradient of march_distance at p from four samples at the tetrahedron's vertices
/// (Quilez); h is the sample offset, tied by the caller to the hit threshold at p.
PROCEDURAY_INLINE real3 tetrahedral_normal(real3 p, real h) {
  real3 a = real3(R(1.0), -R(1.0), -R(1.0));
  real3 b = real3(-R(1.0), -R(1.0), R(1.0));
  real3 c = real3(-R(1.0), R(1.0), -R(1.0));
  real3 e = real3(R(1.0), R(1.0), R(1.0));
  real3 g = a * march_distance(p + h * a) + b * march_distance(p + h * b) + c * march_distance(p + h * c) +
           e * march_distance(p + h * e);
  real len2 = dot(g, g);
  return len2 > R(1.0e-30) ? g * inversesqrt(len2) : real3(R(0.0), R(1.0), R(0.0));
}

/// Central differences: 6 evaluations to tetrahedral's 4, error ~0.14 (h/r)^2 not ~0.5 h/r; prefer it at large h.
PROCEDURAY_INLINE real3 central_normal(real3 p, real h) {
  real3 x = real3(h, R(0.0), R(0.0));
  real3 y = real3(R(0.0), h, R(0.0));
  real3 z = real3(R(0.0), R(0.0), h);
  real3 g = real3(march_distance(p + x) - march_distance(p - x), march_distance(p + y) - march_distance(p - y),
                  march_distance(p + z) - march_distance(p - z));
  real len2 = dot(g, g);
  return len2 > R(1.0e-30) ? g * inversesqrt(len2) : real3(R(0.0), R(1.0), R(0.0));
}

/// Float spacings (2^-23 of the largest |component| of p) that normal_offset keeps h above.
PROCEDURAY_CONST real normal_offset_spacings = R(64.0);

/// The sample offset for central_normal / tetrahedral_normal at p: h, raised to normal_offset_spacings float
/// spacings at p. At c spacings p + h rounds by up to 1/(2c) of h, differently per axis, and tilts the normal
/// (tests/shaders/normals_test.cpp: 0.9 degree at c = 16, 0.3 at 64 out to |p| = 1e4; h under half a spacing
/// leaves p unchanged: the fallback normal). Larger c blurs curved parts. A double build keeps the float rule.
PROCEDURAY_INLINE real normal_offset(real h, real3 p) {
  real m = max(abs(p.x), max(abs(p.y), abs(p.z)));
  return max(h, normal_offset_spacings * R(1.1920928955078125e-7) * m);
}

#endif
