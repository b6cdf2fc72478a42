// The untyped base cannot be used to register a type outside the interface: its typed
// registrations are reachable only through Scene<Interface>.
// expect-gcc: is protected within this context
// expect-clang: is a protected member of
#include "scene_types.hpp"

auto ray(proceduray::Scene<demo::Interface>& scene) {
  proceduray::detail::SceneCore& base = scene;
  return base.add_ray<demo::Stray>("stray", {.miss = "m.rmiss"});
}
