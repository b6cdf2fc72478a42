// expect-success
// The Scene checks' scene with every type in its category compiles: the failures are the ones they name.
#include "scene_types.hpp"

auto build(proceduray::Scene<demo::Interface>& scene) {
  auto radiance = scene.add_ray<demo::Radiance>("radiance", {.miss = "m.rmiss"});
  auto material = scene.add_local_signature<demo::Material>("material");
  scene.add_local_signature("again", demo::Interface::RootArgumentsSet(demo::Material{}));
  return proceduray::add_object<demo::Hit>(scene, "ball", {.geometry = proceduray::GeometryDesc::procedural({{}}),
                                                            .intersection = "ball.rint",
                                                            .closest_hit = {{radiance, "ball.rchit"}}},
                                           material, {demo::Material{}});
}
