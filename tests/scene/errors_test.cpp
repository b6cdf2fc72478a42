#include "proceduray/scene/errors.hpp"

#include <doctest/doctest.h>

#include <type_traits>

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
  CHECK_THROWS_AS(throw MissingEntryError("x"), UsageError);
  CHECK_THROWS_AS(throw SceneError("x"), Error);
  CHECK_THROWS_WITH(throw InvalidGeometryError("message"), "message");
}

TEST_CASE("errors of device limits are runtime errors and no scene errors") {
  // A scene that does not fit a device is not a bug in the calling code.
  CHECK_THROWS_AS(throw DeviceLimitError("x"), std::runtime_error);
  CHECK_THROWS_AS(throw DeviceLimitError("x"), Error);
  CHECK_THROWS_WITH(throw DeviceLimitError("limit"), "limit");
  static_assert(!std::is_base_of_v<std::logic_error, DeviceLimitError>);
  static_assert(!std::is_base_of_v<SceneError, DeviceLimitError>);
  static_assert(std::is_base_of_v<UsageError, SceneError>);
}
