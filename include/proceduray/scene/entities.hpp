// The entities of a scene: rays, hit groups, geometry, layers, callables, global and local
// signatures, each registered by string id and returned as a strong typed id. Scene (scene.hpp)
// is an Entities plus the entries that bind them; use it through Scene.
//
//   proceduray::Scene<DocInterface> scene;   // types: registered with PROCEDURAY_STRUCT, in the interface
//   auto radiance = scene.add_ray<RayPayload>("Radiance", {.miss = "miss.rmiss"});
//   auto shadow   = scene.add_ray<ShadowPayload>("Shadow", {.miss = "shadow.rmiss"});
//   auto pacman   = scene.add_hit_group<Attributes>("Pacman", {.kind = proceduray::HitGroupKind::procedural,
//                                                   .closest_hit = "pacman.rchit", .intersection = "pacman.rint"});
//   auto geometry = scene.add_geometry("Pacman", proceduray::GeometryDesc::procedural({{}}, transforms));
//   auto sig      = scene.add_local_signature<ProceduralArgs>("Procedural");
//   scene.add_layer("casts_shadow");                            // named bits of instance masks
//   auto tint     = scene.add_callable<TintCall>("tint", {.shader = "tint.rcall"});
//   const proceduray::HitGroup* maybe = scene.find_hit_group("Pacman");   // nullptr if absent
//   auto again = scene.ray_id<RayPayload>("Radiance");   // throws: unknown id, wrong payload type
//
// Registration order is the index order: rays' order is their SBT ray index and miss index.
// Geometry goes into BLASes (Scene::blases()): its own, or the one named by GeometryDesc::blas.
#pragma once

#include <proceduray/config.hpp>

#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <typeindex>
#include <typeinfo>
#include <utility>
#include <vector>

#include "proceduray/scene/blas.hpp"
#include "proceduray/scene/callable.hpp"
#include "proceduray/scene/errors.hpp"
#include "proceduray/scene/geometry.hpp"
#include "proceduray/scene/global_signature.hpp"
#include "proceduray/scene/glsl_names.hpp"
#include "proceduray/scene/hit_group.hpp"
#include "proceduray/scene/ids.hpp"
#include "proceduray/scene/layers.hpp"
#include "proceduray/scene/local_signature.hpp"
#include "proceduray/scene/ray.hpp"
#include "proceduray/scene/registry.hpp"
#include "proceduray/scene/shader_data.hpp"

namespace proceduray {

/// The most bytes a ray payload may have. Vulkan sets no limit, but a payload lives on every
/// nested ray's stack (and NVIDIA keeps it in registers where it can): past a few KiB it is cheaper
/// to keep the data in a storage buffer indexed by gl_LaunchIDEXT and carry an index.
inline constexpr std::uint32_t max_payload_size = 4096;

namespace detail {
PROCEDURAY_DECL std::uint32_t next_scene_serial();

template <class A>
constexpr const TypeOps* attribute_glsl_of() {
  if constexpr (std::is_void_v<A>) return nullptr;
  else return &type_ops<A>;
}
}  // namespace detail

/// Every registered entity of a scene (Scene adds the entries that bind them).
class Entities {
 public:
  // Out of line so that a program compiles a scene's members' construction and destruction once.
  Entities();
  ~Entities();
  Entities(const Entities&);
  Entities(Entities&&) noexcept;
  Entities& operator=(const Entities&);
  Entities& operator=(Entities&&) noexcept;

  /// Registers a geometry and puts it in its BLAS; throws InvalidGeometryError, DuplicateIdError.
  GeometryId add_geometry(std::string id, GeometryDesc desc);

  /// Adds a named layer (a bit of instance masks and cull masks) and returns its bit;
  /// throws DuplicateIdError, or SceneError past eight layers.
  std::uint8_t add_layer(std::string name);
  /// The union of the named layers' bits; throws UnknownIdError naming the known layers.
  std::uint8_t layer_mask(std::initializer_list<std::string_view> names) const {
    return m_layers.mask(names, "Scene::layer_mask");
  }
  /// The scene's layers, bit order.
  const Layers& layers() const { return m_layers; }

  /// Registers a global signature; throws SceneError for bad bindings, DuplicateIdError.
  GlobalSignatureId add_global_signature(std::string id, GlobalSignatureDesc desc);

