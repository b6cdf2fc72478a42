// Root arguments must come from the shader layer: a struct without PROCEDURAY_STRUCT is not root arguments.
// expect: Payload, RootArguments and Attributes take structs registered with PROCEDURAY_STRUCT
// expect-gcc: Material
#include <proceduray/scene/scene.hpp>

#include <cstdint>

namespace demo {
struct Material {
  float albedo[4];
  std::uint32_t instance;
};

using Interface = proceduray::ShaderInterface<proceduray::Payload<>, proceduray::RootComponent<>,
                                              proceduray::RootArguments<Material>, proceduray::Attributes<>>;
auto signature(proceduray::Scene<Interface>& scene) { return scene.add_local_signature<Material>("Material"); }
}  // namespace demo
