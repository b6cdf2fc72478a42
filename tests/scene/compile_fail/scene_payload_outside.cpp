// A ray whose payload is not an alternative of the interface's Payload<...> does not compile.
// expect: Scene::add_ray: the payload type (Payload in the instantiation above) is not an alternative of the interface's Payload<...> category
// expect: Stray
#include "scene_types.hpp"

auto ray(proceduray::Scene<demo::Interface>& scene) { return scene.add_ray<demo::Stray>("stray", {.miss = "m.rmiss"}); }