  /// The ray registered as `id`, or nullptr.
  const Ray* find_ray(std::string_view id) const { return m_rays.find(id); }
  /// The hit group registered as `id`, or nullptr.
  const HitGroup* find_hit_group(std::string_view id) const { return m_hit_groups.find(id); }
  /// The geometry registered as `id`, or nullptr.
  const Geometry* find_geometry(std::string_view id) const { return m_geometries.find(id); }
  /// The global signature registered as `id`, or nullptr.
  const GlobalSignature* find_global_signature(std::string_view id) const { return m_global_signatures.find(id); }
  /// The local signature registered as `id`, or nullptr.
  const LocalSignature* find_local_signature(std::string_view id) const { return m_local_signatures.find(id); }

  /// The ray of `id`; throws UnknownIdError (nearest ids) or, for a typed lookup, TypeMismatchError.
  template <class Payload = void>
  RayId<Payload> ray_id(std::string_view id) const {
    const std::uint32_t index = m_rays.index_of(id, "Scene::ray_id");
    if constexpr (!std::is_void_v<Payload>) {
      check_type(m_rays.entities()[index].payload_type, typeid(Payload), "Scene::ray_id", "ray", id, "payload");
    }
    return RayId<Payload>(index, m_serial);
  }
  /// The hit group of `id`; throws UnknownIdError.
  HitGroupId hit_group_id(std::string_view id) const {
    return HitGroupId(m_hit_groups.index_of(id, "Scene::hit_group_id"), m_serial);
  }
  /// The geometry of `id`; throws UnknownIdError.
  GeometryId geometry_id(std::string_view id) const {
    return GeometryId(m_geometries.index_of(id, "Scene::geometry_id"), m_serial);
  }
  /// The global signature of `id`; throws UnknownIdError.
  GlobalSignatureId global_signature_id(std::string_view id) const {
    return GlobalSignatureId(m_global_signatures.index_of(id, "Scene::global_signature_id"), m_serial);
  }
  /// The local signature of `id`; throws UnknownIdError or, for a typed lookup, TypeMismatchError.
  template <class Arguments = void>
  LocalSignatureId<Arguments> local_signature_id(std::string_view id) const {
    const std::uint32_t index = m_local_signatures.index_of(id, "Scene::local_signature_id");
    if constexpr (!std::is_void_v<Arguments>) {
      check_type(m_local_signatures.entities()[index].arguments_type, typeid(Arguments), "Scene::local_signature_id",
                 "local signature", id, "root arguments");
    }
    return LocalSignatureId<Arguments>(index, m_serial);
  }

  /// The callable of `id`; throws UnknownIdError or, for a typed lookup, TypeMismatchError.
  template <class Data = void>
  CallableId<Data> callable_id(std::string_view id) const {
    const std::uint32_t index = m_callables.index_of(id, "Scene::callable_id");
    if constexpr (!std::is_void_v<Data>) {
      check_type(m_callables.entities()[index].data_type, typeid(Data), "Scene::callable_id", "callable", id, "data");
    }
    return CallableId<Data>(index, m_serial);
  }
  /// The callable of an id; throws UnknownIdError.
  const Callable& callable(CallableId<> id) const { return m_callables.at(own(id, "Scene::callable"), "Scene::callable"); }

  /// The ray of an id; throws UnknownIdError for an id this scene did not issue.
  const Ray& ray(RayId<> id) const { return m_rays.at(own(id, "Scene::ray"), "Scene::ray"); }
  /// The ray registered as `id`; throws UnknownIdError.
  const Ray& ray(std::string_view id) const { return m_rays.at(id, "Scene::ray"); }
  /// The hit group of an id; throws UnknownIdError.
  const HitGroup& hit_group(HitGroupId id) const { return m_hit_groups.at(own(id, "Scene::hit_group"), "Scene::hit_group"); }
  /// The hit group registered as `id`; throws UnknownIdError.
  const HitGroup& hit_group(std::string_view id) const { return m_hit_groups.at(id, "Scene::hit_group"); }
  /// The geometry of an id; throws UnknownIdError.
  const Geometry& geometry(GeometryId id) const { return m_geometries.at(own(id, "Scene::geometry"), "Scene::geometry"); }
  /// The geometry registered as `id`; throws UnknownIdError.
  const Geometry& geometry(std::string_view id) const { return m_geometries.at(id, "Scene::geometry"); }
  /// The global signature of an id; throws UnknownIdError.
  const GlobalSignature& global_signature(GlobalSignatureId id) const {
    return m_global_signatures.at(own(id, "Scene::global_signature"), "Scene::global_signature");
  }
  /// The local signature of an id; throws UnknownIdError.
  const LocalSignature& local_signature(LocalSignatureId<> id) const {
    return m_local_signatures.at(own(id, "Scene::local_signature"), "Scene::local_signature");
  }
  /// The BLAS a geometry lives in; throws UnknownIdError.
  const Blas& blas_of(GeometryId id) const { return m_blases.all()[geometry(id).blas]; }

