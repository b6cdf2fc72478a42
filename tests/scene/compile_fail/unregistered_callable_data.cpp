// Callable data is declared in GLSL from its registration: an unregistered type does not compile.
// expect: the callable data type (Data in the instantiation above) must be registered with PROCEDURAY_STRUCT
#include <proceduray/scene/scene.hpp>

namespace demo {
struct Tint {
  float colour[3];
};

auto callable(proceduray::Scene& scene) { return scene.add_callable<Tint>("tint", {.shader = "tint.rcall"}); }
}  // namespace demo
