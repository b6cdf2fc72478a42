// Tests for proceduray/shader/layout_rule.hpp.
#include <proceduray/shader/layout_rule.hpp>

#include <doctest/doctest.h>

TEST_CASE("layout rules print as their GLSL qualifiers") {
  static_assert(proceduray::to_string(proceduray::LayoutRule::scalar) == "scalar");
  CHECK(proceduray::to_string(proceduray::LayoutRule::std430) == "std430");
  CHECK(proceduray::to_string(proceduray::LayoutRule::std140) == "std140");
}
