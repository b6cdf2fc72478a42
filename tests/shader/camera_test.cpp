#include <proceduray/shader/camera.hpp>

#include <doctest/doctest.h>

using namespace proceduray;

TEST_CASE("camera look_at projects its target to the image centre") {
  const Camera c = look_at({0, 2, 6}, {0, 0.5f, 0}, 45.0f, 200, 100);
  const glm::ivec2 centre = project(c, {0, 0.5f, 0}, 200, 100);
  CHECK(centre.x == 100);
  CHECK(centre.y == 50);
  CHECK(glm::length(glm::vec3(c.forward)) == doctest::Approx(1.0f));
  // Aspect 2: the right vector is twice the up vector's length.
  CHECK(glm::length(glm::vec3(c.right)) == doctest::Approx(2.0f * glm::length(glm::vec3(c.up))));
  CHECK(c.pixel_angle == doctest::Approx(2.0f * std::tan(glm::radians(22.5f)) / 100.0f));
}

TEST_CASE("camera project puts points right of the target to the right and above it up") {
  const Camera c = look_at({0, 0, 5}, {0, 0, 0}, 60.0f, 64, 64);
  CHECK(project(c, {1, 0, 0}, 64, 64).x > 32);
  CHECK(project(c, {0, 1, 0}, 64, 64).y < 32);
}

TEST_CASE("camera look_at rejects degenerate cameras") {
  CHECK_THROWS_WITH_AS(look_at({0, 0, 0}, {0, 0, 0}, 45.0f, 8, 8), doctest::Contains("degenerate"), UsageError);
  CHECK_THROWS_AS(look_at({0, 5, 0}, {0, 0, 0}, 45.0f, 8, 8), UsageError);  // looking straight down
  CHECK_THROWS_AS(look_at({0, 0, 5}, {0, 0, 0}, 0.0f, 8, 8), UsageError);
  CHECK_THROWS_AS(look_at({0, 0, 5}, {0, 0, 0}, 45.0f, 0, 8), UsageError);
}
