// Tests for shaders/common/ray.glsl, compiled as C++: the slab clip without infinities.
#include <proceduray/shader/glsl_cpp.hpp>

namespace ray_test {
using namespace proceduray::glsl_cpp;
#include "common/ray.glsl"
}  // namespace ray_test

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

using namespace ray_test;

namespace {
const glm::vec3 lo(-1.0f), hi(1.0f);
}

TEST_CASE("ray_clip_aabb clips an oblique ray to the box") {
  float t0 = 0.0f, t1 = 1.0e30f;
  REQUIRE(ray_clip_aabb(glm::vec3(-3.0f, 0.0f, 0.0f), glm::vec3(1.0f, 0.0f, 0.0f), lo, hi, t0, t1));
  CHECK(t0 == doctest::Approx(2.0f));
  CHECK(t1 == doctest::Approx(4.0f));
}

TEST_CASE("ray_clip_aabb handles zero and negative zero direction components") {
  float t0 = 0.0f, t1 = 1.0e30f;
  REQUIRE(ray_clip_aabb(glm::vec3(0.5f, -0.5f, -3.0f), glm::vec3(0.0f, -0.0f, 2.0f), lo, hi, t0, t1));
  CHECK(t0 == doctest::Approx(1.0f));
  CHECK(t1 == doctest::Approx(2.0f));
  t0 = 0.0f, t1 = 1.0e30f;  // outside the x slab and parallel to it: never inside
  CHECK_FALSE(ray_clip_aabb(glm::vec3(1.5f, 0.0f, -3.0f), glm::vec3(0.0f, 0.0f, 1.0f), lo, hi, t0, t1));
  t0 = 0.0f, t1 = 1.0e30f;  // on the slab plane x = 1 and parallel to it: inside
  CHECK(ray_clip_aabb(glm::vec3(1.0f, 0.0f, -3.0f), glm::vec3(-0.0f, 0.0f, 1.0f), lo, hi, t0, t1));
}

TEST_CASE("ray_clip_aabb treats denormal components as parallel and stays finite") {
  const float denormal = std::numeric_limits<float>::denorm_min();
  float t0 = 0.0f, t1 = 1.0e30f;
  REQUIRE(ray_clip_aabb(glm::vec3(0.0f, 0.0f, -3.0f), glm::vec3(denormal, -denormal, 1.0f), lo, hi, t0, t1));
  CHECK(std::isfinite(t0));
  CHECK(std::isfinite(t1));
  CHECK(t0 == doctest::Approx(2.0f));
  t0 = 0.0f, t1 = 1.0e30f;  // a zero direction: inside for all t, or outside for all t
  CHECK(ray_clip_aabb(glm::vec3(0.0f), glm::vec3(0.0f), lo, hi, t0, t1));
  CHECK(t1 == 1.0e30f);
  CHECK_FALSE(ray_clip_aabb(glm::vec3(2.0f), glm::vec3(0.0f), lo, hi, t0, t1));
}

TEST_CASE("ray_clip_aabb respects the incoming t range") {
  float t0 = 5.0f, t1 = 1.0e30f;  // the box lies before t_min
  CHECK_FALSE(ray_clip_aabb(glm::vec3(-3.0f, 0.0f, 0.0f), glm::vec3(1.0f, 0.0f, 0.0f), lo, hi, t0, t1));
  t0 = 0.0f, t1 = 2.5f;  // origin outside, range ends inside the box
  REQUIRE(ray_clip_aabb(glm::vec3(-3.0f, 0.0f, 0.0f), glm::vec3(1.0f, 0.0f, 0.0f), lo, hi, t0, t1));
  CHECK(t1 == 2.5f);
  CHECK(t_in_range(2.5f, 0.0f, 2.5f));
  CHECK_FALSE(t_in_range(2.6f, 0.0f, 2.5f));
}

TEST_CASE("safe_normalize returns the fallback for zero") {
  const glm::vec3 n = safe_normalize(glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
  CHECK(n.y == 1.0f);
  CHECK(safe_normalize(glm::vec3(0.0f, 0.0f, 3.0f), glm::vec3(1.0f)).z == doctest::Approx(1.0f));
}
