// shaders/marching/knobs.glsl and the methods it selects, compiled as C++: knobs -> settings,
// fixed steps + bisection, unrefined hits, iterations by distance, and segment tracing on the
// metaballs (metaballs.glsl) against the global Lipschitz march. Where a method fails (fixed
// steps over a part thinner than a step), the test says so.
#include <proceduray/shader/glsl_cpp.hpp>

#include <proceduray/march/knobs.hpp>
#include <proceduray/march/primitives.hpp>

namespace march_methods_test {
using namespace proceduray::glsl_cpp;
using MarchKnobs = proceduray::MarchKnobs;
/// A unit sphere, or (slab != 0) a slab |z - 2| < slab / 2 as well.
inline float slab = 0.0f;
inline float march_distance(vec3 p) {
  const float sphere = length(p) - 1.0f;
  return slab > 0.0f ? std::min(sphere, std::abs(p.z - 2.0f) - 0.5f * slab) : sphere;
}
#include "marching/knobs.glsl"
/// The marcher of this test's shape (marching/marcher.glsl): prefix shape, no field data.
struct Shape {};
inline float shape_distance(vec3 p, Shape) { return march_distance(p); }
#define PROCEDURAY_MARCHER shape
#define PROCEDURAY_MARCHER_FIELD Shape
#define PROCEDURAY_MARCHER_DISTANCE shape_distance
#include "marching/marcher.glsl"
namespace blob {
#include "primitives/metaballs.glsl"
}  // namespace blob
}  // namespace march_methods_test

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace march_methods_test;
using proceduray::MarchMethod;

namespace {

MarchKnobs knobs(const char* method) {
  MarchKnobs k = proceduray::march_base_knobs;
  proceduray::set_knob(k, "method", method);
  k.threshold_mode = proceduray::MarchThreshold::absolute;
  k.threshold = 1e-3f;
  return k;
}

struct Marched {
  bool hit = false;
  float s = 0.0f;
  uint steps = 0;
};

Marched trace(const MarchKnobs& k, vec3 o, vec3 u, float s_hi = 6.0f) {
  Marched m;
  m.hit = shape_trace(o, u, 0.0f, s_hi, march_settings(k, 1.0f, 1e-3f, 1.0f), {}, m.s, m.steps);
  return m;
}

}  // namespace

TEST_CASE("march methods - knobs map to the settings the marches read") {
  MarchKnobs k = proceduray::march_base_knobs;  // lipschitz, footprint 0.5, epsilon 1e-4
  MarchSettings m = march_settings(k, 2.0f, 1e-3f, 4.0f);
  CHECK(m.max_steps == 512u);
  CHECK(m.epsilon == doctest::Approx(0.5e-4f));  // world units / world per object
  CHECK(m.footprint == doctest::Approx(0.5e-3f));
  CHECK(m.step_scale == doctest::Approx(0.25f));  // 1 / L
  CHECK(m.over_relaxation == 1.0f);
  CHECK(m.fixed_steps == 0u);
  CHECK(m.hit_rule == march_hit_refined);
  CHECK(m.probe == 2.0f);  // the base knobs' probe: the old constant
  k.probe = 4.0f;
  CHECK(march_settings(k, 2.0f, 1e-3f, 4.0f).probe == 4.0f);
  k.method = MarchMethod::sphere;
  CHECK(march_settings(k, 2.0f, 1e-3f, 4.0f).step_scale == 1.0f);  // plain: no bound applied
  k.method = MarchMethod::relaxed;
  k.relaxation = 1.6f;
  m = march_settings(k, 2.0f, 1e-3f, 4.0f);
  CHECK(m.over_relaxation == doctest::Approx(1.6f));
  CHECK(m.step_scale == doctest::Approx(0.25f));
  k.method = MarchMethod::fixed;
  k.refine = 0;
  k.threshold_mode = proceduray::MarchThreshold::absolute;
  k.threshold = 0.01f;
  m = march_settings(k, 2.0f, 1e-3f, 4.0f);
  CHECK(m.fixed_steps == 64u);
  CHECK(m.hit_rule == march_hit_unrefined);
  CHECK(m.epsilon == doctest::Approx(0.005f));
  CHECK(m.footprint == 0.0f);
  CHECK(march_knobs_threshold(k, 1e-3f, 100.0f) == doctest::Approx(0.01f));
  k.threshold_mode = proceduray::MarchThreshold::footprint;
  k.threshold = 0.5f;
  CHECK(march_knobs_threshold(k, 1e-3f, 100.0f) == doctest::Approx(0.05f));
  CHECK(march_normal_evaluations(k) == 6u);
  k.normal = proceduray::MarchNormal::tetrahedral;
  CHECK(march_normal_evaluations(k) == 4u);
}

