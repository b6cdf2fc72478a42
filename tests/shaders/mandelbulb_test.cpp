// Tests for shaders/primitives/mandelbulb.glsl, compiled as C++: the power-8 estimate, and its
// trigonometry-free z^8 against the angle form it replaced (map and ray truth, in double).
#include <proceduray/march/primitives_glsl.hpp>

#include "02_paper_scene/paper_types.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace {
using F = proceduray::glsl::mandelbulb<float>;
using D = proceduray::glsl::mandelbulb<double>;
float mandelbulb_distance(glm::vec3 p, std::uint32_t n) { return F::mandelbulb_distance(p, n); }
std::uint32_t mandelbulb_animated_iterations(std::uint32_t n, float time) { return F::mandelbulb_animated_iterations(n, time); }

/// The angle form (White and Nylander's, theta from +y, phi = atan(x, z)): the oracle.
glm::dvec3 angle_power8(glm::dvec3 z) {
  const double r = glm::length(z);
  if (r == 0.0) return glm::dvec3(0.0);
  const double theta = 8.0 * std::acos(std::clamp(z.y / r, -1.0, 1.0));
  const double phi = (z.x == 0.0 && z.z == 0.0) ? 0.0 : 8.0 * std::atan2(z.x, z.z);
  return std::pow(r, 8.0) * glm::dvec3(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi));
}

/// Inside after n steps of z <- power8(z) + p (|z| <= 2 throughout).
template <class Power>
bool inside(glm::dvec3 p, std::uint32_t n, Power power8) {
  glm::dvec3 z = p;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (glm::length(z) > 2.0) return false;
    z = power8(z) + p;
  }
  return glm::length(z) <= 2.0;
}

/// The first inside point along o + t d, t in [0, 4]: steps of 1e-3, then 60 bisections; -1: none.
template <class Power>
double first_inside(glm::dvec3 o, glm::dvec3 d, Power power8) {
  for (double t = 0.0; t < 4.0; t += 1.0e-3) {
    if (!inside(o + (t + 1.0e-3) * d, 8, power8)) continue;
    double lo = t, hi = t + 1.0e-3;
    for (int i = 0; i < 60; ++i) (inside(o + 0.5 * (lo + hi) * d, 8, power8) ? hi : lo) = 0.5 * (lo + hi);
    return hi;
  }
  return -1.0;
}
}  // namespace

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

TEST_CASE("mandelbulb trigonometry-free z^8 equals the angle form's, axis and origin included") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  double worst = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const glm::dvec3 z(u(rng), u(rng), u(rng));
    const double r8 = std::pow(glm::length(z), 8.0);
    worst = std::max(worst, glm::length(D::mandelbulb_power8(z) - angle_power8(z)) / r8);
  }
  CAPTURE(worst);
  CHECK(worst < 1.0e-12);  // relative to |z|^8: rounding only
  for (double y : {-1.1, -0.3, 0.0, 0.7}) {  // the y axis, where phi is undefined
    const glm::dvec3 a = D::mandelbulb_power8({0.0, y, 0.0}), b = angle_power8({0.0, y, 0.0});
    CHECK(glm::length(a - b) <= 1.0e-12 * std::max(1.0, std::pow(std::abs(y), 8.0)));
    CHECK(std::isfinite(a.x));
  }
  CHECK(F::mandelbulb_power8(glm::vec3(0.0f)) == glm::vec3(0.0f));
}

TEST_CASE("mandelbulb polynomial truth agrees with the angle form's to 1e-6 along rays, in double") {
  // Rays from a camera at 3 units through a 16 x 16 grid over the bulb: the first inside point
  // of the 8-iteration set by either map, found the same way.
  const glm::dvec3 eye(0.4, 0.9, 3.0);
  std::size_t hits = 0;
  double worst = 0.0;
  for (int j = 0; j < 16; ++j) {
    for (int i = 0; i < 16; ++i) {
      const glm::dvec3 target(-1.1 + 2.2 * (i + 0.5) / 16.0, -1.1 + 2.2 * (j + 0.5) / 16.0, 0.0);
      const glm::dvec3 d = glm::normalize(target - eye);
      const double a = first_inside(eye, d, [](glm::dvec3 z) { return D::mandelbulb_power8(z); });
      const double b = first_inside(eye, d, angle_power8);
      CAPTURE(i);
      CAPTURE(j);
      REQUIRE((a < 0.0) == (b < 0.0));
      if (a < 0.0) continue;
      ++hits;
      worst = std::max(worst, std::abs(a - b));
    }
  }
  CAPTURE(worst);
  CHECK(hits > 60);
  CHECK(worst <= 1.0e-6);
}
