// Callable data is declared in GLSL from its registration: an unregistered type does not compile.
// expect: Payload, RootArguments and Attributes take structs registered with PROCEDURAY_STRUCT
// expect-gcc: Tint
#include <proceduray/scene/scene.hpp>

namespace demo {
struct Tint {
  float colour[3];
};

using Interface = proceduray::ShaderInterface<proceduray::Payload<Tint>, proceduray::RootComponent<>,
                                              proceduray::RootArguments<>, proceduray::Attributes<>>;
auto callable(proceduray::Scene<Interface>& scene) { return scene.add_callable<Tint>("tint", {.shader = "tint.rcall"}); }
}  // namespace demo
