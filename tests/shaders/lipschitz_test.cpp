// Stability scenario 7 of ACCURACY.md: distance functions that are not 1-Lipschitz (non-uniform
// scale, smooth-min blends, twist) marched in float by shaders/marching/sphere_trace.glsl.
// Why: sphere tracing trusts f(p) as a free radius; where |grad f| exceeds 1 a step overshoots
// the surface by up to (L - 1) times the true distance, and a part thinner than that is stepped
// over (a hole) or the march lands on a part behind it (a wrong hit). step_scale = 1 / L is
// the fix; this test shows the failure at step_scale 1 and its absence at 1 / L.
// Shapes (written here on sdf.glsl's sdf_sphere, sdf_box, sdf_twist and its twisted torus) and
// their TRUE bounds:
//   - ellipsoid sdf_sphere(p / s, 1), s = (0.9, 0.12, 0.6): grad = S^-1 grad g, so L = 1 / min(s)
//     = 8.33, reached on the flat faces; times min(s) it is a 1-Lipschitz bound of the same set.
//   - polynomial smooth min of two spheres (Quilez: h = clamp(0.5 + 0.5 (b - a) / k, 0, 1),
//     mix(b, a, h) - k h (1 - h)): d/dh vanishes at that h, so grad = h grad a + (1 - h) grad b,
//     a convex combination: L = max(L_a, L_b), 1 for two spheres (step 1 is already safe) and
//     8.33 for a sphere blended with the raw ellipsoid.
//   - twist about y by k rad per unit height: in the frame that turns with the twist the Jacobian
//     is I + v e_y^T with |v| = k rho, whose largest singular value is (k rho + sqrt(k^2 rho^2 + 4)) / 2
//     (sharper than sdf.glsl's 1 + k rho); rho <= sqrt(2) in the AABB [-1, 1]^3 that bounds the march.
// Ground truth: accuracy::lipschitz_search with the true bound in double on the same shape
// functions (the march is not shared), on the AABB-clipped ray.
#include <proceduray/shader/glsl_cpp.hpp>

#include <cstdint>

namespace lipschitz_test {
using namespace proceduray::glsl_cpp;
template <class T>
struct lib {
  PROCEDURAY_GLSL_CPP_SCALAR(T)
#include "primitives/sdf.glsl"
#include "common/ray.glsl"

  static constexpr uint ellipsoid_raw = 0u, ellipsoid_min = 1u, blend_spheres = 2u, blend_raw = 3u,
                        twisted_torus = 4u, twisted_plate = 5u, shape_count = 6u;
  static constexpr T torus_twist = T(3), plate_twist = T(4);

  static pr_real3 ellipsoid_radii() { return pr_real3(T(0.9), T(0.12), T(0.6)); }
  static pr_real ellipsoid(pr_real3 p) { return sdf_sphere(p / ellipsoid_radii(), T(1)); }

  /// Quilez's polynomial smooth minimum, blend width k.
  static pr_real smooth_min(pr_real a, pr_real b, pr_real k) {
    pr_real h = clamp(T(0.5) + T(0.5) * (b - a) / k, T(0), T(1));
    return mix(b, a, h) - k * h * (T(1) - h);
  }

  static pr_real distance(uint shape, pr_real3 p) {
    if (shape == ellipsoid_raw) return ellipsoid(p);
    if (shape == ellipsoid_min) return ellipsoid(p) * T(0.12);
    if (shape == blend_spheres) {
      return smooth_min(sdf_sphere(p - pr_real3(T(-0.35), T(0), T(0)), T(0.45)),
                        sdf_sphere(p - pr_real3(T(0.4), T(0.1), T(0)), T(0.3)), T(0.3));
    }
    if (shape == blend_raw) return smooth_min(sdf_sphere(p - pr_real3(T(0), T(0.45), T(0)), T(0.3)), ellipsoid(p), T(0.3));
    if (shape == twisted_torus) return sdf_twisted_torus_distance(p, torus_twist);
    return sdf_box(sdf_twist(p, plate_twist), pr_real3(T(0.7), T(0.9), T(0.06)));
  }

  static inline uint shape = 0u;  // what march_distance marches
  static pr_real march_distance(pr_real3 p) { return distance(shape, p); }
#include "marching/sphere_trace.glsl"
  struct Shape {};
  static pr_real shape_distance(pr_real3 p, Shape) { return march_distance(p); }
#define PROCEDURAY_MARCHER shape
#define PROCEDURAY_MARCHER_FIELD Shape
#define PROCEDURAY_MARCHER_DISTANCE shape_distance
#include "marching/marcher.glsl"
};
}  // namespace lipschitz_test

