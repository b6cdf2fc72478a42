// Tests for shaders/marching/sphere_trace.glsl, compiled as C++: hits, misses, exhausted steps,
// the hit rule (a sign change, bisected; grazing rays march on; the threshold on the unscaled
// distance), over-relaxation on a thin plate (also at the range's end) and its fallback,
// longer probes for an underestimating bound, tetrahedral normals.
#include <proceduray/shader/glsl_cpp.hpp>

#include <algorithm>
#include <cmath>
#include <initializer_list>

namespace sphere_trace_test {
using namespace proceduray::glsl_cpp;
// 0: unit sphere; 1: thin plate |z| <= 0.01 (exact distances, Lipschitz 1); 2: the unit sphere
// as an estimate that is 0 inside (as the fractals' are); 3: the unit sphere's distance a
// quarter of the truth outside (an estimate that underestimates 4-fold, as the Mandelbulb's
// does near its surface).
inline int shape = 0;
inline float march_distance(vec3 p) {
  if (shape == 1) return std::abs(p.z) - 0.01f;
  const float d = length(p) - 1.0f;
  if (shape == 3) return d > 0.0f ? 0.25f * d : d;
  return shape == 2 ? std::max(d, 0.0f) : d;
}
#include "marching/sphere_trace.glsl"
/// The marcher of this test's shape (marching/marcher.glsl): prefix shape, no field data.
struct Shape {};
inline float shape_distance(vec3 p, Shape) { return march_distance(p); }
#define PROCEDURAY_MARCHER shape
#define PROCEDURAY_MARCHER_FIELD Shape
#define PROCEDURAY_MARCHER_DISTANCE shape_distance
#include "marching/marcher.glsl"
}  // namespace sphere_trace_test

#include <doctest/doctest.h>

using namespace sphere_trace_test;

namespace {
MarchSettings settings(float w = 1.0f, std::uint32_t steps = 256) { return MarchSettings{steps, 1e-5f, 0.0f, 1.0f, w}; }
}

