// Callable data travels like a payload: a type outside the interface's Payload<...> does not compile.
// expect: Scene::add_callable: the callable data type (Data in the instantiation above) is not an alternative of the interface's Payload<...> category
// expect: Stray
#include "scene_types.hpp"

auto callable(proceduray::Scene<demo::Interface>& scene) {
  return scene.add_callable<demo::Stray>("tint", {.shader = "tint.rcall"});
}
