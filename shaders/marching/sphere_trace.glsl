// Sphere tracing (Hart 1996) with run-time knobs, optional over-relaxation (Keinert et al.
// 2014), or fixed steps; hits confirmed by a sign change and refined by bisection (or not), and
// normals by central or tetrahedral differences: the settings and the rule. The marching code
// itself is generated per distance function by marching/marcher.glsl (P_trace, P_normal, ...);
// marching/knobs.glsl builds the settings from a geometry's MarchKnobs (proceduray/march/knobs.hpp).
//
//   MarchSettings m = MarchSettings(max_steps, epsilon, footprint, step_scale, over_relaxation, 0u, march_hit_refined, 2.0);
//   float s; uint steps;
//   if (bulb_trace(o, u, s_lo, s_hi, m, field, s, steps)) {            // marcher.glsl, prefix bulb
//     vec3 p = o + s * u;
//     vec3 n = bulb_central_normal(p, normal_offset(march_epsilon(m, s), p), field);   // tetrahedral: 4 evaluations
//   }
//
// The distance (marcher.glsl's PROCEDURAY_MARCHER_DISTANCE) is a signed distance bound, positive
// outside, <= 0 inside (the SDFs go negative, the fractal estimates return 0). `u` must be unit
// length, so s is a distance in the same units as the distance.
//
// The hit rule. The classic rule (stop at the first point whose distance is below the
// threshold) stops in front of the surface by up to threshold / cos(incidence), more where
// the estimate underestimates (the Mandelbulb's: a median 1.5 pixel footprints at a threshold
// of half a footprint), and takes a ray that passes within the threshold without entering for
// a hit (fat silhouettes: ~40 % of the fractals' 1-pixel silhouette band were such false
// hits). Here the threshold only says where to look; a hit is a sign change:
//   - below the threshold t the march probes on instead of stopping: steps of
//     m.probe (march_probe_scale, 2, by default) distances, clamped to [march_probe_min (1/64), 1] t and never
//     shorter than the bound's own step, until a point is inside (distance <= 0). Probes are
//     finer where the distance is far below t, i.e. near the surface or a part thinner than t
//     (fractal filaments), which probes a whole t apart would step over; past the bound's
//     step d, a probe of 2 d can step over only a part thinner than d (4 d cost an exact SDF
//     thin parts, 1 d the fractals 30 % more evaluations; an estimate that underestimates
//     several-fold near its surface, as the Mandelbulb's does, creeps at 2 d: m.probe 4 takes
//     15 % fewer evaluations there, and steps over more thin parts, see docs/accuracy.md). The floor bounds what a probe
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
//   probe           probe length below the threshold in distances, clamped to [1, 8]; 0 (a
//                   settings struct left zero) is march_probe_scale.
//   hit_rule        march_hit_refined: bisect as above; march_hit_unrefined: report the last
//                   outside point as it is (up to one probe, <= the threshold, or one fixed
//                   step short), saving the ~5 bisections; march_hit_classic: the classic
//                   rule, kept as a method so the charts show what it costs: the first point
//                   of an outside approach whose distance is below the threshold is the hit,
//                   no sign change needed (rays passing within the threshold are hits:
//                   silhouettes grow by the threshold, and estimates stop short).
#ifndef PROCEDURAY_MARCHING_SPHERE_TRACE_GLSL
#define PROCEDURAY_MARCHING_SPHERE_TRACE_GLSL

#include "../common/compat.glsl"

/// Run-time knobs of one march (see the header).
struct MarchSettings {
  uint max_steps;
  pr_real epsilon;
  pr_real footprint;
  pr_real step_scale;
  pr_real over_relaxation;
  uint fixed_steps;  // 0: sphere tracing; n > 0: n equal steps across [s_lo, s_hi], then the crossing's refinement
  uint hit_rule;     // march_hit_refined (0), march_hit_unrefined (1) or march_hit_classic (2)
  pr_real probe;     // probes below the threshold, in distances; 0: march_probe_scale (2)
};

/// MarchSettings::hit_rule: bisect the crossing to march_refine_fraction of the threshold, or
/// report the last outside point before the first inside one as it is (cheaper, up to one
/// probe or fixed step short of the surface).
PROCEDURAY_CONST uint march_hit_refined = 0u;
PROCEDURAY_CONST uint march_hit_unrefined = 1u;
PROCEDURAY_CONST uint march_hit_classic = 2u;

/// How a normal is taken by differences (a marcher's P_normal; MarchNormal's values).
PROCEDURAY_CONST uint march_normal_analytic = 0u;
PROCEDURAY_CONST uint march_normal_central = 1u;
PROCEDURAY_CONST uint march_normal_tetrahedral = 2u;

/// The hit threshold at distance s along the ray.
PROCEDURAY_INLINE pr_real march_epsilon(MarchSettings m, pr_real s) { return max(m.epsilon, m.footprint * s); }

/// Refinement of a confirmed hit: bisection stops once [outside, inside] is at most this
/// fraction of the threshold long (so the reported point is within it of the crossing).
PROCEDURAY_CONST pr_real march_refine_fraction = PR(0.03125);

/// Probe length below the threshold: march_probe_scale times the distance, clamped to
/// [march_probe_min, 1] thresholds (see the header).
PROCEDURAY_CONST pr_real march_probe_scale = PR(2.0);
PROCEDURAY_CONST pr_real march_probe_min = PR(0.015625);

/// Float spacings (2^-23 of the largest |component| of p) that normal_offset keeps h above.
PROCEDURAY_CONST pr_real normal_offset_spacings = PR(64.0);

/// The sample offset for central_normal / tetrahedral_normal at p: h, raised to normal_offset_spacings float
/// spacings at p. At c spacings p + h rounds by up to 1/(2c) of h, differently per axis, and tilts the normal
/// (tests/shaders/normals_test.cpp: 0.9 degree at c = 16, 0.3 at 64 out to |p| = 1e4; h under half a spacing
/// leaves p unchanged: the fallback normal). Larger c blurs curved parts. A double build keeps the float rule.
PROCEDURAY_INLINE pr_real normal_offset(pr_real h, pr_real3 p) {
  pr_real m = max(abs(p.x), max(abs(p.y), abs(p.z)));
  return max(h, normal_offset_spacings * PR(1.1920928955078125e-7) * m);
}

#endif
