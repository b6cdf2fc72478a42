#include "proceduray/scene/hit_group.hpp"

#include <doctest/doctest.h>

using namespace proceduray;

TEST_CASE("hit_group validate checks shaders against the kind") {
  CHECK_NOTHROW(validate(HitGroupDesc{.closest_hit = "c"}, "T", "op"));
  CHECK_NOTHROW(validate(HitGroupDesc{}, "Shadow", "op"));  // a triangles group may have no shader at all
  CHECK_NOTHROW(validate(HitGroupDesc{.kind = HitGroupKind::procedural, .intersection = "i"}, "P", "op"));
  CHECK_THROWS_WITH_AS(validate(HitGroupDesc{.any_hit = "a", .intersection = "i"}, "T", "op"),
                       doctest::Contains("op: triangle hit group \"T\" has intersection shader \"i\""), HitGroupKindError);
  CHECK_THROWS_WITH_AS(validate(HitGroupDesc{.kind = HitGroupKind::procedural, .closest_hit = "c"}, "P", "op"),
                       doctest::Contains("set .intersection"), HitGroupKindError);
  CHECK(std::string(to_string(HitGroupKind::procedural)) == "procedural");
}
