// expect-success
// The compile-fail sources' scene, written correctly, compiles: the failures are the ones they name.
#include <proceduray/scene/shader_table.hpp>
#include <proceduray/shader/field_list.hpp>

namespace demo {
struct Radiance {
  glm::vec4 color;
};
PROCEDURAY_STRUCT(Radiance, scalar, color);
struct ProceduralArgs {
  glm::vec4 albedo;
  std::uint32_t instance;
};
PROCEDURAY_STRUCT(ProceduralArgs, scalar, albedo, instance);
struct Hit {
  glm::vec3 normal;
  float t;
};
PROCEDURAY_STRUCT(Hit, scalar, normal, t);

void bind(proceduray::Scene& scene, proceduray::ShaderTable& table) {
  const auto radiance = scene.add_ray<Radiance>("Radiance", {.miss = "miss"});
  const auto group = scene.add_hit_group<Hit>("Sphere", {.kind = proceduray::HitGroupKind::procedural,
                                                         .closest_hit = "sphere.rchit", .intersection = "sphere.rint"});
  const auto sphere = scene.add_geometry("Sphere", proceduray::GeometryDesc::procedural({proceduray::Aabb{}}, {}));
  const auto signature = scene.add_local_signature<ProceduralArgs>("Procedural");
  table.add_hit(radiance, group, signature, ProceduralArgs{}, sphere);
}
}  // namespace demo
