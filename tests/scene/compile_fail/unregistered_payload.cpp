// A ray's payload must come from the shader layer: a struct without PROCEDURAY_STRUCT is no payload.
// expect: Payload, RootArguments and Attributes take structs registered with PROCEDURAY_STRUCT
// expect-gcc: Colour
#include <proceduray/scene/scene.hpp>

namespace demo {
struct Colour {
  float rgb[3];
};

using Interface = proceduray::ShaderInterface<proceduray::Payload<Colour>, proceduray::RootComponent<>,
                                              proceduray::RootArguments<>, proceduray::Attributes<>>;
auto ray(proceduray::Scene<Interface>& scene) { return scene.add_ray<Colour>("radiance", {.miss = "sky.rmiss"}); }
}  // namespace demo
