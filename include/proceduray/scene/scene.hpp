// A scene, declared from its interface: the report's four std::variant categories (Payload,
// RootComponent, RootArguments, Attributes; shader/categories.hpp) are its vocabulary. Its
// entities, the entries that bind them into shader-table records, the global signature and how
// deep rays nest; compile(scene) (compile.hpp) turns it into a Plan with no device.
//
//   using Interface = proceduray::ShaderInterface<
//       proceduray::Payload<RadiancePayload, ShadowPayload>, proceduray::RootComponent<SceneConstants>,
//       proceduray::RootArguments<Material>, proceduray::Attributes<BallHit>>;
//   proceduray::Scene<Interface> scene;
//   auto radiance = scene.add_ray<RadiancePayload>("radiance", {.miss = "sky.rmiss"});   // in Payload<...>
//   auto shadow   = scene.add_ray<ShadowPayload>("shadow", {.miss = "shadow.rmiss"});
//   auto ball     = scene.add_hit_group<BallHit>("ball", {.kind = proceduray::HitGroupKind::procedural,
//                                                        .closest_hit = "ball.rchit", .intersection = "ball.rint"});
//   auto occluder = scene.add_hit_group<BallHit>("ball_shadow", {.kind = proceduray::HitGroupKind::procedural,
//                                                               .intersection = "ball.rint"});
//   auto balls    = scene.add_geometry("balls", proceduray::GeometryDesc::procedural({box}, {left, right}));
//   auto material = scene.add_local_signature<Material>("material");               // in RootArguments<...>
//   auto sky      = scene.add_local_signature("sky", Interface::RootArgumentsSet(Material{}));  // the report's style
//   scene.add_raygen("camera.rgen");
//   scene.add_hit(radiance, ball, material, Material{red}, balls, 0);    // instance 0
//   scene.add_hit(radiance, ball, material, Material{blue}, balls, 1);   // instance 1
//   scene.add_hit(shadow, occluder, balls);                              // every instance, no data
//   scene.add_miss(radiance, material, Material{...});                   // optional miss root arguments
//   scene.set_global_signature({.bindings = {...}});   // binding types: RootComponent<...> alternatives
//   scene.set_max_recursion_depth(2);                                    // closest hits trace shadow rays
//   scene.set_outputs({proceduray::Output::t, proceduray::Output::normal});   // per-pixel images (outputs.hpp)
//
// A type outside its category does not compile, nor does an entry whose arguments type differs
// from its local signature's; the string-id overload checks it at run time (TypeMismatchError).
// The order entries are added in does not matter: compile() assigns every instance's SBT offset
// and every record's place. A hit group must match the geometry's kind (HitGroupKindError);
// every (ray, geometry, instance) needs an entry, instance-specific first, then geometry-wide,
// then the ray's default for the geometry's kind (set_default_hit), or compile() throws
// MissingEntryError. The maxima the pipeline needs (payload, attributes, root arguments) come
// from the alternatives the records use, not from every alternative listed.
#pragma once

#include <proceduray/config.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "proceduray/scene/constants.hpp"
#include "proceduray/scene/entities.hpp"
#include "proceduray/scene/entry.hpp"
#include "proceduray/scene/errors.hpp"
#include "proceduray/march/calibration.hpp"
#include "proceduray/scene/field.hpp"
#include "proceduray/scene/outputs.hpp"
#include "proceduray/shader/categories.hpp"

namespace proceduray {

namespace detail {

/// A scene's entities and entries, untyped: the base Scene<Interface> (below) registers typed
/// entities through. Not used on its own: its typed registrations are reachable only through Scene.
class SceneCore : public Entities {
 public:
  /// Adds a raygen record for `shader`, without root arguments.
  EntryId add_raygen(std::string shader) { return add_raygen_entry(std::move(shader), no_index, nullptr, 0); }
  /// Adds a raygen record for `shader` carrying `data` (type fixed by the local signature).
  template <RootArgumentsData Arguments, class Given>
    requires ArgumentsMatchSignature<Given, Arguments>
  EntryId add_raygen(std::string shader, LocalSignatureId<Arguments> signature, const Given& data) {
    return add_raygen_entry(std::move(shader), signature_index(signature, "Scene::add_raygen"), &data, sizeof(Arguments));
  }

