// march/sphere_set.hpp: the sphere block's checks and its box.
#include <proceduray/march/sphere_set.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using namespace proceduray;

TEST_CASE("sphere set bounds hold every sphere, scaled radii too") {
  const SphereSet set = make_sphere_set({{0.0f, 0.0f, 0.0f, 0.5f}, {1.0f, 0.5f, -0.25f, 0.25f}});
  CHECK(set.count == 2u);
  const Aabb box = sphere_set_bounds(set);
  CHECK(box.min == glm::vec3(-0.5f, -0.5f, -0.5f));
  CHECK(box.max == glm::vec3(1.25f, 0.75f, 0.5f));
  const Aabb half = sphere_set_bounds(set, 0.5f);
  CHECK(half.max.x == doctest::Approx(1.125f));
}

TEST_CASE("sphere set bad input: none, nine, radius 0, NaN") {
  CHECK_THROWS_WITH_AS(make_sphere_set(std::vector<glm::vec4>{}), doctest::Contains("make_sphere_set: 0 spheres"),
                       UsageError);
  CHECK_THROWS_WITH_AS(make_sphere_set(std::vector<glm::vec4>(9, glm::vec4(0, 0, 0, 1))),
                       doctest::Contains("9 spheres, over the limit of 8"), UsageError);
  CHECK_THROWS_WITH_AS(make_sphere_set({glm::vec4(0.0f)}), doctest::Contains("sphere 0 has radius 0.000000"), UsageError);
  CHECK_THROWS_WITH_AS(make_sphere_set({glm::vec4(0, 0, 0, 1), glm::vec4(NAN)}), doctest::Contains("sphere 1 is not finite"),
                       UsageError);
  CHECK_THROWS_WITH_AS(sphere_set_bounds(SphereSet{}), doctest::Contains("sphere_set_bounds: the set has 0 spheres"),
                       UsageError);
}