#include <proceduray/accuracy/closed_form.hpp>
#include <proceduray/accuracy/ground_truth.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace {

namespace acc = proceduray::accuracy;
using F = lipschitz_test::lib<float>;
using D = lipschitz_test::lib<double>;

/// The largest singular value of a twist's Jacobian at radius rho (see the header).
double twist_bound(double k, double rho) { return 0.5 * (k * rho + std::sqrt(k * k * rho * rho + 4.0)); }

/// The true Lipschitz bound of each shape over the AABB (see the header).
double true_bound(std::uint32_t shape) {
  const double raw = 1.0 / 0.12;
  switch (shape) {
    case F::ellipsoid_raw: return raw;
    case F::ellipsoid_min: return 1.0;
    case F::blend_spheres: return 1.0;
    case F::blend_raw: return raw;
    case F::twisted_torus: return twist_bound(D::torus_twist, std::sqrt(2.0));
    default: return twist_bound(D::plate_twist, std::sqrt(2.0));
  }
}

const std::string shape_names[] = {"ellipsoid raw", "ellipsoid times min(s)", "smooth-min of two spheres",
                             "smooth-min of sphere and raw ellipsoid", "twisted torus k 3", "twisted plate k 4"};

/// The D3D12 scene's knobs (512 steps, epsilon 1e-4, half a footprint) for a pixel of `pixel_angle`.
constexpr float pixel_angle = 2.0e-3f;
F::MarchSettings knobs(float step_scale, std::uint32_t max_steps = 512u) {
  return {max_steps, 1e-4f, 0.5f * pixel_angle, step_scale, 1.0f};
}

/// A 48 x 48 grid of unit rays from an oblique eye over the AABB, each with its clipped range.
struct Ray {
  glm::vec3 o, u;
  float t0, t1;       ///< ray_clip_aabb in float: the march's range
  double lo, hi;      ///< intersect_box in double: the truth's range
};
std::vector<Ray> rays() {
  std::vector<Ray> out;
  const glm::vec3 eye(0.9f, 1.4f, 3.2f), forward = glm::normalize(-eye);
  const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
  const glm::vec3 up = glm::cross(right, forward);
  const float half = std::tan(glm::radians(22.0f));
  for (int y = 0; y < 48; ++y) {
    for (int x = 0; x < 48; ++x) {
      const float a = ((float(x) + 0.5f) / 48.0f * 2.0f - 1.0f) * half, b = ((float(y) + 0.5f) / 48.0f * 2.0f - 1.0f) * half;
      Ray r{eye, glm::normalize(forward + a * right - b * up), 0.0f, 1e30f, 0.0, 0.0};
      if (!F::ray_clip_aabb(r.o, r.u, glm::vec3(-1.0f), glm::vec3(1.0f), r.t0, r.t1)) continue;
      const glm::dvec3 o(r.o), u(r.u);
      const acc::Result in = acc::intersect_box(o, u, glm::dvec3(-1.0), glm::dvec3(1.0), 0.0, 1e30);
      if (in.outcome != acc::Outcome::hit) continue;
      const acc::Result exit = acc::intersect_box(o, u, glm::dvec3(-1.0), glm::dvec3(1.0), in.t + 1e-9, 1e30);
      if (!(exit.outcome == acc::Outcome::hit && exit.starts_inside)) continue;  // a corner graze
      r.lo = in.t;
      r.hi = exit.t;
      out.push_back(r);
    }
  }
  return out;
}

/// lipschitz_search of shape + offset (offset < 0 grows the shape, > 0 shrinks it) on the ray.
acc::Result truth(std::uint32_t shape, const Ray& r, double offset = 0.0) {
  auto f = [shape, offset](glm::dvec3 p) { return D::distance(shape, p) + offset; };
  return acc::lipschitz_search(f, true_bound(shape), glm::dvec3(r.o), glm::dvec3(r.u), r.lo, r.hi,
                               {.min_step = 1e-9});
}

struct Outcome {
  std::size_t rays = 0, truth_hits = 0, clear = 0;         ///< clear: away from the silhouette band
  std::size_t misses = 0, wrong_hits = 0, exhausted = 0;    ///< over all rays
  std::size_t clear_misses = 0, clear_wrong_hits = 0;       ///< over the clear rays
  std::size_t long_misses = 0;  ///< misses of an inside run at least one threshold long
  std::size_t past_crossing = 0;  ///< hits more than 64 float spacings behind the truth's crossing
  double worst_t_ratio = 0;  ///< max |t - t_ref| / (threshold / 32 + float) over both-hit rays
  std::vector<double> steps;  ///< evaluations per march
};

