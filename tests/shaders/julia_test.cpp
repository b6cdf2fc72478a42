// Tests for shaders/primitives/julia.glsl, compiled as C++: the quaternion Julia estimate and the cut.
#include <proceduray/shader/glsl_cpp.hpp>

namespace julia_test {
using namespace proceduray::glsl_cpp;
#include "primitives/julia.glsl"
}  // namespace julia_test

#include "02_paper_scene/paper_types.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace julia_test;

namespace {
const glm::vec4 c0 = julia_animated_c(0.0f);
}

TEST_CASE("quaternion product matches known identities") {
  const glm::vec4 i(0, 1, 0, 0), j(0, 0, 1, 0), k(0, 0, 0, 1);
  CHECK(quat_mul(i, j) == k);
  CHECK(quat_mul(j, i) == -k);
  CHECK(quat_mul(i, i) == glm::vec4(-1, 0, 0, 0));
  const glm::vec4 q(0.3f, -1.2f, 0.7f, 2.0f);
  const glm::vec4 d = quat_square(q) - quat_mul(q, q);
  CHECK(glm::dot(d, d) < 1e-10f);
}

TEST_CASE("julia estimate is zero inside and a lower bound outside") {
  CHECK(c0 == glm::vec4(-0.2f, 0.6f, 0.2f, 0.2f));
  CHECK(julia_distance(glm::vec3(0.0f), c0, 10u) == 0.0f);  // the origin's orbit stays bounded
  // Outside the set, within the AABB: positive and at most the distance to the origin (inside).
  const glm::vec3 probes[] = {{1.5f, 0.0f, 0.0f}, {0.0f, -1.5f, 0.0f}, {1.0f, 1.0f, 1.0f}, {-1.5f, 1.5f, -1.5f}};
  for (const glm::vec3& p : probes) {
    const float d = julia_distance(p, c0, 10u);
    CAPTURE(p.x);
    CHECK(d > 0.0f);
    CHECK(d <= glm::length(p));
  }
}

TEST_CASE("julia set fits its AABB at every time") {
  for (float time = 0.0f; time < 10.0f; time += 0.7f) {
    const glm::vec4 c = julia_animated_c(time);
    for (float u = -1.0f; u <= 1.0f; u += 0.25f) {
      for (float v = -1.0f; v <= 1.0f; v += 0.25f) {
        // Every face of the box is outside the set.
        const float e = paper::julia_aabb.max.x;
        CHECK(julia_distance(glm::vec3(e, u * e, v * e), c, 10u) > 0.0f);
        CHECK(julia_distance(glm::vec3(u * e, -e, v * e), c, 10u) > 0.0f);
        CHECK(julia_distance(glm::vec3(u * e, v * e, e), c, 10u) > 0.0f);
      }
    }
  }
}

TEST_CASE("julia cut face is the plane exactly") {
  const glm::vec4 plane(0.0f, 0.0f, 1.0f, -0.05f);  // keeps z <= -0.05
  const glm::vec3 p(0.0f, 0.0f, 0.2f);              // inside the set, in front of the cut
  REQUIRE(julia_distance(p, c0, 10u) == 0.0f);
  CHECK(julia_cut_distance(p, c0, 10u, plane) == doctest::Approx(0.25f));
}

TEST_CASE("julia degenerate inputs give no NaN") {
  CHECK(julia_distance(glm::vec3(0.3f), c0, 0u) == 0.0f);  // no iterations: nothing escapes
  CHECK(julia_distance(glm::vec3(0.0f), glm::vec4(0.0f), 20u) == 0.0f);
  const float far = julia_distance(glm::vec3(1000.0f, 0.0f, 0.0f), c0, 10u);
  CHECK(std::isfinite(far));
  CHECK(far > 0.0f);
  CHECK(std::isfinite(julia_distance(glm::vec3(4.0f, 0.0f, 0.0f), glm::vec4(0.0f), 1u)));
}