  /// Gives the miss record of `ray` root arguments; rays without it get a record with none.
  template <class Payload, RootArgumentsData Arguments, class Given>
    requires ArgumentsMatchSignature<Given, Arguments>
  EntryId add_miss(RayId<Payload> ray, LocalSignatureId<Arguments> signature, const Given& data) {
    Entry e{.region = SbtRegionKind::miss, .ray = own(ray, "Scene::add_miss"),
            .local_signature = signature_index(signature, "Scene::add_miss")};
    return add_entry("Scene::add_miss", e, &data, sizeof(Arguments));
  }

  /// Gives the record of callable `callable` root arguments; callables without it get a record with none.
  template <class Data, RootArgumentsData Arguments, class Given>
    requires ArgumentsMatchSignature<Given, Arguments>
  EntryId add_callable_record(CallableId<Data> callable, LocalSignatureId<Arguments> signature, const Given& data) {
    Entry e{.region = SbtRegionKind::callable, .local_signature = signature_index(signature, "Scene::add_callable_record"),
            .shader = own(callable, "Scene::add_callable_record")};
    return add_entry("Scene::add_callable_record", e, &data, sizeof(Arguments));
  }

  /// Binds <ray, hit group> (no root arguments) to a geometry, or one instance of it.
  template <class Payload>
  EntryId add_hit(RayId<Payload> ray, HitGroupId group, GeometryId geometry, std::uint32_t instance = all_instances) {
    constexpr std::string_view op = "Scene::add_hit";
    Entry e{.ray = own(ray, op), .hit_group = own(group, op), .geometry = own(geometry, op), .instance = instance};
    return add_entry(op, e, nullptr, 0);
  }
  /// Binds <ray, hit group, local signature, arguments> to a geometry, or one instance of it.
  template <class Payload, RootArgumentsData Arguments, class Given>
    requires ArgumentsMatchSignature<Given, Arguments>
  EntryId add_hit(RayId<Payload> ray, HitGroupId group, LocalSignatureId<Arguments> signature, const Given& args,
                  GeometryId geometry, std::uint32_t instance = all_instances) {
    constexpr std::string_view op = "Scene::add_hit";
    Entry e{.ray = own(ray, op), .hit_group = own(group, op), .local_signature = signature_index(signature, op),
            .geometry = own(geometry, op), .instance = instance};
    return add_entry("Scene::add_hit", e, &args, sizeof(Arguments));
  }
  /// The same by string ids; throws UnknownIdError, or TypeMismatchError when Arguments is not the signature's type.
  template <RootArgumentsData Arguments>
  EntryId add_hit(std::string_view ray, std::string_view group, std::string_view signature, const Arguments& args,
                  std::string_view geometry, std::uint32_t instance = all_instances) {
    return add_hit(ray_id(ray), hit_group_id(group), local_signature_id<Arguments>(signature), args, geometry_id(geometry),
                   instance);
  }

  /// Declares the hit group `ray` uses on geometry of the group's kind that has no entry.
  template <class Payload>
  EntryId set_default_hit(RayId<Payload> ray, HitGroupId group) {
    Entry e{.ray = own(ray, "Scene::set_default_hit"), .hit_group = own(group, "Scene::set_default_hit"), .is_default = true};
    return add_entry("Scene::set_default_hit", e, nullptr, 0);
  }
  /// The same, with root arguments.
  template <class Payload, RootArgumentsData Arguments, class Given>
    requires ArgumentsMatchSignature<Given, Arguments>
  EntryId set_default_hit(RayId<Payload> ray, HitGroupId group, LocalSignatureId<Arguments> signature, const Given& args) {
    Entry e{.ray = own(ray, "Scene::set_default_hit"), .hit_group = own(group, "Scene::set_default_hit"),
            .local_signature = signature_index(signature, "Scene::set_default_hit"), .is_default = true};
    return add_entry("Scene::set_default_hit", e, &args, sizeof(Arguments));
  }