TEST_CASE("bad input: knobs written into memory without validate() are clamped, so no march hangs or hides") {
  CHECK(march_steps_cap == proceduray::march_max_steps_limit);  // the shader's caps are the host's limits
  CHECK(march_step_scale_floor == proceduray::march_min_step_scale);
  MarchKnobs k = knobs("lipschitz");
  k.max_steps = 0xFFFFFFFFu;  // with 1e-30 steps this loop would run for hours on the device
  k.step_scale = 1.0e-30f;
  MarchSettings m = march_settings(k, 1.0f, 1e-3f, 1.0f);
  CHECK(m.max_steps == proceduray::march_max_steps_limit);
  CHECK(m.step_scale == doctest::Approx(proceduray::march_min_step_scale));
  const Marched far = trace(k, vec3(0.0f, 0.0f, -5.0f), vec3(0.0f, 1.0f, 0.0f), 1.0e30f);  // a miss: every step spent
  CHECK_FALSE(far.hit);
  CHECK(far.steps <= proceduray::march_max_steps_limit);
  k.step_scale = std::numeric_limits<float>::quiet_NaN();
  CHECK(march_settings(k, 1.0f, 1e-3f, 1.0f).step_scale == doctest::Approx(proceduray::march_min_step_scale));
  k.step_scale = 8.0f;  // longer than the bound allows: would step through the surface
  CHECK(march_settings(k, 1.0f, 1e-3f, 1.0f).step_scale == 1.0f);
  k = knobs("lipschitz");
  k.max_steps = 0;  // would make the sphere vanish without a word; one step at least is taken
  CHECK(march_settings(k, 1.0f, 1e-3f, 1.0f).max_steps == 1u);
}

TEST_CASE("march methods - fractal iterations by distance drop one per doubling of the footprint") {
  MarchKnobs k = proceduray::fractal_capabilities(8).defaults;
  CHECK(march_iterations(k, 1.0f) == 8u);  // fixed mode: all, however far
  k.iteration_mode = proceduray::MarchIterations::by_distance;
  k.iteration_detail = 0.01f;
  CHECK(march_iterations(k, 0.005f) == 8u);
  CHECK(march_iterations(k, 0.01f) == 8u);
  CHECK(march_iterations(k, 0.015f) == 7u);
  CHECK(march_iterations(k, 0.02f) == 7u);
  CHECK(march_iterations(k, 0.03f) == 6u);
  CHECK(march_iterations(k, 1.0e6f) == 1u);  // never below one
}

