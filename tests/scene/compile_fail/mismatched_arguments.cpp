// An entry whose arguments type differs from its local signature's root arguments type does not compile.
// expect-gcc: no matching function for call to
// expect-gcc: proceduray::detail::SceneCore::add_hit(
// expect-gcc: required for the satisfaction of
// expect-gcc: ArgumentsMatchSignature<Given, Arguments>
// expect-gcc: with Given = demo::TriangleArgs
// expect-gcc: Arguments = demo::ProceduralArgs]
// expect-clang: no matching member function for call to 'add_hit'
// expect-clang: because 'ArgumentsMatchSignature<demo::TriangleArgs, demo::ProceduralArgs>' evaluated to false
#include <proceduray/scene/scene.hpp>
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
struct TriangleArgs {
  glm::vec4 albedo;
};
PROCEDURAY_STRUCT(TriangleArgs, scalar, albedo);

using Interface = proceduray::ShaderInterface<proceduray::Payload<Radiance>, proceduray::RootComponent<>,
                                              proceduray::RootArguments<ProceduralArgs, TriangleArgs>, proceduray::Attributes<>>;
void bind(proceduray::Scene<Interface>& scene) {
  const auto radiance = scene.add_ray<Radiance>("Radiance", {.miss = "miss"});
  const auto group = scene.add_hit_group("Plane", {.closest_hit = "plane.rchit"});
  const auto plane = scene.add_geometry(
      "Plane", proceduray::GeometryDesc::triangles({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2}}));
  const auto signature = scene.add_local_signature<ProceduralArgs>("Procedural");
  scene.add_hit(radiance, group, signature, TriangleArgs{}, plane);
}
}  // namespace demo