  /// Makes a registered global signature the one the pipeline uses; default: none.
  void set_global_signature(GlobalSignatureId id);
  /// Registers `desc` as `id` and makes it the one the pipeline uses.
  GlobalSignatureId set_global_signature(GlobalSignatureDesc desc, std::string id = "global");
  /// Declares the deepest traceRayEXT nesting the shaders do (1 = rays from raygen only).
  /// Undeclared, the renderer derives it from what each shader traces (scene/recursion.hpp); it
  /// refuses a declared depth below that, and needs one when shaders trace in a cycle (reflections).
  void set_max_recursion_depth(std::uint32_t depth);

  /// The global signature the pipeline uses; invalid when none was set.
  GlobalSignatureId pipeline_global_signature() const { return m_global_signature; }
  /// The declared recursion depth, if any.
  std::optional<std::uint32_t> max_recursion_depth() const { return m_max_recursion_depth; }
  /// Asks for per-pixel outputs besides colour (outputs.hpp): compile() gives each an image
  /// binding in set 0 after the global signature's, and every shader the helpers that write it.
  void set_outputs(OutputSet outputs) { m_outputs = outputs; }
  /// The outputs asked for (none by default).
  OutputSet outputs() const { return m_outputs; }
  /// Declares a constant every stage gets (constants.hpp); throws SceneError for a name that is no
  /// GLSL identifier or is reserved, DuplicateIdError for a name taken.
  void add_constant(std::string name, ConstantValue value);
  /// Declares `#define name 1` in every stage, for code a switch keeps out (constants.hpp); throws as add_constant.
  void add_define(std::string name);
  /// The constants and defines declared, in order.
  const std::vector<SceneConstant>& constants() const { return m_constants; }
  /// Every entry and its root arguments.
  const EntryList& entries() const { return m_entries; }
  /// The distance fields declared (add_distance_field, distance_field.hpp), in order.
  const std::vector<DistanceField>& fields() const { return m_fields; }
  /// Records a distance field whose object add_distance_field registered: compile() plans its
  /// intersection stage and settings. Checks the field (validate(DistanceField)) first.
  void add_field(DistanceField field) {
    validate(field, "add_distance_field");
    m_fields.push_back(std::move(field));
  }
  /// Asks compile() to give every distance field the cheapest setting of `table` that meets
  /// `budget` (march/calibration.hpp; default: what a 1080p picture cannot tell) and that the
  /// field accepts, for frames of width x height: the size the table was measured at, since
  /// errors in footprints grow with the resolution (compile() refuses another size). The pick
  /// is the field's starting knobs and Plan::fields()'s report.
  void set_error_budget(ErrorBudget budget, Calibration table, std::uint32_t width, std::uint32_t height) {
    validate(budget, "Scene::set_error_budget");
    m_budget = FieldBudget{budget, std::move(table), width, height};
  }
  /// The error budget of the fields, if one was set.
  const std::optional<FieldBudget>& error_budget() const { return m_budget; }
  /// Reserves room for `entries` entries and `data_bytes` of root arguments.
  void reserve_entries(std::size_t entries, std::size_t data_bytes) { m_entries.reserve(entries, data_bytes); }

 private:
  /// A signature the caller passed: checked even when default-constructed (invalid).
  std::uint32_t signature_index(LocalSignatureId<> id, std::string_view op) const {
    local_signatures().check_index(own(id, op), op);
    return id.index();
  }
  EntryId add_raygen_entry(std::string shader, std::uint32_t signature, const void* data, std::uint32_t size);
  EntryId add_entry(std::string_view op, const Entry& e, const void* data, std::uint32_t size);
  void check_hit(std::string_view op, const Entry& e) const;
  void declare_constant(std::string_view op, SceneConstant c);

