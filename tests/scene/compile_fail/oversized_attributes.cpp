// A hit group's attributes larger than the 32 bytes every device guarantees do not compile.
// expect: Attributes: a hit attribute type is larger than 32 bytes
// expect-gcc: WideHit
#include <proceduray/scene/scene.hpp>
#include <proceduray/shader/field_list.hpp>

namespace demo {
struct WideHit {
  glm::vec4 normal;
  glm::vec4 tangent;
  float t;
};
PROCEDURAY_STRUCT(WideHit, scalar, normal, tangent, t);

using Interface = proceduray::ShaderInterface<proceduray::Payload<>, proceduray::RootComponent<>,
                                              proceduray::RootArguments<>, proceduray::Attributes<WideHit>>;
auto group(proceduray::Scene<Interface>& scene) {
  return scene.add_hit_group<WideHit>("Wide", {.kind = proceduray::HitGroupKind::procedural,
                                               .closest_hit = "wide.rchit", .intersection = "wide.rint"});
}
}  // namespace demo
