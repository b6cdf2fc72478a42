// The compile-fail sources' scene, written correctly, compiles: the failures are the ones they name.
// expect-success
#include <proceduray/scene/compile.hpp>
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
struct Tint {
  float value;
};
PROCEDURAY_STRUCT(Tint, scalar, value);
struct TintArgs {
  float factor[4];
};
PROCEDURAY_STRUCT(TintArgs, scalar, factor);

using Interface = proceduray::ShaderInterface<proceduray::Payload<Radiance, Tint>, proceduray::RootComponent<>,
                                              proceduray::RootArguments<ProceduralArgs, TintArgs>, proceduray::Attributes<Hit>>;
proceduray::Plan bind(proceduray::Scene<Interface>& scene) {
  const auto radiance = scene.add_ray<Radiance>("Radiance", {.miss = "miss"});
  const auto group = scene.add_hit_group<Hit>("Sphere", {.kind = proceduray::HitGroupKind::procedural,
                                                         .closest_hit = "sphere.rchit", .intersection = "sphere.rint"});
  const auto sphere = scene.add_geometry("Sphere", proceduray::GeometryDesc::procedural({proceduray::Aabb{}}, {}));
  const auto signature = scene.add_local_signature<ProceduralArgs>("Procedural");
  const auto tint = scene.add_callable<Tint>("tint", {.shader = "tint.rcall"});
  const auto tint_args = scene.add_local_signature<TintArgs>("TintArgs");
  scene.add_raygen("raygen.rgen");
  scene.add_hit(radiance, group, signature, ProceduralArgs{}, sphere);
  scene.add_callable_record(tint, tint_args, TintArgs{});
  return proceduray::compile(scene);
}
}  // namespace demo
