// Ground truth for ray/primitive hits, in double, by searches that share nothing with the
// methods under test (sphere tracing, fixed steps, interval CSG): what a shader's hit is
// compared against.
//
//   using namespace proceduray::accuracy;
//   auto sphere = [](glm::dvec3 p) { return glm::length(p) - 1.0; };  // a distance bound, L = 1
//   const glm::dvec3 o(0.0, 0.0, -5.0), d(0.0, 0.0, 1.0);
//   Result a = lipschitz_search(sphere, 1.0, o, d, 0.0, 10.0, {.min_step = 1e-9});
//   auto ball = [](glm::dvec3 p) { return glm::dot(p, p) <= 1.0; };  // membership only
//   Result b = predicate_search(ball, o, d, 0.0, 10.0, 1e-3);
//   glm::dvec3 n = gradient_normal(sphere, o + a.t * d, 1e-6);  // at a hit: a.outcome == Outcome::hit
//
// Both searches look for the first boundary crossing in [t_lo, t_hi]: from outside the first
// entry, from inside (Result::starts_inside) the first exit, as the closed forms
// (closed_form.hpp) report it; callers that want entries only treat starts_inside apart.
//   lipschitz_search   f(p) <= 0 inside, |f(p) - f(q)| <= L |p - q|. Steps of |f| / (L |dir|)
//                      cannot cross the surface (f cannot change sign within them), so the only
//                      way to miss a feature is the floor min_step: where |f| / L < min_step the
//                      step is min_step, and an inside (or outside) run along the ray shorter
//                      than min_step may be stepped over. Pick min_step far below what is
//                      measured, e.g. 1e-6 of a pixel footprint. Grazing rays pay for this in
//                      evaluations (~1e5 at an impact parameter within 1e-9 of the radius).
//   predicate_search   only a membership test (fractal orbit bounded, CSG membership, metaball
//                      field >= threshold): samples every `spacing` and bisects the first change;
//                      runs shorter than `spacing` may be missed, so it guarantees nothing below
//                      the spacing and is the reference only where no bound L is known.
// A thresholded field (metaballs) gets no third searcher: predicate_search on field >= threshold
// samples it, and lipschitz_search on threshold - field with L = the sum of the balls' slope
// bounds (quintic falloff: 1.875 / radius each) is the one that misses no neck. Bisecting the
// field's value instead of its sign (regula falsi) would only save evaluations, not move the root.
//
// Outcomes: hit (t within the tolerance, `bracket` the final width of the bisection), miss (the
// whole range sampled, no crossing), undetermined (the evaluation budget ran out first: never a
// guess; `t` is only where the search stopped). Refinement is bisection on the sign alone, so a
// hit's t is at most bracket / 2 from the crossing for any function, smooth or not.
//
// Rays: `dir` need not be unit length; t, min_step, spacing and tolerances are in units of the
// ray parameter (lengths when |dir| = 1). Bad input (non-finite or zero vectors, t_lo > t_hi, a
// range beyond +-1e300, non-positive L, spacing, min_step or budget, a NaN distance) throws
// UsageError naming the call, the value and the fix.
//
// Normals: prefer a closed form where one exists (closed_form.hpp gives them). gradient_normal
// takes central differences of f in double; its error is ~(h / curvature radius)^2 plus ~1e-16
// |p| / h (rounding of f near p), so h ~ 1e-5 of the curvature radius is best on smooth surfaces
// (seen: 1e-11 on a unit sphere, 3e-3 at h = 0.3 and at h = 1e-14). A fractal's normal depends on
// the scale looked at: difference at the scale the image resolves (a fraction of the pixel
// footprint at the hit; the shader's own differences use its hit threshold) and say which. A set
// known only by membership has no gradient: difference a distance estimate or field instead.
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>

#include <glm/glm.hpp>

#include "proceduray/accuracy/outcome.hpp"
#include "proceduray/error.hpp"

namespace proceduray::accuracy {

/// One ray's answer; the searchers and the closed forms return the same type.
struct Result {
  Outcome outcome = Outcome::miss;
  double t = 0.0;                  ///< the hit (hit); where the search stopped (undetermined); 0 (miss)
  glm::dvec3 normal{0.0};          ///< outward unit normal: closed forms only; searchers leave 0
  std::uint64_t evaluations = 0;   ///< function evaluations (closed forms: 1)
  double bracket = 0.0;            ///< width of the final bisection bracket (closed forms: 0)
  bool starts_inside = false;      ///< the point at t_lo is inside: t is where the ray leaves
};

/// Knobs of a search; defaults suit unit-sized objects seen at ~1e-3 pixel footprints.
struct SearchOptions {
  double min_step = 1.0e-9;            ///< lipschitz_search: smallest step (features below it may be missed)
  double tolerance = 0.0;              ///< bisection stops at this absolute bracket width...
  double relative_tolerance = 1.0e-13; ///< ...or at this width relative to |t| (or at one ulp)
  std::uint64_t budget = std::uint64_t{1} << 22;  ///< evaluations at most; beyond: undetermined
};

namespace detail {

/// The shortest text that reads back as v: 0.1, not 0.10000000000000001.
inline std::string show(double v) {
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, v).ptr);
}
inline std::string show(glm::dvec3 v) { return "(" + show(v.x) + ", " + show(v.y) + ", " + show(v.z) + ")"; }

