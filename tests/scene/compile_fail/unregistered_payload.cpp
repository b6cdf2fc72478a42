// A ray's payload must come from the shader layer: a struct without PROCEDURAY_STRUCT is no payload.
// expect: PayloadData<Payload>
// expect: [with Payload = demo::Colour]
#include <proceduray/scene/scene.hpp>

namespace demo {
struct Colour {
  float rgb[3];
};

auto ray(proceduray::Scene& scene) { return scene.add_ray<Colour>("radiance", {.miss = "sky.rmiss"}); }
}  // namespace demo
