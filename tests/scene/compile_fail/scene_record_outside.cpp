// Root arguments that is not an alternative of RootArguments<...> does not compile.
// expect: Scene::add_local_signature: the root arguments type (Arguments in the instantiation above) is not an alternative of the interface's RootArguments<...> category
// expect: Stray
#include "scene_types.hpp"

auto signature(proceduray::Scene<demo::Interface>& scene) { return scene.add_local_signature<demo::Stray>("s"); }
