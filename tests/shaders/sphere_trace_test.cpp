// Tests for shaders/marching/sphere_trace.glsl, compiled as C++: hits, misses, exhausted steps,
// over-relaxation on a thin plate (also at the range's end) and its fallback, tetrahedral normals.
#include "common/glsl_cpp.hpp"

#include <cmath>
#include <initializer_list>

namespace sphere_trace_test {
using namespace proceduray_glsl_cpp;
// 0: unit sphere; 1: thin plate |z| <= 0.01 (exact distances, Lipschitz 1).
inline int shape = 0;
inline float march_distance(vec3 p) { return shape == 0 ? length(p) - 1.0f : std::abs(p.z) - 0.01f; }
#include "../../shaders/marching/sphere_trace.glsl"
}  // namespace sphere_trace_test

#include <doctest/doctest.h>

using namespace sphere_trace_test;

namespace {
MarchSettings settings(float w = 1.0f, std::uint32_t steps = 256) { return MarchSettings{steps, 1e-5f, 0.0f, 1.0f, w}; }
}

TEST_CASE("sphere_trace hits the unit sphere within epsilon") {
  shape = 0;
  for (float w : {1.0f, 1.2f, 1.6f, 1.9f}) {
    float s;
    std::uint32_t steps;
    REQUIRE(sphere_trace(glm::vec3(0.0f, 0.3f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f, settings(w), s, steps));
    CAPTURE(w);
    CHECK(s == doctest::Approx(5.0f - std::sqrt(1.0f - 0.09f)).epsilon(1e-4));
    CHECK(s <= 5.0f - std::sqrt(1.0f - 0.09f) + 1e-6f);  // never past the surface
    CHECK(steps > 0u);
  }
}

TEST_CASE("sphere_trace misses when the ray misses or the range ends") {
  shape = 0;
  float s;
  std::uint32_t steps;
  CHECK_FALSE(sphere_trace(glm::vec3(0.0f, 1.5f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f, settings(), s, steps));
  CHECK_FALSE(sphere_trace(glm::vec3(0.0f, 0.0f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 3.5f, settings(), s, steps));
}

TEST_CASE("sphere_trace reports a miss when steps run out") {
  shape = 0;
  float s;
  std::uint32_t steps;
  // A grazing ray needs many steps near the silhouette: with 4 it must not claim a hit.
  CHECK_FALSE(sphere_trace(glm::vec3(0.0f, 1.0f + 1e-4f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f,
                           settings(1.0f, 4), s, steps));
  CHECK(steps == 4u);
  CHECK_FALSE(sphere_trace(glm::vec3(0.0f, 0.0f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f, settings(1.0f, 0),
                           s, steps));
}

TEST_CASE("sphere_trace footprint threshold grows with distance") {
  shape = 0;
  MarchSettings m = settings();
  m.footprint = 0.01f;
  CHECK(march_epsilon(m, 0.0f) == 1e-5f);
  CHECK(march_epsilon(m, 10.0f) == doctest::Approx(0.1f));
  float s;
  std::uint32_t coarse, fine;
  REQUIRE(sphere_trace(glm::vec3(0.0f, 0.0f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f, m, s, coarse));
  CHECK(s == doctest::Approx(4.0f).epsilon(0.02));
  REQUIRE(sphere_trace(glm::vec3(0.0f, 0.9f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f, settings(), s, fine));
  m.footprint = 0.0f;
}

TEST_CASE("over-relaxation does not tunnel through a thin plate") {
  shape = 1;
  const glm::vec3 dir = glm::normalize(glm::vec3(1.0f, 0.0f, 0.05f));  // shallow: long relaxed steps
  const float expected = (-0.01f + 2.0f) / dir.z;                     // from z = -2 to z = -0.01
  for (float w : {1.0f, 1.2f, 1.6f, 1.9f}) {
    float s;
    std::uint32_t steps;
    REQUIRE(sphere_trace(glm::vec3(0.0f, 0.0f, -2.0f), dir, 0.0f, 100.0f, settings(w, 4096), s, steps));
    CAPTURE(w);
    CHECK(s == doctest::Approx(expected).epsilon(1e-3));
  }
  shape = 0;
}

TEST_CASE("over-relaxation finds a thin plate just before the end of the range") {
  // Head-on from z = -2 with the range ending at s = 2: the plate's front is at s = 1.99. The
  // first relaxed step (w * 1.99) leaves the range; a march that called that a miss would
  // pass through the plate (a thin part near the AABB's exit), so it must retry the plain step.
  shape = 1;
  for (float w : {1.0f, 1.2f, 1.6f, 1.9f}) {
    float s;
    std::uint32_t steps;
    CAPTURE(w);
    REQUIRE(sphere_trace(glm::vec3(0.0f, 0.0f, -2.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 2.0f, settings(w), s, steps));
    CHECK(s == doctest::Approx(1.99f).epsilon(1e-5));
    CHECK(steps <= 3u);  // the relaxed step, then the plain step's end (a hit there)
  }
  // Beyond the range it stays a miss, relaxed or not.
  float s;
  std::uint32_t steps;
  CHECK_FALSE(sphere_trace(glm::vec3(0.0f, 0.0f, -2.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 1.9f, settings(1.6f), s, steps));
  shape = 0;
}

TEST_CASE("relaxed steps fall back once they stop overlapping and then march plainly") {
  // Head-on at the unit sphere from z = -5: r = 4, the relaxed step of 6.4 lands past the
  // sphere (z = 1.4, r = 0.4): 4 + 0.4 < 6.4, the spheres leave a gap, so the march goes back
  // to s = 4 (the plain step's end) and hits there.
  shape = 0;
  float s;
  std::uint32_t steps;
  REQUIRE(sphere_trace(glm::vec3(0.0f, 0.0f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f, settings(1.6f), s, steps));
  CHECK(s == doctest::Approx(4.0f));
  CHECK(steps == 3u);  // s = 0, s = 6.4 (rejected), s = 4
  // w = 1 never falls back: two evaluations.
  REQUIRE(sphere_trace(glm::vec3(0.0f, 0.0f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f, settings(1.0f), s, steps));
  CHECK(steps == 2u);
}

TEST_CASE("tetrahedral normal of the sphere is radial") {
  shape = 0;
  const glm::vec3 n = tetrahedral_normal(glm::normalize(glm::vec3(1.0f, 2.0f, -2.0f)), 1e-3f);
  CHECK(glm::dot(n, glm::normalize(glm::vec3(1.0f, 2.0f, -2.0f))) == doctest::Approx(1.0f).epsilon(1e-4));
  const glm::vec3 flat = tetrahedral_normal(glm::vec3(5.0f), 0.0f);  // h = 0: zero gradient, fallback
  CHECK(std::isfinite(flat.x + flat.y + flat.z));
}
