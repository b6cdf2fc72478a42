// A ray's payload must come from the shader layer: a struct without PROCEDURAY_STRUCT is no payload.
// expect-gcc: PayloadData<Payload>
// expect-gcc: [with Payload = demo::Colour]
// expect-clang: because 'demo::Colour' does not satisfy 'PayloadData'
// expect-clang: because 'demo::Colour' does not satisfy 'RegisteredStruct'
#include <proceduray/scene/scene.hpp>

namespace demo {
struct Colour {
  float rgb[3];
};

auto ray(proceduray::Scene& scene) { return scene.add_ray<Colour>("radiance", {.miss = "sky.rmiss"}); }
}  // namespace demo