  EntryList m_entries;
  GlobalSignatureId m_global_signature;
  std::optional<std::uint32_t> m_max_recursion_depth;
  OutputSet m_outputs;
  std::vector<SceneConstant> m_constants;
  std::vector<DistanceField> m_fields;
  std::optional<FieldBudget> m_budget;
};

}  // namespace detail

/// A scene declared from its interface (a ShaderInterface of the four categories, the report's
/// shader compatibility layer): every payload, attribute, root arguments and callable data type is
/// an alternative of its category, or the registration does not compile. compile() declares the
/// interface's alternatives in every stage and derives the sizes from those the records use.
template <class Interface>
class Scene : public detail::SceneCore {
  static_assert(detail::is_shader_interface<Interface>,
                "Scene<Interface>: Interface must be a proceduray::ShaderInterface<Payload<...>, RootComponent<...>, "
                "RootArguments<...>, Attributes<...>> listing the scene's GPU-visible types");

 public:
  using Categories = Interface;  ///< the ShaderInterface the scene's types come from

  Scene() { set_vocabulary(Interface::types); }

  /// Registers a ray type whose payload is an alternative of Interface's Payload<...> (its
  /// rayPayloadEXT type); throws DuplicateIdError, SceneError (see Entities).
  template <class Payload>
  RayId<Payload> add_ray(std::string id, RayDesc desc) {
    static_assert(Interface::Payloads::template contains<Payload>,
                  "Scene::add_ray: the payload type (Payload in the instantiation above) is not an alternative "
                  "of the interface's Payload<...> category; add it there");
    return Entities::add_ray<Payload>(std::move(id), std::move(desc));
  }

  /// Registers a hit group whose intersection reports an alternative of Interface's Attributes<...>
  /// (void: none, or triangles' barycentrics); throws HitGroupKindError, DuplicateIdError.
  template <class Attributes = void>
  HitGroupId add_hit_group(std::string id, HitGroupDesc desc) {
    static_assert(std::is_void_v<Attributes> || Interface::AttributesSet::template contains<Attributes>,
                  "Scene::add_hit_group: the attribute type (Attributes in the instantiation above) is not an "
                  "alternative of the interface's Attributes<...> category; add it there");
    return Entities::add_hit_group<Attributes>(std::move(id), std::move(desc));
  }

  /// Registers a local signature whose records carry an alternative of Interface's RootArguments<...>.
  template <class Arguments>
  LocalSignatureId<Arguments> add_local_signature(std::string id) {
    static_assert(Interface::RootArgumentsSet::template contains<Arguments>,
                  "Scene::add_local_signature: the root arguments type (Arguments in the instantiation above) is not "
                  "an alternative of the interface's RootArguments<...> category; add it there");
    return Entities::add_local_signature<Arguments>(std::move(id));
  }
  /// The report's style: the root arguments type is the alternative `type` holds.
  LocalSignatureId<> add_local_signature(std::string id, const typename Interface::RootArgumentsSet& type) {
    return std::visit(
        [&]<class Arguments>(const Arguments&) { return LocalSignatureId<>(add_local_signature<Arguments>(std::move(id))); },
        static_cast<const typename Interface::RootArgumentsSet::Base&>(type));
  }

  /// Registers a callable shader whose data is an alternative of Interface's Payload<...> (it
  /// travels like a payload); throws DuplicateIdError, SceneError for no shader.
  template <class Data>
  CallableId<Data> add_callable(std::string id, CallableDesc desc) {
    static_assert(Interface::Payloads::template contains<Data>,
                  "Scene::add_callable: the callable data type (Data in the instantiation above) is not an "
                  "alternative of the interface's Payload<...> category; add it there");
    return Entities::add_callable<Data>(std::move(id), std::move(desc));
  }
};
}  // namespace proceduray

#include "proceduray/scene/scene-inl.hpp"  // the bodies (config.hpp)
