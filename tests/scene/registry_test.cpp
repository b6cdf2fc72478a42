#include "proceduray/scene/registry.hpp"

#include <doctest/doctest.h>

#include <string>

using namespace proceduray;

TEST_CASE("registry keeps registration order and finds by id") {
  Registry<int> r("thing");
  CHECK(r.add("op", "b", 20) == 0);
  CHECK(r.add("op", "a", 10) == 1);
  CHECK(r.size() == 2);
  REQUIRE(r.find("a") != nullptr);
  CHECK(*r.find("a") == 10);
  CHECK(r.find("c") == nullptr);
  CHECK(r.at("b") == 20);
  CHECK(r.at(1u) == 10);
  CHECK(r.name(0) == "b");
  CHECK(r.entities()[1] == 10);
  CHECK(r.index_of("a") == 1);
}

TEST_CASE("registry errors name operation id and fix") {
  Registry<int> r("thing");
  r.add("Owner::add", "alpha", 1);
  r.add("Owner::add", "beta", 2);
  r.add("Owner::add", "alphabet", 3);
  CHECK_THROWS_WITH_AS(r.add("Owner::add", "beta", 4),
                       "Owner::add: duplicate thing id \"beta\" (already thing #1); choose a unique id", DuplicateIdError);
  CHECK_THROWS_WITH_AS(r.at("alpah", "Owner::get"),
                       "Owner::get: unknown thing id \"alpah\"; nearest known ids: \"alpha\", \"beta\", \"alphabet\"; "
                       "register it first or fix the spelling",
                       UnknownIdError);
  CHECK_THROWS_WITH_AS(r.add("Owner::add", "", 5), doctest::Contains("empty thing id"), SceneError);
  CHECK_THROWS_WITH_AS(r.at(3u, "Owner::get"), doctest::Contains("thing #3 is not registered (3 thing entities)"),
                       UnknownIdError);
  CHECK(r.size() == 3);
}

TEST_CASE("registry finds every id after its index grows") {
  Registry<int> r("thing");
  for (int i = 0; i < 5000; ++i) CHECK(r.add("op", "id" + std::to_string(i), i) == static_cast<std::uint32_t>(i));
  CHECK(r.size() == 5000);
  int found = 0;
  for (int i = 0; i < 5000; ++i) {
    const int* value = r.find("id" + std::to_string(i));
    if (value && *value == i) ++found;
  }
  CHECK(found == 5000);
  CHECK(r.find("id5000") == nullptr);
  CHECK(r.find("") == nullptr);
  CHECK_THROWS_WITH_AS(r.add("op", "id4321", 0), doctest::Contains("(already thing #4321)"), DuplicateIdError);
  Registry<int> reserved("thing");
  reserved.reserve(100);
  CHECK(reserved.find("x") == nullptr);
  reserved.add("op", "x", 7);
  CHECK(*reserved.find("x") == 7);
}
