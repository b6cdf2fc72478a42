// Tests for shaders/primitives/mandelbulb.glsl, compiled as C++: the power-8 estimate.
#include <proceduray/shader/glsl_cpp.hpp>

namespace mandelbulb_test {
using namespace proceduray::glsl_cpp;
#include "primitives/mandelbulb.glsl"
}  // namespace mandelbulb_test

#include "02_paper_scene/paper_types.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace mandelbulb_test;

TEST_CASE("mandelbulb estimate is zero inside and a lower bound outside") {
  CHECK(mandelbulb_distance(glm::vec3(0.0f), 8u) == 0.0f);
  // Find the set's last inside point on the x axis (about 0.87 at 8 iterations).
  float x_in = 0.0f;
  for (float x = 0.0f; x < 1.25f; x += 0.001f) {
    if (mandelbulb_distance(glm::vec3(x, 0.0f, 0.0f), 8u) == 0.0f) x_in = x;
  }
  CHECK(x_in > 0.8f);
  CHECK(x_in < 1.2f);
  for (float x = x_in + 0.01f; x < 3.0f; x += 0.05f) {
    const float d = mandelbulb_distance(glm::vec3(x, 0.0f, 0.0f), 8u);
    CAPTURE(x);
    CHECK(d > 0.0f);
    CHECK(d <= x - x_in);
  }
  // Escaping at once: 0.5 r ln r / 1.
  CHECK(mandelbulb_distance(glm::vec3(2.5f, 0.0f, 0.0f), 8u) == doctest::Approx(0.5f * 2.5f * std::log(2.5f)));
}

TEST_CASE("mandelbulb fits its AABB for every iteration count") {
  const float e = paper::mandelbulb_aabb.max.x;
  for (std::uint32_t n = 1; n <= 8; ++n) {
    for (float u = -1.0f; u <= 1.0f; u += 0.25f) {
      for (float v = -1.0f; v <= 1.0f; v += 0.25f) {
        CHECK(mandelbulb_distance(glm::vec3(e, u * e, v * e), n) > 0.0f);
        CHECK(mandelbulb_distance(glm::vec3(u * e, -e, v * e), n) > 0.0f);
        CHECK(mandelbulb_distance(glm::vec3(u * e, v * e, -e), n) > 0.0f);
      }
    }
  }
}

TEST_CASE("mandelbulb degenerate inputs give no NaN") {
  // On the pole axis (x = z = 0, where atan is undefined) and at the origin.
  for (float y = -1.2f; y <= 1.2f; y += 0.1f) CHECK(std::isfinite(mandelbulb_distance(glm::vec3(0.0f, y, 0.0f), 8u)));
  CHECK(mandelbulb_distance(glm::vec3(0.3f), 0u) == 0.0f);
  CHECK(std::isfinite(mandelbulb_distance(glm::vec3(0.0f, 0.0f, 1.1f), 30u)));
}

TEST_CASE("mandelbulb iterations animate down from the maximum") {
  CHECK(mandelbulb_animated_iterations(8u, 0.0f) == 8u);
  CHECK(mandelbulb_animated_iterations(8u, 0.5f) == 7u);
  CHECK(mandelbulb_animated_iterations(8u, 3.5f) == 1u);
  CHECK(mandelbulb_animated_iterations(8u, 4.0f) == 8u);
  CHECK(mandelbulb_animated_iterations(8u, -3.0f) == 8u);
  CHECK(mandelbulb_animated_iterations(0u, 2.0f) == 1u);
  CHECK(mandelbulb_animated_iterations(8u, 1.0e30f) >= 1u);
}
