// Tests for proceduray/shader/glsl_keywords.hpp.
#include <proceduray/shader/glsl_keywords.hpp>

#include <doctest/doctest.h>

#include <algorithm>

TEST_CASE("the reserved word list is sorted and free of duplicates") {
  const auto& words = proceduray::glsl_reserved_words;
  CHECK(std::is_sorted(words.begin(), words.end()));
  CHECK(std::adjacent_find(words.begin(), words.end()) == words.end());
}

TEST_CASE("keywords and reserved words are rejected") {
  static_assert(proceduray::is_glsl_reserved("sample"));
  CHECK(proceduray::is_glsl_reserved("input"));
  CHECK(proceduray::is_glsl_reserved("output"));
  CHECK(proceduray::is_glsl_reserved("filter"));
  CHECK(proceduray::is_glsl_reserved("vec3"));
  CHECK(proceduray::is_glsl_reserved("rayPayloadEXT"));
  CHECK(proceduray::is_glsl_reserved("gl_Position"));
  CHECK(proceduray::is_glsl_reserved("my__name"));
}

TEST_CASE("ordinary names are accepted") {
  CHECK_FALSE(proceduray::is_glsl_reserved("radius"));
  CHECK_FALSE(proceduray::is_glsl_reserved("samples"));
  CHECK_FALSE(proceduray::is_glsl_reserved("Input"));
  CHECK_FALSE(proceduray::is_glsl_reserved("center_gl_"));
}