/// The float march of `shape` at step_scale over the rays, against the truths.
Outcome compare(std::uint32_t shape, float step_scale, const std::vector<Ray>& rs, const std::vector<acc::Result>& ref,
                const std::vector<bool>& clear, std::uint32_t max_steps = 512u) {
  Outcome c;
  F::shape = shape;
  const F::MarchSettings m = knobs(step_scale, max_steps);
  for (std::size_t i = 0; i < rs.size(); ++i) {
    float s = 0.0f;
    std::uint32_t steps = 0;
    const bool hit = F::shape_trace(rs[i].o, rs[i].u, rs[i].t0, rs[i].t1, m, {}, s, steps);
    const bool truth_hit = ref[i].outcome == acc::Outcome::hit;
    ++c.rays;
    c.truth_hits += truth_hit;
    c.clear += clear[i];
    c.steps.push_back(double(steps));
    c.exhausted += !hit && steps >= m.max_steps;
    // The hit rule's tolerance: the bracket left by bisection (threshold / 32), whose outside end
    // is reported, plus float rounding of t and of the distance near the crossing (64 spacings
    // of t). Measured: up to 0.9995 of threshold / 32 in front of the crossing, never behind it
    // (by 0.003 of threshold / 32 at most in the other direction), so the float term is the margin.
    bool wrong = false;
    if (hit) {
      const double tolerance = double(F::march_epsilon(m, float(ref[i].t))) * double(F::march_refine_fraction) +
                               64.0 * std::ldexp(1.0, -24) * ref[i].t;
      const double ratio = truth_hit ? std::abs(double(s) - ref[i].t) / tolerance : 1e30;
      wrong = ratio > 1.0;
      if (truth_hit) c.worst_t_ratio = std::max(c.worst_t_ratio, ratio);
      c.past_crossing += truth_hit && double(s) - ref[i].t > 64.0 * std::ldexp(1.0, -24) * ref[i].t;
    }
    const bool miss = truth_hit && !hit;
    if (miss) {
      // The inside run the march missed: from the entry to the exit (a search from just inside).
      auto f = [shape](glm::dvec3 p) { return D::distance(shape, p); };
      const acc::Result exit = acc::lipschitz_search(f, true_bound(shape), glm::dvec3(rs[i].o), glm::dvec3(rs[i].u),
                                                     ref[i].t + 1e-9, rs[i].hi, {.min_step = 1e-9});
      const double run = exit.starts_inside ? exit.t - ref[i].t : 0.0;
      c.long_misses += run >= double(F::march_epsilon(m, float(ref[i].t)));
    }
    c.misses += miss;
    c.wrong_hits += wrong;
    c.clear_misses += miss && clear[i];
    c.clear_wrong_hits += wrong && clear[i];
  }
  return c;
}

}  // namespace

TEST_CASE("lipschitz - the stated bounds hold and are reached by sampled slopes") {
  // Random pairs 1e-3 apart in the AABB: the bound is a bound, and (where sharp) nearly reached.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::uint32_t shape = 0; shape < F::shape_count; ++shape) {
    double worst = 0.0;
    for (int i = 0; i < 20000; ++i) {
      const glm::dvec3 p(u(rng), u(rng), u(rng)), dir = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)));
      const glm::dvec3 q = glm::clamp(p + 1e-3 * dir, glm::dvec3(-1.0), glm::dvec3(1.0));
      if (q == p) continue;
      worst = std::max(worst, std::abs(D::distance(shape, p) - D::distance(shape, q)) / glm::length(p - q));
    }
    MESSAGE(shape_names[shape] << ": sampled slope " << worst << ", bound " << true_bound(shape));
    CAPTURE(shape);
    CHECK(worst <= true_bound(shape) * (1.0 + 1e-6));
    // The scale and the blends reach their bounds (the flat faces), so 1 / L is no wasted caution:
    // seen 0.999 L, and 0.87 L for the blend with the raw ellipsoid (its flattest part is blended
    // away near the sphere, so random pairs hit the face less often). The twists' sampled slopes (2.0 and 2.9, against 4.5 and 5.8) stay below:
    // rho = sqrt(2) occurs only at the AABB's vertical edges, and the gradient of the untwisted
    // shape there is not along v.
    if (shape <= F::blend_raw) CHECK(worst >= 0.75 * true_bound(shape));
    if (shape >= F::twisted_torus) CHECK(worst > 1.5);
  }
}

