// march/cut_planes.hpp: planes as data, unit normals, and the block's checks.
#include <proceduray/march/cut_planes.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using namespace proceduray;

TEST_CASE("cut planes: cut_plane normalises, make_cut_planes keeps up to two in order") {
  const glm::vec4 a = cut_plane({0.0f, 3.0f, 4.0f}, 0.5f);
  CHECK(a.y == doctest::Approx(0.6f));
  CHECK(a.z == doctest::Approx(0.8f));
  CHECK(a.w == 0.5f);
  const CutPlanes two = make_cut_planes({a, cut_plane({-1.0f, 0.0f, 0.0f}, 0.4f)});
  CHECK(two.count == 2u);
  CHECK(two.plane[0] == a);
  CHECK(two.plane[1] == glm::vec4(-1.0f, 0.0f, 0.0f, 0.4f));
  CHECK(make_cut_planes(std::vector<glm::vec4>{}).count == 0u);  // no cut: the whole set
}

TEST_CASE("cut planes bad input: a zero normal, NaN, a normal not unit, three planes") {
  CHECK_THROWS_WITH_AS(cut_plane(glm::vec3(0.0f), 1.0f), doctest::Contains("cut_plane: normal (0.000000, 0.000000, 0.000000)"),
                       UsageError);
  CHECK_THROWS_AS(cut_plane({1.0f, 0.0f, 0.0f}, NAN), UsageError);
  CHECK_THROWS_WITH_AS(make_cut_planes({glm::vec4(0.0f, 2.0f, 0.0f, 0.0f)}),
                       doctest::Contains("plane 0 has a normal of length 2.000000"), UsageError);
  CHECK_THROWS_WITH_AS(make_cut_planes({glm::vec4(NAN)}), doctest::Contains("plane 0 is not finite"), UsageError);
  const glm::vec4 x = cut_plane({1.0f, 0.0f, 0.0f}, 0.0f);
  CHECK_THROWS_WITH_AS(make_cut_planes({x, x, x}), doctest::Contains("3 planes, over the limit of 2"), UsageError);
}
