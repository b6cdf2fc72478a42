// Tests for shaders/primitives/pacman.glsl, compiled as C++: interval CSG of sphere minus wedge.
#include <proceduray/shader/glsl_cpp.hpp>

namespace pacman_test {
using namespace proceduray::glsl_cpp;
#include "primitives/pacman.glsl"
}  // namespace pacman_test

#include <doctest/doctest.h>

#include <cmath>

using namespace pacman_test;

namespace {
const float a = 0.6f;  // the paper scene's mouth half-angle
}

TEST_CASE("pacman ray into the body hits the sphere") {
  float t;
  glm::vec3 n;
  REQUIRE(pacman_intersect(glm::vec3(0.0f, 0.0f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), a, 0.0f, 1.0e30f, t, n));
  CHECK(t == doctest::Approx(4.0f));
  CHECK(n.z == doctest::Approx(-1.0f));
}

TEST_CASE("pacman ray into the mouth hits the jaw face behind the removed wedge") {
  float t;
  glm::vec3 n;
  // At height y = 0.1 the wedge spans z > 0.1 / tan(a): the ray passes the sphere's front
  // (removed) and hits the upper jaw's inner face, whose outward normal is (0, -cos a, sin a).
  REQUIRE(pacman_intersect(glm::vec3(0.0f, 0.1f, 5.0f), glm::vec3(0.0f, 0.0f, -1.0f), a, 0.0f, 1.0e30f, t, n));
  CHECK(t == doctest::Approx(5.0f - 0.1f / std::tan(a)));
  CHECK(n.y == doctest::Approx(-std::cos(a)));
  CHECK(n.z == doctest::Approx(std::sin(a)));
  CHECK(t > 4.0f);  // not the sphere's front
}

TEST_CASE("pacman ray across the open mouth misses") {
  float t;
  glm::vec3 n;
  CHECK_FALSE(pacman_intersect(glm::vec3(5.0f, 0.0f, 0.5f), glm::vec3(-1.0f, 0.0f, 0.0f), a, 0.0f, 1.0e30f, t, n));
  // The same ray behind the hinge goes through the body.
  CHECK(pacman_intersect(glm::vec3(5.0f, 0.0f, -0.5f), glm::vec3(-1.0f, 0.0f, 0.0f), a, 0.0f, 1.0e30f, t, n));
}

TEST_CASE("pacman ray from inside the solid reports where it leaves") {
  float t;
  glm::vec3 n;
  REQUIRE(pacman_intersect(glm::vec3(0.0f, 0.0f, -0.5f), glm::vec3(0.0f, 0.0f, -1.0f), a, 0.0f, 1.0e30f, t, n));
  CHECK(t == doctest::Approx(0.5f));
  CHECK(n.z == doctest::Approx(-1.0f));
}

TEST_CASE("pacman honours the t range") {
  float t;
  glm::vec3 n;
  CHECK_FALSE(pacman_intersect(glm::vec3(0.0f, 0.0f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), a, 0.0f, 3.0f, t, n));
  REQUIRE(pacman_intersect(glm::vec3(0.0f, 0.0f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), a, 4.5f, 1.0e30f, t, n));
  CHECK(t == doctest::Approx(5.0f));  // where the body ends: the hinge, behind the open mouth
}

TEST_CASE("pacman degenerate rays give no NaN") {
  float t;
  glm::vec3 n;
  CHECK_FALSE(pacman_intersect(glm::vec3(0.0f, 0.0f, -5.0f), glm::vec3(0.0f), a, 0.0f, 1.0e30f, t, n));
  // Coplanar with the upper jaw face (c y = s z) and along the hinge's direction.
  const glm::vec3 on_face(2.0f, 0.5f * std::tan(a), 0.5f);
  const bool hit = pacman_intersect(on_face, glm::vec3(-1.0f, 0.0f, 0.0f), a, 0.0f, 1.0e30f, t, n);
  CHECK(std::isfinite(t));
  CHECK(std::isfinite(n.x + n.y + n.z));
  static_cast<void>(hit);
  // Along the hinge itself (the x axis): the wedge is closed, so the hinge line is removed too.
  CHECK_FALSE(pacman_intersect(glm::vec3(-3.0f, 0.0f, 0.0f), glm::vec3(1.0f, 0.0f, 0.0f), a, 0.0f, 1.0e30f, t, n));
  CHECK(std::isfinite(t));
  // Just below it the ray is in the body: a hit on the sphere with a unit normal.
  REQUIRE(pacman_intersect(glm::vec3(-3.0f, 0.0f, -1e-3f), glm::vec3(1.0f, 0.0f, 0.0f), a, 0.0f, 1.0e30f, t, n));
  CHECK(glm::length(n) == doctest::Approx(1.0f));
}
