// A hit group's attributes larger than the 32 bytes every device guarantees do not compile.
// expect: static assertion failed: Scene::add_hit_group: the attribute type
// expect: at most 32 bytes
// expect-gcc: with Attributes = demo::WideHit
// expect-clang: 'proceduray::Entities::add_hit_group<demo::WideHit>' requested here
#include <proceduray/scene/scene.hpp>
#include <proceduray/shader/field_list.hpp>

namespace demo {
struct WideHit {
  glm::vec4 normal;
  glm::vec4 tangent;
  float t;
};
PROCEDURAY_STRUCT(WideHit, scalar, normal, tangent, t);

auto group(proceduray::Scene& scene) {
  return scene.add_hit_group<WideHit>("Wide", {.kind = proceduray::HitGroupKind::procedural,
                                               .closest_hit = "wide.rchit", .intersection = "wide.rint"});
}
}  // namespace demo
