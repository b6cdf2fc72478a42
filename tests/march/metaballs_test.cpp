// march/metaballs.hpp: the metaball block's checks and the box that holds the blob at every time.
#include <proceduray/march/metaballs.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using namespace proceduray;

TEST_CASE("metaballs bounds hold every source's sphere at every time, and no more") {
  const Metaballs blob = make_metaballs({metaball({0.0f, 0.0f, 0.0f}, 0.5f, {0.3f, 0.0f, 0.0f}, glm::vec3(1.3f)),
                                         metaball({1.0f, 0.5f, 0.0f}, 0.25f, {0.0f, -0.2f, 0.1f}, glm::vec3(0.7f))},
                                        0.25f);
  const Aabb box = metaballs_bounds(blob);
  CHECK(box.min.x == doctest::Approx(-0.8f));  // centre 0 - amplitude 0.3 - radius 0.5
  CHECK(box.max.x == doctest::Approx(1.25f));  // 1 + 0.25
  CHECK(box.max.y == doctest::Approx(0.95f));  // 0.5 + 0.2 + 0.25
  CHECK(box.min.z == doctest::Approx(-0.5f));
  // Every point the field can be positive at, over time, lies inside.
  for (int k = 0; k < 400; ++k) {
    const float t = 0.05f * static_cast<float>(k);
    for (std::uint32_t i = 0; i < blob.count; ++i) {
      const glm::vec3 c = metaball_centre_at(blob.ball[i], t);
      const float r = blob.ball[i].radius;
      CHECK(glm::all(glm::lessThanEqual(box.min, c - glm::vec3(r) + 1e-5f)));
      CHECK(glm::all(glm::greaterThanEqual(box.max, c + glm::vec3(r) - 1e-5f)));
    }
  }
}

TEST_CASE("metaballs bad input: none, over the limit, radius 0, NaN, threshold outside (0, 1)") {
  CHECK_THROWS_WITH_AS(make_metaballs(std::vector<Metaball>{}, 0.25f), doctest::Contains("make_metaballs: 0 metaballs"),
                       UsageError);
  const std::vector<Metaball> nine(max_metaballs + 1, metaball(glm::vec3(0.0f), 0.5f));
  CHECK_THROWS_WITH_AS(make_metaballs(nine, 0.25f), doctest::Contains("9 metaballs, over the limit of 8"), UsageError);
  CHECK_THROWS_WITH_AS(make_metaballs({metaball(glm::vec3(0.0f), 0.0f)}, 0.25f),
                       doctest::Contains("metaball 0 has radius 0.000000; a source needs a positive radius"), UsageError);
  CHECK_THROWS_WITH_AS(make_metaballs({metaball(glm::vec3(0.0f), 0.5f), metaball(glm::vec3(NAN), 0.5f)}, 0.25f),
                       doctest::Contains("metaball 1 has a non-finite"), UsageError);
  CHECK_THROWS_WITH_AS(make_metaballs({metaball(glm::vec3(0.0f), 0.5f)}, 1.0f),
                       doctest::Contains("threshold 1.000000 is outside (0, 1)"), UsageError);
  CHECK_THROWS_AS(make_metaballs({metaball(glm::vec3(0.0f), 0.5f)}, 0.0f), UsageError);
  CHECK_THROWS_WITH_AS(metaballs_bounds(Metaballs{}), doctest::Contains("metaballs_bounds: the block has 0 sources"),
                       UsageError);
  CHECK(make_metaballs(std::vector<Metaball>(max_metaballs, metaball(glm::vec3(0.0f), 0.5f)), 0.25f).count == 8u);
}
