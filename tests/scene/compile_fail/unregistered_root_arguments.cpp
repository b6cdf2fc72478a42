// Root arguments must come from the shader layer: a struct without PROCEDURAY_STRUCT is not root arguments.
// expect-gcc: required for the satisfaction of
// expect-gcc: RootArgumentsData<Arguments>
// expect-gcc: [with Arguments = demo::Material]
// expect-gcc: proceduray_fields(proceduray::detail::TypeTag<T>{})
// expect-clang: because 'demo::Material' does not satisfy 'RootArgumentsData'
// expect-clang: because 'demo::Material' does not satisfy 'RegisteredStruct'
#include <proceduray/scene/scene.hpp>

#include <cstdint>

namespace demo {
struct Material {
  float albedo[4];
  std::uint32_t instance;
};

auto signature(proceduray::Scene& scene) { return scene.add_local_signature<Material>("Material"); }
}  // namespace demo
