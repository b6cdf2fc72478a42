// Tests for shaders/shading/phong.glsl, compiled as C++.
#include <proceduray/shader/glsl_cpp.hpp>

namespace phong_test {
using namespace proceduray::glsl_cpp;
#include "shading/phong.glsl"
}  // namespace phong_test

#include <doctest/doctest.h>

#include <cmath>

using namespace phong_test;

TEST_CASE("schlick fresnel runs from f0 at normal incidence to 1 at grazing") {
  CHECK(schlick_fresnel(0.04f, 1.0f) == doctest::Approx(0.04f));
  CHECK(schlick_fresnel(0.04f, 0.0f) == doctest::Approx(1.0f));
  CHECK(schlick_fresnel(0.04f, -0.5f) == doctest::Approx(1.0f));  // clamped, no pow of a negative
  CHECK(schlick_fresnel(0.04f, 1.5f) == doctest::Approx(0.04f));
}

TEST_CASE("phong is diffuse plus specular and zero facing away") {
  const glm::vec3 n(0, 1, 0), up(0, 1, 0);
  const glm::vec3 c = phong(glm::vec3(0.5f), n, up, up, glm::vec3(1.0f), 1.0f, 1.0f, 10.0f);
  CHECK(c.x == doctest::Approx(1.5f));
  const glm::vec3 dark = phong(glm::vec3(0.5f), n, -up, up, glm::vec3(1.0f), 1.0f, 1.0f, 10.0f);
  CHECK(dark.x == 0.0f);
  const glm::vec3 edge = phong(glm::vec3(0.5f), n, glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(1.0f), 1.0f, 1.0f, 0.0f);
  CHECK(std::isfinite(edge.x));
}