TEST_CASE("lipschitz - step scale 1 over-steps non-1-Lipschitz shapes and step scale 1 over L misses nothing") {
  const std::vector<Ray> rs = rays();
  REQUIRE(rs.size() > 1500);
  for (std::uint32_t shape = 0; shape < F::shape_count; ++shape) {
    const double L = true_bound(shape);
    // Truth, and which rays are clear of the silhouette band: the shape shrunk by L times the
    // largest threshold on the ray is still hit (the inside run is longer than 2 thresholds, so
    // no probe can step over it), or the shape grown by as much is still missed.
    std::vector<acc::Result> ref;
    std::vector<bool> clear;
    for (const Ray& r : rs) {
      ref.push_back(truth(shape, r));
      REQUIRE(ref.back().outcome != acc::Outcome::undetermined);
      REQUIRE_FALSE(ref.back().starts_inside);
      const double margin = L * double(F::march_epsilon(knobs(1.0f), float(r.hi)));
      clear.push_back(ref.back().outcome == acc::Outcome::hit ? truth(shape, r, margin).outcome == acc::Outcome::hit
                                                              : truth(shape, r, -margin).outcome == acc::Outcome::miss);
    }
    const Outcome one = compare(shape, 1.0f, rs, ref, clear);
    const Outcome scaled = compare(shape, float(1.0 / L), rs, ref, clear);
    // Steps of 1 / L are L times shorter, so a march needs up to L times the evaluations: the
    // scene's 512 with the budget scaled by ceil(L).
    const std::uint32_t more = 512u * std::uint32_t(std::ceil(L));
    const Outcome budget = compare(shape, float(1.0 / L), rs, ref, clear, more);
    auto median = [](std::vector<double> v) {
      std::sort(v.begin(), v.end());
      return v[v.size() / 2];
    };
    MESSAGE(shape_names[shape] << " (L " << L << "): rays " << one.rays << ", truth hits " << one.truth_hits
                               << ", clear of the silhouette band " << one.clear << "; step scale 1: misses "
                               << one.misses << " (clear " << one.clear_misses << "), wrong hits " << one.wrong_hits
                               << " (clear " << one.clear_wrong_hits << "), median steps " << median(one.steps)
                               << "; step scale 1/L, 512 steps: misses " << scaled.misses << " (clear "
                               << scaled.clear_misses << ", of a run over a threshold " << scaled.long_misses
                               << ", out of steps " << scaled.exhausted << "), wrong hits "
                               << scaled.wrong_hits << ", median steps " << median(scaled.steps) << " max "
                               << *std::max_element(scaled.steps.begin(), scaled.steps.end()) << "; with " << more
                               << " steps: misses " << budget.misses << " (of a run over a threshold "
                               << budget.long_misses << "), wrong hits " << budget.wrong_hits << ", max steps "
                               << *std::max_element(budget.steps.begin(), budget.steps.end())
                               << "; worst |t - t_ref| / (threshold/32 + 64 float spacings) " << budget.worst_t_ratio);
    CAPTURE(shape);
    CHECK(one.truth_hits >= one.rays / 10);
    CHECK(one.clear >= one.rays * 9 / 10);  // seen >= 93 %
    // 1 / L, at the scene's 512 steps and at L times as many: zero wrong hits on every ray and
    // zero misses on every clear ray. In the silhouette band a miss may only be what the hit
    // rule documents: an inside run shorter than one threshold, which a probe can step over
    // (seen: one ray of the twisted plate, a run of 2.7e-4 at a threshold of 3.9e-3).
    CHECK(scaled.wrong_hits == 0);
    CHECK(scaled.clear_misses == 0);
    CHECK(scaled.long_misses == 0);
    CHECK(budget.wrong_hits == 0);
    CHECK(budget.clear_misses == 0);
    CHECK(budget.long_misses == 0);
    CHECK(budget.misses <= 2);  // seen: 0, and 1 for the twisted plate
    CHECK(budget.exhausted == 0);
    CHECK(budget.worst_t_ratio <= 1.0);
    CHECK(budget.past_crossing == 0);  // the outside end: never inside the shape
    // Where L > 1, step scale 1 fails on clear rays, not only at silhouettes.
    if (L > 1.0) CHECK(one.clear_misses + one.clear_wrong_hits > 0);
    if (L == 1.0) CHECK(one.misses + one.wrong_hits == 0);
  }
}
