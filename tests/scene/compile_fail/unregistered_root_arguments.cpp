// Root arguments must come from the shader layer: a struct without PROCEDURAY_STRUCT is not root arguments.
// expect: required for the satisfaction of
// expect: RootArgumentsData<Arguments>
// expect: [with Arguments = demo::Material]
// expect: proceduray_fields(proceduray::detail::TypeTag<T>{})
#include <proceduray/scene/scene.hpp>

#include <cstdint>

namespace demo {
struct Material {
  float albedo[4];
  std::uint32_t instance;
};

auto signature(proceduray::Scene& scene) { return scene.add_local_signature<Material>("Material"); }
}  // namespace demo
