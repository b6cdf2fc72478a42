// Tests for spheres.glsl's SphereList and sphere_set.glsl, compiled as C++: spheres as data,
// against closed-form distances, and the D3D12 sample's three unchanged bit for bit.
#include <proceduray/march/sphere_set.hpp>

#include <proceduray/shader/glsl_cpp.hpp>

namespace sphere_set_test {
using namespace proceduray::glsl_cpp;
using proceduray::SphereSet;  // the generated struct's C++ side
#include "primitives/sphere_set.glsl"
}  // namespace sphere_set_test

#include <doctest/doctest.h>

#include <cmath>
#include <random>

using namespace sphere_set_test;

TEST_CASE("sphere set: each sphere is hit at its closed-form distance, nearest first") {
  const SphereSet set = proceduray::make_sphere_set({{-2.0f, 0.0f, 0.0f, 0.5f}, {2.0f, 0.0f, 0.0f, 1.0f},
                                                      {2.0f, 0.0f, -3.0f, 1.0f}});
  const SphereList list = sphere_list(set);
  REQUIRE(list.count == 3u);
  float t = 0.0f;
  glm::vec3 n(0.0f);
  // Down -z through each centre from z = 5: entry at 5 - r; the sphere behind the second is hidden.
  REQUIRE(ray_spheres(glm::vec3(-2, 0, 5), glm::vec3(0, 0, -1), list, 1.0f, 0.0f, 100.0f, 0u, t, n));
  CHECK(t == doctest::Approx(4.5f));
  CHECK(n.z == doctest::Approx(1.0f));
  REQUIRE(ray_spheres(glm::vec3(2, 0, 5), glm::vec3(0, 0, -1), list, 1.0f, 0.0f, 100.0f, 0u, t, n));
  CHECK(t == doctest::Approx(4.0f));
  // radius_scale scales every radius.
  REQUIRE(ray_spheres(glm::vec3(2, 0, 5), glm::vec3(0, 0, -1), list, 0.5f, 0.0f, 100.0f, 0u, t, n));
  CHECK(t == doctest::Approx(4.5f));
  CHECK_FALSE(ray_spheres(glm::vec3(0, 0, 5), glm::vec3(0, 0, -1), list, 1.0f, 0.0f, 100.0f, 0u, t, n));
}

TEST_CASE("sphere set: the sample's list gives the sample's hits, bit for bit") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 o(u(rng) * 3.0f, u(rng) * 3.0f, 3.0f), target(u(rng) * 0.8f, u(rng) * 0.8f, u(rng) * 0.8f);
    const glm::vec3 d = target - o;
    float ta = 0.0f, tb = 0.0f;
    glm::vec3 na(0.0f), nb(0.0f);
    const bool a = ray_spheres(o, d, 0.9f, 0.0f, 100.0f, 0u, ta, na);
    const bool b = ray_spheres(o, d, spheres_sample(), 0.9f, 0.0f, 100.0f, 0u, tb, nb);
    CHECK(a == b);
    CHECK(ta == tb);
    CHECK(na == nb);
    hits += a;
  }
  CHECK(hits > 200);
}
