#include "proceduray/scene/errors.hpp"
#include "proceduray/scene/scene.hpp"

#include <doctest/doctest.h>

using namespace proceduray;

TEST_CASE("errors edit distance and nearest ids") {
  CHECK(detail::edit_distance("kitten", "sitting") == 3);
  CHECK(detail::edit_distance("", "abc") == 3);
  CHECK(detail::edit_distance("same", "same") == 0);
  const std::vector<std::string> known{"Radiance", "Shadow", "Radiance2", "Occlusion"};
  const auto nearest = detail::nearest_ids("Radiancee", known, 2);
  REQUIRE(nearest.size() == 2);
  CHECK(nearest[0] == "Radiance");
  CHECK(nearest[1] == "Radiance2");
  CHECK(detail::nearest_ids("x", std::vector<std::string>{}).empty());
  CHECK(detail::quote_list({"a", "b"}) == "\"a\", \"b\"");
  CHECK(detail::quote_list({}) == "(none)");
}

TEST_CASE("errors are logic errors") {
  CHECK_THROWS_AS(throw UnknownIdError("x"), std::logic_error);
  CHECK_THROWS_AS(throw MissingEntryError("x"), SceneError);
  CHECK_THROWS_AS(throw DeviceLimitError("x"), std::logic_error);
}

TEST_CASE("errors a library call's message names the call, the id, the nearest ids and the fix") {
  Scene scene;
  scene.add_geometry("Pacman", GeometryDesc::procedural({{glm::vec3(-1.0f), glm::vec3(1.0f)}}));
  scene.add_geometry("Plane", GeometryDesc::procedural({{glm::vec3(-2.0f), glm::vec3(2.0f)}}));
  CHECK_THROWS_WITH_AS(scene.geometry_id("Pacmn"),
                       "Scene::geometry_id: unknown geometry id \"Pacmn\"; nearest known ids: \"Pacman\", \"Plane\""
                       "; register it first or fix the spelling",
                       UnknownIdError);
}