  /// All rays in ray-index order.
  const Registry<Ray>& rays() const { return m_rays; }
  /// All hit groups in registration order.
  const Registry<HitGroup>& hit_groups() const { return m_hit_groups; }
  /// All geometries in registration order.
  const Registry<Geometry>& geometries() const { return m_geometries; }
  /// All callables in callable-index order.
  const Registry<Callable>& callables() const { return m_callables; }
  /// All global signatures.
  const Registry<GlobalSignature>& global_signatures() const { return m_global_signatures; }
  /// All local signatures.
  const Registry<LocalSignature>& local_signatures() const { return m_local_signatures; }
  /// All BLASes in creation order (the order of their first geometry).
  std::span<const Blas> blases() const { return m_blases.all(); }
  /// The shared BLAS called `name`, or nullptr.
  const Blas* find_shared_blas(std::string_view name) const { return m_blases.find_shared(name); }
  /// TLAS instances over all BLASes.
  std::uint64_t instance_count() const { return m_blases.instance_count(); }

  /// The serial ids of this scene carry (a copy of a scene keeps it: the copy accepts the ids).
  std::uint32_t serial() const { return m_serial; }
  /// `id`'s index, after checking that this scene issued it; throws UnknownIdError naming `op`.
  template <class Tag, class Data>
  std::uint32_t own(Id<Tag, Data> id, std::string_view op) const {
    if (id.scene() != 0 && id.scene() != m_serial) {
      throw UnknownIdError(std::string(op) + ": the id (index " + std::to_string(id.index()) + ") was issued by scene #" +
                           std::to_string(id.scene()) + ", not by this one (#" + std::to_string(m_serial) +
                           "); use an id this scene returned (or look it up by name here)");
    }
    return id.index();
  }
  /// Every name the scene's rays, layers and callables would declare in GLSL. Global signatures'
  /// names are not here: only the one the pipeline uses is declared, and compile() checks it.
  std::vector<GlslName> glsl_names() const;
  /// What a global signature declares: its named bindings and push constant block.
  static std::vector<GlslName> signature_glsl_names(const GlobalSignatureDesc& desc);

  /// Reserves room for `count` geometries (and their BLASes).
  void reserve_geometries(std::size_t count);

  /// The GLSL types of the scene's interface (ShaderInterface::types: payloads, root components,
  /// root arguments, attributes, in that order): what compile() declares in every stage.
  std::span<const TypeOps* const> vocabulary() const { return m_vocabulary; }


 protected:
  /// Scene<Interface> sets its interface's types once, when constructed.
  void set_vocabulary(std::span<const TypeOps* const> types) { m_vocabulary = types; }

  // Typed registration: Scene<Interface> (scene.hpp) calls these after checking each type's
  // category, so no type reaches the scene outside its interface.

  /// Registers a ray type with payload type Payload; throws DuplicateIdError.
  /// Throws SceneError for conflicting flags, cull mask 0, a payload over max_payload_size, or an id
  /// that is no valid GLSL name; DuplicateIdError for an id taken, also after GLSL mangling.
  template <PayloadData Payload>
  RayId<Payload> add_ray(std::string id, RayDesc desc) {
    constexpr std::string_view op = "Scene::add_ray";
    m_rays.check_new(op, id);
    validate_ray(desc, id, op);
    if (sizeof(Payload) > max_payload_size) {
      throw SceneError(std::string(op) + ": ray \"" + id + "\" has a payload of " + std::to_string(sizeof(Payload)) +
                       " bytes, over the " + std::to_string(max_payload_size) + " the library allows (a payload lives "
                       "on every nested ray's stack); keep the data in a storage buffer and carry an index");
    }
    check_glsl_names(op, glsl_names(), ray_glsl_names(id));
    return RayId<Payload>(m_rays.add(op, std::move(id), Ray{std::move(desc), sizeof(Payload), typeid(Payload), &type_ops<Payload>}),
                          m_serial);
  }

