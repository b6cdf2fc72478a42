// A distance field as an object: the user gives the GLSL function, its box and its Lipschitz
// bound; the library writes the intersection shader from its own marchers (every method and
// knob of march/), the normal, the outputs and the evaluation counts. The user writes no
// marching code.
//
//   using Interface = proceduray::ShaderInterface<proceduray::Payload<Radiance>, proceduray::RootComponent<Frame>,
//                                                 proceduray::RootArguments<Material>,
//                                                 proceduray::Attributes<proceduray::FieldHit>>;   // what fields report
//   // gyroid.glsl, in a shader folder:  pr_real gyroid_distance(pr_real3 p) { ... }
//   proceduray::GeometryId g = proceduray::add_distance_field(scene, "gyroid",
//       {.glsl = "gyroid.glsl", .aabb = {glm::vec3(-1.0f), glm::vec3(1.0f)}, .lipschitz = 1.8f,
//        .closest_hit = {{radiance, "shade.rchit"}}},         // reads hit.normal (object space), hit.steps
//       material, {gold});
//   // a fractal: .iterations = 8 and `pr_real bulb_distance(pr_real3 p, uint iterations)`
//   // animated: .parameters = {proceduray::field_parameter(constants_slot, &Constants::time)} and
//   //           `pr_real bulb_distance(pr_real3 p, uint iterations, float time)`, read per frame
//
// The renderer then needs the view's pixel angle (Renderer::set_pixel_angle(camera.pixel_angle):
// footprint thresholds scale with it) and takes each field's knobs (Renderer::set_field_knobs(g,
// knobs), checked against field_capabilities).
//
// Registers the object as add_object<FieldHit> does (geometry "<id>", hit groups "<id>" and
// "<id>_<ray>"), with the generated intersection stage "<id>.field.rint" for every ray type.
// Every check comes first (the field's: validate(DistanceField); the object's: add_object's), so
// a throw leaves the scene as it was.
#pragma once

#include <proceduray/config.hpp>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "proceduray/scene/field.hpp"
#include "proceduray/scene/object.hpp"

namespace proceduray {

/// What a distance field is: its function, bounds and bound, instances and shaders.
struct DistanceFieldDesc {
  std::string glsl;              ///< the file holding the function, found in RendererOptions::shader_dirs
  std::string function;          ///< its name; empty: "<id>_distance"
  Aabb aabb;                     ///< local bounds; the surface lies inside
  float lipschitz = 0.0f;        ///< |f(p) - f(q)| <= L |p - q|: required (> 0) unless exact
  bool exact = false;            ///< an exact distance (L = 1)
  std::uint32_t iterations = 0;  ///< > 0: a fractal, f(p, iterations), with this default count (a knob)
  std::vector<FieldParameter> parameters;  ///< uniform or record members passed after p (and iterations): field_parameter
  std::optional<MarchKnobs> knobs;         ///< starting knobs (checked); none: field_capabilities' defaults
  std::string normal;                      ///< bool f(p[, iterations][, parameters], out n): exact where true
  std::vector<InstanceTransform> instances{identity_transform()};  ///< where it stands
  std::vector<RayShader> closest_hit;  ///< closest-hit shaders; a ray type not listed runs none
  std::vector<RayShader> any_hit;      ///< any-hit shaders; a ray type not listed runs none
};

namespace detail {

/// FieldHit is what every field's generated shader reports: the interface must list it.
template <class Interface>
inline constexpr bool reports_field_hits = Interface::AttributesSet::template contains<FieldHit>;

/// The field and the object add_distance_field registers for `desc`; checks the field, and that
/// its record parameters read `records` (the type of its hit records; null: it has none).
inline std::pair<DistanceField, ObjectDesc> field_object(const std::string& id, DistanceFieldDesc desc,
                                                         const TypeOps* records) {
  for (const FieldParameter& p : desc.parameters) {
    if (!p.record || p.block_type == records) continue;
    throw UsageError("add_distance_field: distance field \"" + id + "\" takes the parameter arguments." + p.member +
                     " of " + std::string(p.block_type->glsl_name) + " records, but its records are " +
                     (records == nullptr ? std::string("none") : std::string(records->glsl_name)) +
                     "; pass records of that type (a LocalSignatureId<" + std::string(p.block_type->glsl_name) +
                     ">) or make the parameter from their signature");
  }
  DistanceField f{id,          std::move(desc.glsl), std::move(desc.function), desc.aabb,
                  desc.lipschitz, desc.exact,         desc.iterations,          std::move(desc.parameters),
                  desc.knobs,   std::move(desc.normal)};
  validate(f, "add_distance_field");
  ObjectDesc object{.geometry = GeometryDesc::procedural({f.aabb}, std::move(desc.instances)),
                    .intersection = field_stage_name(f), .closest_hit = std::move(desc.closest_hit),
                    .any_hit = std::move(desc.any_hit)};
  return {std::move(f), std::move(object)};
}

}  // namespace detail

/// Registers a distance field whose hit records carry `records` (one for all instances, or one
/// per instance) under `signature`. FieldHit must be in the interface's Attributes<...> (else it
/// does not compile). Throws UsageError for the field (validate(DistanceField)), SceneError and
/// its subclasses for the object, before changing anything.
template <class Interface, RootArgumentsData Arguments>
GeometryId add_distance_field(Scene<Interface>& scene, std::string id, DistanceFieldDesc desc,
                              LocalSignatureId<Arguments> signature, std::type_identity_t<std::vector<Arguments>> records) {
  static_assert(detail::reports_field_hits<Interface>,
                "add_distance_field: proceduray::FieldHit (what a field's generated intersection reports) is not in "
                "the interface's Attributes<...>: list it there");
  auto [field, object] = detail::field_object(id, std::move(desc), &type_ops<Arguments>);
  const GeometryId geometry = add_object<FieldHit>(scene, std::move(id), std::move(object), signature, std::move(records));
  scene.add_field(std::move(field));  // checked above: cannot throw now
  return geometry;
}

/// Registers a distance field whose hit records carry no data.
template <class Interface>
GeometryId add_distance_field(Scene<Interface>& scene, std::string id, DistanceFieldDesc desc) {
  static_assert(detail::reports_field_hits<Interface>,
                "add_distance_field: proceduray::FieldHit (what a field's generated intersection reports) is not in "
                "the interface's Attributes<...>: list it there");
  auto [field, object] = detail::field_object(id, std::move(desc), nullptr);
  const GeometryId geometry = add_object<FieldHit>(scene, std::move(id), std::move(object));
  scene.add_field(std::move(field));
  return geometry;
}

}  // namespace proceduray