[[noreturn]] inline void refuse(std::string_view call, const std::string& what, const std::string& fix) {
  throw UsageError(std::string(call) + ": " + what + "; " + fix);
}

inline bool finite(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

/// Origin, direction and range of a ray: what every call checks first.
inline void check_ray(std::string_view call, glm::dvec3 origin, glm::dvec3 dir, double t_lo, double t_hi) {
  if (!finite(origin)) refuse(call, "origin " + show(origin) + " is not finite", "pass a finite ray origin");
  if (!finite(dir)) refuse(call, "direction " + show(dir) + " is not finite", "pass a finite ray direction");
  // The squared length must be a normal double: the searches divide by |dir|, the sphere by dir.dir.
  const double a = glm::dot(dir, dir);
  if (!(a >= std::numeric_limits<double>::min()) || !std::isfinite(a)) {
    refuse(call, "direction " + show(dir) + (a == 0.0 ? " has zero length" : " cannot be squared in double"),
           "pass a non-zero direction of moderate length (normalise it)");
  }
  constexpr double far = 1.0e300;  // keeps t_hi - t_lo and 2 max|t| finite
  if (!(std::abs(t_lo) <= far) || !(std::abs(t_hi) <= far)) {
    refuse(call, "t range [" + show(t_lo) + ", " + show(t_hi) + "] is not finite (or beyond +-1e300)",
           "pass finite ends, e.g. the far side of the object's bounds");
  }
  if (t_lo > t_hi) refuse(call, "t_lo = " + show(t_lo) + " > t_hi = " + show(t_hi), "pass t_lo <= t_hi");
}

inline void check_positive(std::string_view call, std::string_view name, double value, std::string_view fix) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    refuse(call, std::string(name) + " = " + show(value) + " is not a positive finite number", std::string(fix));
  }
}

inline void check_options(std::string_view call, const SearchOptions& o, bool uses_min_step) {
  if (uses_min_step) {
    check_positive(call, "options.min_step", o.min_step,
                   "state the thinnest feature to find, e.g. 1e-6 of a pixel footprint");
  }
  if (!(o.tolerance >= 0.0) || !(o.relative_tolerance >= 0.0) || !std::isfinite(o.tolerance) ||
      !std::isfinite(o.relative_tolerance)) {
    refuse(call, "options.tolerance = " + show(o.tolerance) + ", options.relative_tolerance = " +
                     show(o.relative_tolerance) + " (must be finite and >= 0)",
           "pass 0 to bisect down to one ulp");
  }
  if (o.budget == 0) refuse(call, "options.budget = 0 evaluations", "allow at least one evaluation (default 2^22)");
}

/// Bisects [a, b] where crossed(a) is false and crossed(b) true; crossed counts its evaluations
/// into r, whose budget bounds the loop.
template <class Crossed>
Result bisect(Crossed&& crossed, double a, double b, const SearchOptions& o, Result& r) {
  for (;;) {
    const double width = b - a;
    const double mid = a + 0.5 * width;
    const double goal = std::max(o.tolerance, o.relative_tolerance * std::max(std::abs(a), std::abs(b)));
    r.t = mid;
    r.bracket = width;
    // mid == a or b: a and b are neighbouring doubles, the best double can say.
    if (width <= goal || mid <= a || mid >= b) {
      r.outcome = Outcome::hit;
      return r;
    }
    if (r.evaluations >= o.budget) {
      r.outcome = Outcome::undetermined;
      return r;
    }
    if (crossed(mid)) {
      b = mid;
    } else {
      a = mid;
    }
  }
}

/// The next sample after t: at least one ulp further (a step below t's spacing would stall), at most t_hi.
inline double advance(double t, double step, double t_hi) {
  return std::min(std::max(t + step, std::nextafter(t, t_hi)), t_hi);
}

}  // namespace detail

/// First boundary crossing of {f <= 0} along origin + t dir, t in [t_lo, t_hi], for f with
/// Lipschitz bound L (1 for an exact distance; the largest scale factor for a scaled one).
template <class Distance>
  requires std::is_invocable_r_v<double, Distance&, glm::dvec3>
