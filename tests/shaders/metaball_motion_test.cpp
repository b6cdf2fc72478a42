// Tests for shaders/primitives/metaball_motion.glsl and the data-driven metaballs.glsl, compiled
// as C++ (float, as the GPU runs them): a proceduray::Metaballs block of any sources, each with
// its own radius, against ground truth independent of the march: the falloff's root in double
// by bisection, and the host's motion formula.
#include <proceduray/march/metaballs.hpp>

#include <proceduray/shader/glsl_cpp.hpp>

namespace metaball_motion_test {
using namespace proceduray::glsl_cpp;
using proceduray::Metaball;   // the generated structs' C++ side: same names, same members
using proceduray::Metaballs;
#include "primitives/metaball_motion.glsl"
}  // namespace metaball_motion_test

#include <doctest/doctest.h>

#include <cmath>

using namespace metaball_motion_test;

namespace {

/// x in (0, 1) where the falloff 1 - (6x^5 - 15x^4 + 10x^3) equals t: bisection in double.
double falloff_root(double t) {
  double lo = 0.0, hi = 1.0;  // falloff(lo) = 1 > t > 0 = falloff(hi), decreasing
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi), x3 = mid * mid * mid;
    const double f = 1.0 - x3 * (mid * (6.0 * mid - 15.0) + 10.0);
    (f > t ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

MarchSettings settings() {
  MarchSettings m{};
  m.max_steps = 512u;
  m.epsilon = 1.0e-5f;
  m.footprint = 0.0f;
  m.step_scale = 1.0f;
  m.over_relaxation = 1.0f;
  m.fixed_steps = 0u;
  m.hit_rule = march_hit_refined;
  return m;
}

}  // namespace

TEST_CASE("metaball motion places each source where the host formula does") {
  const Metaballs blob = proceduray::make_metaballs(
      {proceduray::metaball({0.5f, 0.0f, 0.0f}, 0.4f, {0.2f, 0.1f, 0.0f}, {1.1f, 0.7f, 0.0f}, {0.0f, 1.0f, 0.0f}),
       proceduray::metaball({-0.5f, 0.2f, 0.0f}, 0.7f)},
      0.3f);
  for (const float time : {0.0f, 0.8f, 3.5f}) {
    const MetaballList list = metaballs_at(blob, time);
    REQUIRE(list.count == 2u);
    for (std::uint32_t i = 0; i < 2; ++i) {
      const glm::vec3 host = proceduray::metaball_centre_at(blob.ball[i], time);
      CHECK(glm::vec3(list.ball[i]) == host);
      CHECK(list.ball[i].w == blob.ball[i].radius);
    }
    CHECK(list.ball[2] == glm::vec4(0.0f));  // unused slots stay empty
  }
}

TEST_CASE("metaballs of different radii: each isolated source's surface sits at its own radius' root") {
  // Two sources far enough apart that neither reaches the other: each surface is a sphere of
  // radius x* R_i, x* the falloff's root at the threshold.
  const float threshold = 0.25f;
  const Metaballs blob = proceduray::make_metaballs(
      {proceduray::metaball({-2.0f, 0.0f, 0.0f}, 0.5f), proceduray::metaball({2.0f, 0.0f, 0.0f}, 1.0f)}, threshold);
  const MetaballList balls = metaballs_at(blob, 0.0f);
  const double x_star = falloff_root(threshold);
  for (std::uint32_t i = 0; i < 2; ++i) {
    const glm::vec3 c = glm::vec3(balls.ball[i]);
    const glm::vec3 o = c + glm::vec3(0.0f, 0.0f, 5.0f), u(0.0f, 0.0f, -1.0f);
    const double truth = 5.0 - x_star * blob.ball[i].radius;
    for (const bool segment : {false, true}) {
      CAPTURE(i);
      CAPTURE(segment);
      float s = 0.0f;
      glm::vec3 n(0.0f);
      uint steps = 0u;
      REQUIRE(metaballs_march_lipschitz(o, u, 0.0f, 10.0f, balls, threshold, segment, settings(), s, n, steps));
      CHECK(std::abs(double(s) - truth) < 1.0e-4);
      CHECK(n.z == doctest::Approx(1.0f).epsilon(1e-3));  // facing the ray
    }
    float s = 0.0f;
    glm::vec3 n(0.0f);
    uint steps = 0u;
    REQUIRE(metaballs_march_fixed(o, u, 0.0f, 10.0f, balls, threshold, 256u, march_hit_refined, s, n, steps));
    CHECK(std::abs(double(s) - truth) < 10.0 / 256.0 / 512.0);  // a step bisected 10 times
  }
}

TEST_CASE("metaballs with no source, or a source of radius 0, are a miss and never a NaN") {
  MetaballList none{};
  none.count = 0u;
  float s = 1.0f;
  glm::vec3 n(0.0f);
  uint steps = 7u;
  CHECK_FALSE(metaballs_march_lipschitz(glm::vec3(0, 0, 5), glm::vec3(0, 0, -1), 0.0f, 10.0f, none, 0.25f, true,
                                        settings(), s, n, steps));
  CHECK(steps == 0u);
  MetaballList flat{};
  flat.count = 1u;
  flat.ball[0] = glm::vec4(0.0f);  // radius 0
  CHECK_FALSE(metaballs_march_fixed(glm::vec3(0, 0, 5), glm::vec3(0, 0, -1), 0.0f, 10.0f, flat, 0.25f, 64u,
                                    march_hit_refined, s, n, steps));
  CHECK(std::isfinite(s));
}
