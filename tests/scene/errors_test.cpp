#include "proceduray/scene/errors.hpp"
#include "proceduray/scene/scene.hpp"

#include <doctest/doctest.h>

#include <stdexcept>
#include <string>
#include <type_traits>

using namespace proceduray;
using TestSceneInterface = proceduray::ShaderInterface<proceduray::Payload<>, proceduray::RootComponent<>, proceduray::RootArguments<>,
                                   proceduray::Attributes<>>;
using TestScene = proceduray::Scene<TestSceneInterface>;

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

// TestScene errors are usage errors (bugs in the calling code); a device limit is a runtime error, not a SceneError.
static_assert(std::is_base_of_v<UsageError, SceneError> && std::is_base_of_v<std::logic_error, SceneError>);
static_assert(std::is_base_of_v<SceneError, UnknownIdError> && std::is_base_of_v<SceneError, MissingEntryError>);
static_assert(std::is_base_of_v<std::runtime_error, DeviceLimitError> && !std::is_base_of_v<SceneError, DeviceLimitError>);
static_assert(std::is_base_of_v<Error, SceneError> && std::is_base_of_v<Error, DeviceLimitError>);

TEST_CASE("errors a scene call's error is caught as SceneError, UsageError, std::logic_error and Error alike") {
  TestScene scene;
  scene.add_geometry("Pacman", GeometryDesc::procedural({{glm::vec3(-1.0f), glm::vec3(1.0f)}}));
  const Aabb inverted{glm::vec3(1.0f), glm::vec3(-1.0f)};
  auto bad_box = [&] { scene.add_geometry("Bad", GeometryDesc::procedural({inverted})); };
  CHECK_THROWS_WITH_AS(bad_box(), doctest::Contains("Scene::add_geometry: geometry \"Bad\" AABB 0 has min"),
                       InvalidGeometryError);
  CHECK_THROWS_WITH_AS(bad_box(), doctest::Contains("swap the corners"), SceneError);
  CHECK_THROWS_WITH_AS(bad_box(), doctest::Contains("swap the corners"), std::logic_error);
  std::string through_base;
  try {
    bad_box();
  } catch (const Error& e) {  // the common base reaches the same message
    through_base = e.what();
  }
  CHECK(through_base.find("geometry \"Bad\" AABB 0 has min") != std::string::npos);
  CHECK_THROWS_AS((void)scene.geometry_id("Pacmn"), UsageError);
}

TEST_CASE("errors a library call's message names the call, the id, the nearest ids and the fix") {
  TestScene scene;
  scene.add_geometry("Pacman", GeometryDesc::procedural({{glm::vec3(-1.0f), glm::vec3(1.0f)}}));
  scene.add_geometry("Plane", GeometryDesc::procedural({{glm::vec3(-2.0f), glm::vec3(2.0f)}}));
  CHECK_THROWS_WITH_AS(scene.geometry_id("Pacmn"),
                       "Scene::geometry_id: unknown geometry id \"Pacmn\"; nearest known ids: \"Pacman\", \"Plane\""
                       "; register it first or fix the spelling",
                       UnknownIdError);
}