TEST_CASE("sphere_trace hits the unit sphere within epsilon") {
  shape = 0;
  for (float w : {1.0f, 1.2f, 1.6f, 1.9f}) {
    float s = 0.0f;
    std::uint32_t steps = 0;
    REQUIRE(shape_trace(glm::vec3(0.0f, 0.3f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f, settings(w), {}, s, steps));
    CAPTURE(w);
    CHECK(s == doctest::Approx(5.0f - std::sqrt(1.0f - 0.09f)).epsilon(1e-4));
    CHECK(s <= 5.0f - std::sqrt(1.0f - 0.09f) + 1e-6f);  // never past the surface
    CHECK(steps > 0u);
  }
}

TEST_CASE("sphere_trace misses when the ray misses or the range ends") {
  shape = 0;
  float s = 0.0f;
  std::uint32_t steps = 0;
  CHECK_FALSE(shape_trace(glm::vec3(0.0f, 1.5f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f, settings(), {}, s, steps));
  CHECK_FALSE(shape_trace(glm::vec3(0.0f, 0.0f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 3.5f, settings(), {}, s, steps));
}

TEST_CASE("sphere_trace reports a miss when steps run out") {
  shape = 0;
  float s = 0.0f;
  std::uint32_t steps = 0;
  // A grazing ray needs many steps near the silhouette: with 4 it must not claim a hit.
  CHECK_FALSE(shape_trace(glm::vec3(0.0f, 1.0f + 1e-4f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f, settings(1.0f, 4), {}, s, steps));
  CHECK(steps == 4u);
  CHECK_FALSE(shape_trace(glm::vec3(0.0f, 0.0f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f, settings(1.0f, 0), {}, s, steps));
}

TEST_CASE("sphere_trace footprint threshold grows with distance") {
  shape = 0;
  MarchSettings m = settings();
  m.footprint = 0.01f;
  CHECK(march_epsilon(m, 0.0f) == 1e-5f);
  CHECK(march_epsilon(m, 10.0f) == doctest::Approx(0.1f));
  float s = 0.0f;
  std::uint32_t coarse, fine;
  // A threshold of ~0.04 at s = 4: probes and the bisection's tolerance scale with it.
  REQUIRE(shape_trace(glm::vec3(0.0f, 0.6f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f, m, {}, s, coarse));
  CHECK(s == doctest::Approx(4.2f).epsilon(0.02));
  CHECK(std::abs(s - 4.2f) <= march_refine_fraction * march_epsilon(m, s) + 1e-5f);
  REQUIRE(shape_trace(glm::vec3(0.0f, 0.6f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f, settings(), {}, s, fine));
  CHECK(coarse < fine);
}

namespace {
/// The exact t of the unit sphere along +z from (0, y, -5), |y| < 1.
float sphere_t(float y) { return 5.0f - std::sqrt(1.0f - y * y); }
}  // namespace

TEST_CASE("sphere_trace: a grazing ray that passes within the threshold is a miss") {
  // The classic rule stops at the first distance below the threshold, so a ray passing the
  // unit sphere 0.3 thresholds away was a hit (a fat silhouette). Now the march probes for an
  // inside point, finds none, and marches on to the end of the range.
  shape = 0;
  for (const float eps : {1e-3f, 1e-2f}) {
    MarchSettings m = settings(1.0f, 4096);
    m.epsilon = eps;
    float s = 0.0f;
    std::uint32_t steps = 0;
    CAPTURE(eps);
    CHECK_FALSE(shape_trace(glm::vec3(0.0f, 1.0f + 0.3f * eps, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f, m, {}, s, steps));
    // Plain steps shrink towards the closest approach, then probes of 0.6 to 1 threshold cover
    // the stretch where the distance stays below it (2 sqrt(1.4 eps) long), then plain steps
    // to the end: seen 187 evaluations at 1e-3, 60 at 1e-2 (the classic rule took 45 and 14,
    // to a false hit).
    CHECK(steps < 256u);
    MESSAGE("grazing at 0.3 thresholds, threshold " << eps << ": " << steps << " evaluations");
    // A ray that does enter, a tenth of a threshold inside the silhouette, is a hit.
    const float y = 1.0f - 0.1f * eps;
    REQUIRE(shape_trace(glm::vec3(0.0f, y, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f, m, {}, s, steps));
    CHECK(s <= sphere_t(y));
    CHECK(march_distance(glm::vec3(0.0f, y, -5.0f + s)) > 0.0f);
  }
}

TEST_CASE("sphere_trace: a hit is refined to a fraction of the threshold and stays outside") {
  // The classic rule stops where the distance first falls below the threshold: at incidence
  // cos 0.6 (y = 0.8) that is 0.67 to 1.67 thresholds in front of the surface. The sign
  // change is bisected down to march_refine_fraction (1/32) of the threshold.
  shape = 0;
  for (const float eps : {1e-3f, 1e-2f}) {
    for (const float y : {0.0f, 0.3f, 0.8f, 0.95f, 0.999f}) {
      for (const float w : {1.0f, 1.6f}) {
        MarchSettings m = settings(w, 4096);
        m.epsilon = eps;
        float s = 0.0f;
        std::uint32_t steps = 0;
        CAPTURE(eps);
        CAPTURE(y);
        CAPTURE(w);
        REQUIRE(shape_trace(glm::vec3(0.0f, y, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f, m, {}, s, steps));
        CHECK(std::abs(s - sphere_t(y)) <= 0.05f * eps);
        CHECK(march_distance(glm::vec3(0.0f, y, -5.0f + s)) > 0.0f);  // never inside
      }
    }
  }
}

TEST_CASE("sphere_trace: the threshold compares the unscaled distance") {
  // step_scale 0.5 halves the steps only. The classic rule tested 0.5 * distance, so a ray
  // passing 1.5 thresholds from the sphere stopped there; now it does not even probe.
  shape = 0;
  MarchSettings m = settings(1.0f, 4096);
  m.epsilon = 1e-3f;
  m.step_scale = 0.5f;
  float s = 0.0f;
  std::uint32_t steps = 0;
  CHECK_FALSE(shape_trace(glm::vec3(0.0f, 1.0015f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f, m, {}, s, steps));
  REQUIRE(shape_trace(glm::vec3(0.0f, 0.8f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f, m, {}, s, steps));
  CHECK(std::abs(s - sphere_t(0.8f)) <= 0.05f * m.epsilon);
}

TEST_CASE("sphere_trace: probes and bisection stay within max_steps") {
  // Every budget from 1 on: at most max_steps evaluations; a hit (once a sign change is found,
  // its bisection possibly cut short) is never inside; an unconfirmed march is a miss.
  shape = 0;
  std::uint32_t first_hit = 0;
  for (std::uint32_t n = 1; n <= 40; ++n) {
    MarchSettings m = settings(1.0f, n);
    m.epsilon = 1e-3f;
    float s = 0.0f;
    std::uint32_t steps = 0;
    const bool hit = shape_trace(glm::vec3(0.0f, 0.8f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f, m, {}, s, steps);
    CAPTURE(n);
    CHECK(steps <= n);
    if (!hit) continue;
    if (first_hit == 0) first_hit = n;
    CHECK(march_distance(glm::vec3(0.0f, 0.8f, -5.0f + s)) > 0.0f);
    CHECK(s <= sphere_t(0.8f));
  }
  CHECK(first_hit > 0u);
}

TEST_CASE("sphere_trace: a march that starts inside an SDF reports where it leaves") {
  // As the closed forms do: the exit, bracketed and refined like an entry, reported from the
  // start's side (inside), so cull flags see a back-facing hit. Relaxation does not change it.
  shape = 0;
  for (float w : {1.0f, 1.6f}) {
    for (float z : {-0.5f, 0.0f, 0.9f}) {
      CAPTURE(w);
      CAPTURE(z);
      MarchSettings m = settings(w);
      m.epsilon = 1e-3f;
      float s = -1.0f;
      std::uint32_t steps = 0;
      REQUIRE(shape_trace(glm::vec3(0.0f, 0.0f, z), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f, m, {}, s, steps));
      const float exit = 1.0f - z;
      CHECK(s <= exit);
      CHECK(exit - s <= march_refine_fraction * m.epsilon + 1e-6f);
      CHECK(march_distance(glm::vec3(0.0f, 0.0f, z + s)) < 0.0f);  // the start's side
      CHECK(steps <= 16u);  // one plain step lands on the surface, then the refinement (seen 7)
    }
  }
  // The exit lies beyond the range: a miss, not a hit at the range's end.
  float s = 0.0f;
  std::uint32_t steps = 0;
  CHECK_FALSE(shape_trace(glm::vec3(0.0f, 0.0f, -0.5f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 1.0f, settings(), {}, s, steps));
}

TEST_CASE("sphere_trace: inside an estimate that is zero there or on the surface is a miss") {
  // No bound to march out on: no exit is claimed, and no hit at the start (the old rule's
  // wrong surface with an arbitrary normal). One evaluation decides it.
  shape = 2;
  float s = 0.0f;
  std::uint32_t steps = 0;
  CHECK_FALSE(shape_trace(glm::vec3(0.0f, 0.0f, -0.5f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f, settings(), {}, s, steps));
  CHECK(steps == 1u);
  // From outside the same estimate is hit as the exact sphere is.
  REQUIRE(shape_trace(glm::vec3(0.0f, 0.3f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f, settings(), {}, s, steps));
  CHECK(s == doctest::Approx(sphere_t(0.3f)).epsilon(1e-4));
  // A secondary ray that starts exactly on its surface does not hit it there.
  shape = 0;
  CHECK_FALSE(shape_trace(glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 0.0f, -1.0f), 0.0f, 10.0f, settings(), {}, s, steps));
  CHECK(steps == 1u);
}

TEST_CASE("over-relaxation does not tunnel through a thin plate") {
  shape = 1;
  const glm::vec3 dir = glm::normalize(glm::vec3(1.0f, 0.0f, 0.05f));  // shallow: long relaxed steps
  const float expected = (-0.01f + 2.0f) / dir.z;                     // from z = -2 to z = -0.01
  for (float w : {1.0f, 1.2f, 1.6f, 1.9f}) {
    float s = 0.0f;
    std::uint32_t steps = 0;
    REQUIRE(shape_trace(glm::vec3(0.0f, 0.0f, -2.0f), dir, 0.0f, 100.0f, settings(w, 4096), {}, s, steps));
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
    float s = 0.0f;
    std::uint32_t steps = 0;
    CAPTURE(w);
    REQUIRE(shape_trace(glm::vec3(0.0f, 0.0f, -2.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 2.0f, settings(w), {}, s, steps));
    CHECK(s == doctest::Approx(1.99f).epsilon(1e-5));
    // The relaxed step (past s_hi: not evaluated) or the start, the plain step's end (inside
    // by rounding), one probe a threshold back, 5 bisections to 1/32 threshold: seen 8.
    CHECK(steps <= 8u);
  }
  // Beyond the range it stays a miss, relaxed or not.
  float s = 0.0f;
  std::uint32_t steps = 0;
  CHECK_FALSE(shape_trace(glm::vec3(0.0f, 0.0f, -2.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 1.9f, settings(1.6f), {}, s, steps));
  shape = 0;
}

TEST_CASE("relaxed steps fall back once they stop overlapping and then march plainly") {
  // Head-on at the unit sphere from z = -5: r = 4, the relaxed step of 6.4 lands past the
  // sphere (z = 1.4, r = 0.4): 4 + 0.4 < 6.4, the spheres leave a gap, so the march goes back
  // to s = 4 (the plain step's end), exactly on the surface (distance 0: inside), so the hit
  // is refined there: one probe a threshold back (outside), 5 bisections.
  shape = 0;
  float s = 0.0f;
  std::uint32_t steps = 0;
  REQUIRE(shape_trace(glm::vec3(0.0f, 0.0f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f, settings(1.6f), {}, s, steps));
  CHECK(s == doctest::Approx(4.0f));
  CHECK(s < 4.0f);
  CHECK(steps == 3u + 6u);  // s = 0, s = 6.4 (rejected), s = 4; then the refinement
  // w = 1 never falls back: two evaluations, then the same refinement.
  REQUIRE(shape_trace(glm::vec3(0.0f, 0.0f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f, settings(1.0f), {}, s, steps));
  CHECK(steps == 2u + 6u);
}

TEST_CASE("tetrahedral normal of the sphere is radial") {
  shape = 0;
  const glm::vec3 n = shape_tetrahedral_normal(glm::normalize(glm::vec3(1.0f, 2.0f, -2.0f)), 1e-3f, {});
  CHECK(glm::dot(n, glm::normalize(glm::vec3(1.0f, 2.0f, -2.0f))) == doctest::Approx(1.0f).epsilon(1e-4));
  const glm::vec3 flat = shape_tetrahedral_normal(glm::vec3(5.0f), 0.0f, {});  // h = 0: zero gradient, fallback
  CHECK(std::isfinite(flat.x + flat.y + flat.z));
}

TEST_CASE("sphere_trace: probes of 4 distances cross an underestimating bound sooner, to the same point") {
  shape = 3;
  const glm::vec3 o(0.0f, 0.3f, -5.0f), u(0.0f, 0.0f, 1.0f);
  const float truth = 5.0f - std::sqrt(1.0f - 0.09f);
  std::uint32_t evaluations[3] = {};
  const float probes[3] = {0.0f, 2.0f, 4.0f};  // 0: a settings struct left zero, the default 2
  for (int i = 0; i < 3; ++i) {
    MarchSettings m = settings(1.0f, 4096);
    m.footprint = 1e-3f;  // a threshold of 1e-3 t, so probing starts well before the surface
    m.probe = probes[i];
    float s = 0.0f;
    REQUIRE(shape_trace(o, u, 0.0f, 10.0f, m, {}, s, evaluations[i]));
    CAPTURE(probes[i]);
    CHECK(s <= truth + 1e-6f);                                 // outside, as always
    CHECK(truth - s <= march_refine_fraction * 1e-3f * truth);  // within t/32 of the crossing
  }
  CHECK(evaluations[0] == evaluations[1]);
  CHECK(evaluations[2] < evaluations[1]);
  shape = 0;
}
