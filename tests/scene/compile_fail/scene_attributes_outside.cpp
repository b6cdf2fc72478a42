// Hit attributes outside Attributes<...> do not compile, through add_object too.
// expect: Scene::add_hit_group: the attribute type (Attributes in the instantiation above) is not an alternative of the interface's Attributes<...> category
// expect: Stray
#include "scene_types.hpp"

auto object(proceduray::Scene<demo::Interface>& scene) {
  return proceduray::add_object<demo::Stray>(scene, "ball", {.geometry = proceduray::GeometryDesc::procedural({{}}),
                                                              .intersection = "ball.rint"});
}
