// A distance field in a scene whose Attributes<...> does not list FieldHit does not compile.
// expect: add_distance_field: proceduray::FieldHit (what a field's generated intersection reports) is not in the interface's Attributes<...>
#include "scene_types.hpp"

#include <proceduray/scene/distance_field.hpp>

auto field(proceduray::Scene<demo::Interface>& scene) {
  return proceduray::add_distance_field(scene, "ball", {.glsl = "ball.glsl", .exact = true});
}