  /// Registers a hit group; Attributes is what its intersection shader reports (void: none,
  /// or the built-in barycentrics for triangles). Throws HitGroupKindError, DuplicateIdError.
  template <class Attributes = void>
  HitGroupId add_hit_group(std::string id, HitGroupDesc desc) {
    static_assert(std::is_void_v<Attributes> || AttributeData<Attributes>,
                  "Scene::add_hit_group: the attribute type (Attributes in the instantiation above) must be registered with "
                  "PROCEDURAY_STRUCT and at most 32 bytes (maxRayHitAttributeSize that Vulkan guarantees); "
                  "register it, or shrink it and pass the rest through the payload");
    validate(desc, id, "Scene::add_hit_group");
    std::uint32_t size = 0;
    if constexpr (!std::is_void_v<Attributes>) {
      if (desc.kind == HitGroupKind::triangles) {
        throw HitGroupKindError(std::string("Scene::add_hit_group: triangle hit group \"") + id + "\" declares an attribute type (" +
                                std::to_string(sizeof(Attributes)) + " bytes); triangles report the built-in "
                                "barycentrics: call add_hit_group<void>");
      }
      size = sizeof(Attributes);
    } else if (desc.kind == HitGroupKind::triangles) {
      size = triangle_attribute_size;
    }
    return HitGroupId(m_hit_groups.add("Scene::add_hit_group", std::move(id),
                                       HitGroup{std::move(desc), size, typeid(Attributes), detail::attribute_glsl_of<Attributes>()}),
                      m_serial);
  }

  /// Registers a callable shader called with Data; throws DuplicateIdError, SceneError for no shader.
  template <class Data>
  CallableId<Data> add_callable(std::string id, CallableDesc desc) {
    static_assert(PayloadData<Data>,
                  "Scene::add_callable: the callable data type (Data in the instantiation above) must be registered "
                  "with PROCEDURAY_STRUCT: it is declared in GLSL as callableDataEXT from that registration");
    if (desc.shader.empty()) {
      throw SceneError("Scene::add_callable: callable " + detail::quote_id(id) + " has no shader; set .shader");
    }
    m_callables.check_new("Scene::add_callable", id);
    check_glsl_names("Scene::add_callable", glsl_names(), callable_glsl_names(id));
    return CallableId<Data>(m_callables.add("Scene::add_callable", std::move(id),
                                            Callable{std::move(desc), sizeof(Data), typeid(Data), &type_ops<Data>}),
                            m_serial);
  }

  /// Registers a local signature whose records carry Arguments; throws DuplicateIdError.
  template <RootArgumentsData Arguments>
  LocalSignatureId<Arguments> add_local_signature(std::string id) {
    return LocalSignatureId<Arguments>(m_local_signatures.add("Scene::add_local_signature", std::move(id),
                                                         LocalSignature{sizeof(Arguments), typeid(Arguments), &type_ops<Arguments>}),
                                       m_serial);
  }

 private:
  static void check_type(std::type_index have, std::type_index want, std::string_view op, std::string_view kind,
                         std::string_view id, std::string_view what);

  static void validate_ray(const RayDesc& desc, std::string_view id, std::string_view op);
  /// Throws TypeMismatchError unless `type` (nullptr: none) is one of the interface's types.
  void check_root_component(const TypeOps* type, const std::string& what) const;

  std::uint32_t m_serial = detail::next_scene_serial();
  Registry<Ray> m_rays{"ray"};
  Registry<HitGroup> m_hit_groups{"hit group"};
  Registry<Geometry> m_geometries{"geometry"};
  Registry<GlobalSignature> m_global_signatures{"global signature"};
  Registry<LocalSignature> m_local_signatures{"local signature"};
  Registry<Callable> m_callables{"callable"};
  Layers m_layers;
  BlasSet m_blases;
  std::span<const TypeOps* const> m_vocabulary;  // static storage (ShaderInterface::types)
};

}  // namespace proceduray

#include "proceduray/scene/entities-inl.hpp"  // the bodies (config.hpp)