Result lipschitz_search(Distance&& distance, double L, glm::dvec3 origin, glm::dvec3 dir, double t_lo, double t_hi,
                        const SearchOptions& options = {}) {
  constexpr std::string_view call = "lipschitz_search";
  detail::check_ray(call, origin, dir, t_lo, t_hi);
  detail::check_positive(call, "the Lipschitz bound L", L, "pass the function's Lipschitz bound (1 for an exact distance)");
  detail::check_options(call, options, true);
  Result r;
  auto at = [&](double t) {
    ++r.evaluations;
    const glm::dvec3 p = origin + t * dir;
    const double d = static_cast<double>(distance(p));
    if (std::isnan(d)) {
      detail::refuse(call, "the distance function returned NaN at t = " + detail::show(t) + ", p = " + detail::show(p),
                     "guard its NaN sources (acos, log, pow, normalize of 0)");
    }
    return d;
  };
  const double per_t = L * glm::length(dir);  // |f| changes by at most this per unit of t
  if (!(per_t >= std::numeric_limits<double>::min()) || !std::isfinite(per_t)) {  // else steps of inf or 0
    detail::refuse(call, "L * |dir| = " + detail::show(L) + " * " + detail::show(glm::length(dir)) + " is out of range",
                   "scale the direction to unit length and L to match");
  }
  double t = t_lo;
  double d = at(t);
  if (d == 0.0) {  // on the surface: the first boundary point in range, as the closed forms say
    r.outcome = Outcome::hit;
    r.t = t;
    return r;
  }
  r.starts_inside = d < 0.0;
  auto crossed = [&](double value) { return r.starts_inside ? value >= 0.0 : value <= 0.0; };
  for (;;) {
    if (t >= t_hi) return r;  // miss: sampled up to t_hi without a crossing
    if (r.evaluations >= options.budget) {
      r.outcome = Outcome::undetermined;
      r.t = t;
      return r;
    }
    const double previous = t;
    t = detail::advance(t, std::max(std::abs(d) / per_t, options.min_step), t_hi);
    d = at(t);
    if (crossed(d)) return detail::bisect([&](double s) { return crossed(at(s)); }, previous, t, options, r);
  }
}

/// First change of `inside` along origin + t dir, t in [t_lo, t_hi], sampled every `spacing`
/// (in t) and bisected; starts_inside says whether the point at t_lo is inside.
template <class Inside>
  requires std::is_invocable_r_v<bool, Inside&, glm::dvec3>
Result predicate_search(Inside&& inside, glm::dvec3 origin, glm::dvec3 dir, double t_lo, double t_hi, double spacing,
                        const SearchOptions& options = {}) {
  constexpr std::string_view call = "predicate_search";
  detail::check_ray(call, origin, dir, t_lo, t_hi);
  detail::check_positive(call, "spacing", spacing, "pass the sample spacing in t (below the thinnest feature to find)");
  detail::check_options(call, options, false);
  Result r;
  auto at = [&](double t) {
    ++r.evaluations;
    return static_cast<bool>(inside(origin + t * dir));
  };
  r.starts_inside = at(t_lo);
  auto crossed = [&](double s) { return at(s) != r.starts_inside; };
  double t = t_lo;
  for (std::uint64_t k = 1;; ++k) {
    if (t >= t_hi) return r;  // miss
    if (r.evaluations >= options.budget) {
      r.outcome = Outcome::undetermined;
      r.t = t;
      return r;
    }
    const double previous = t;
    // From t_lo by k spacings, not by repeated addition: no drift over millions of samples.
    t = detail::advance(previous, t_lo + static_cast<double>(k) * spacing - previous, t_hi);
    if (crossed(t)) return detail::bisect(crossed, previous, t, options, r);
  }
}

/// Unit gradient of f at p by central differences of step h (6 evaluations); for a distance
/// (positive outside) the outward normal, for a field with inside = f >= threshold its negation.
/// (0, 0, 0) where the differences cancel (flat at this h: take a larger h).
template <class Field>
  requires std::is_invocable_r_v<double, Field&, glm::dvec3>
glm::dvec3 gradient_normal(Field&& f, glm::dvec3 p, double h) {
  constexpr std::string_view call = "gradient_normal";
  if (!detail::finite(p)) detail::refuse(call, "point " + detail::show(p) + " is not finite", "pass a finite point");
  detail::check_positive(call, "h", h, "pass a difference step (see the header: ~1e-2 of the pixel footprint)");
  glm::dvec3 g(0.0);
  for (int axis = 0; axis < 3; ++axis) {
    glm::dvec3 e(0.0);
    e[axis] = h;
    g[axis] = (static_cast<double>(f(p + e)) - static_cast<double>(f(p - e))) / (2.0 * h);
  }
  if (!detail::finite(g)) {
    detail::refuse(call, "the differences at p = " + detail::show(p) + " are not finite: " + detail::show(g),
                   "guard the function's NaN sources, or take h within its domain");
  }
  const double length = glm::length(g);
  return length > 0.0 ? g / length : glm::dvec3(0.0);
}

}  // namespace proceduray::accuracy