TEST_CASE("march methods - fixed steps and unrefined hits stay on the outside, within their bounds") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> tilt(-0.6f, 0.6f);
  std::uint32_t refined_steps = 0, unrefined_steps = 0;
  for (int i = 0; i < 200; ++i) {
    const vec3 o(tilt(rng), tilt(rng), -3.0f);
    const vec3 u = normalize(vec3(0.0f, 0.0f, 1.0f) - 0.2f * vec3(o.x, o.y, 0.0f));
    // The closed form: first root of |o + s u| = 1.
    const double b = dot(dvec3(o), dvec3(u)), c = dot(dvec3(o), dvec3(o)) - 1.0;
    const double disc = b * b - c;
    if (disc <= 0.0) continue;
    const double truth = -b - std::sqrt(disc);
    CAPTURE(i);
    const Marched refined = trace(knobs("lipschitz"), o, u);
    MarchKnobs k = knobs("lipschitz");
    k.refine = 0;
    const Marched unrefined = trace(k, o, u);
    MarchKnobs f = knobs("fixed");
    f.fixed_steps = 120;  // 0.05 per step over 6 units
    const Marched fixed = trace(f, o, u);
    f.refine = 0;
    const Marched fixed_unrefined = trace(f, o, u);
    REQUIRE(refined.hit);
    REQUIRE(unrefined.hit);
    REQUIRE(fixed.hit);
    REQUIRE(fixed_unrefined.hit);
    CHECK(truth - refined.s >= -1e-6);  // outside (or on) the surface, to a few float spacings
    CHECK(truth - refined.s <= 1e-3 / 32 + 1e-6);
    CHECK(truth - unrefined.s >= -1e-6);
    CHECK(truth - unrefined.s <= 1e-3 + 1e-6);  // one probe at most
    CHECK(unrefined.steps <= refined.steps);
    refined_steps += refined.steps;
    unrefined_steps += unrefined.steps;
    CHECK(truth - fixed.s >= -1e-6);
    CHECK(truth - fixed.s <= 1e-3 / 32 + 1e-6);
    CHECK(truth - fixed_unrefined.s >= -1e-6);
    CHECK(truth - fixed_unrefined.s <= 0.05 + 1e-6);  // one fixed step at most
    CHECK(fixed.steps <= 512u);
  }
  CHECK(unrefined_steps < refined_steps);  // an exact bound often lands on the surface: no bisection either way
}

TEST_CASE("march methods - fixed steps fail on a part thinner than a step, sphere tracing does not") {
  slab = 0.02f;  // |z - 2| < 0.01, beside nothing else on this ray
  const vec3 o(3.0f, 0.0f, 0.0f), u(0.0f, 0.0f, 1.0f);
  MarchKnobs f = knobs("fixed");
  f.fixed_steps = 50;  // 0.12 per step over [0, 6]: the slab lies between two samples
  const Marched fixed = trace(f, o, u);
  const Marched traced = trace(knobs("lipschitz"), o, u);
  slab = 0.0f;
  CHECK_FALSE(fixed.hit);
  REQUIRE(traced.hit);
  CHECK(traced.s == doctest::Approx(1.99f).epsilon(1e-3));
}

TEST_CASE("march methods - segment tracing finds the metaballs' surface with fewer evaluations") {
  // Rays at the blob from around it: the segment bound's hits equal the global bound's (both
  // bracket the first crossing and bisect it the same way) and cost fewer evaluations.
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> angle(0.0f, 6.2831853f), spread(-0.5f, 0.5f);
  MarchSettings m{512u, 1e-4f, 0.0f, 1.0f, 1.0f, 0u, march_hit_refined};
  std::size_t agree = 0, rays = 0, hits = 0;
  double global_steps = 0.0, segment_steps = 0.0;
  for (int i = 0; i < 400; ++i) {
    const float a = angle(rng);
    const vec3 o(3.0f * std::cos(a), spread(rng), 3.0f * std::sin(a));
    const vec3 u = normalize(vec3(spread(rng), spread(rng), spread(rng)) * 0.6f - o);
    float s0 = 0.0f, s1 = 0.0f;
    vec3 n0, n1;
    uint c0 = 0, c1 = 0;
    const bool h0 = blob::metaballs_march(o, u, 0.0f, 6.0f, 0.6f, 0.25f, 0.3f, blob::metaball_method_lipschitz, 128u, m,
                                          s0, n0, c0);
    const bool h1 = blob::metaballs_march(o, u, 0.0f, 6.0f, 0.6f, 0.25f, 0.3f, blob::metaball_method_segment, 128u, m,
                                          s1, n1, c1);
    ++rays;
    agree += h0 == h1;
    if (h0 && h1) {
      ++hits;
      CHECK(std::abs(s0 - s1) <= 2e-3f);
    }
    global_steps += c0;
    segment_steps += c1;
  }
  CAPTURE(global_steps / rays);
  CAPTURE(segment_steps / rays);
  CHECK(agree >= rays * 99 / 100);
  CHECK(hits > rays / 3);
  CHECK(segment_steps < 0.8 * global_steps);
}
