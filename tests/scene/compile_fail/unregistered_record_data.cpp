// Record data must come from the shader layer: a struct without PROCEDURAY_STRUCT is not record data.
// expect: required for the satisfaction of
// expect: RecordData<Args>
// expect: [with Args = demo::Material]
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
