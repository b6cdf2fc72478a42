// Strong ids for scene entities: an index into the scene's registry, typed by entity kind
// and, for rays, local signatures and callables, by the data type they carry.
//
//   proceduray::RayId<RayPayload> radiance = scene.add_ray<RayPayload>("Radiance", {.miss = "miss"});
//   proceduray::RayId<> any_ray = radiance;          // typed ids convert to untyped ones
//   proceduray::LocalSignatureId<Arguments> sig = scene.add_local_signature<Arguments>("Procedural");
//
// Ids are never raw integers: a GeometryId does not convert to a HitGroupId. An id also carries
// the serial of the scene that issued it, so another scene (or a renderer built from another
// scene) refuses it instead of reading whatever entity has the same index.
#pragma once

#include <compare>
#include <concepts>
#include <cstdint>
#include <type_traits>

namespace proceduray {

/// Tags naming the entity kind of an Id.
struct RayTag {};
struct HitGroupTag {};
struct GeometryTag {};
struct GlobalSignatureTag {};
struct LocalSignatureTag {};
struct EntryTag {};
struct CallableTag {};

/// A typed index into a scene registry; default-constructed ids are invalid.
template <class Tag, class Data = void>
class Id {
 public:
  static constexpr std::uint32_t invalid_index = 0xFFFF'FFFFu;  ///< index of a default-constructed id

  constexpr Id() = default;
  /// Wraps a registry index of scene `scene` (0: any scene, unchecked); only the scene should call this.
  constexpr explicit Id(std::uint32_t index, std::uint32_t scene = 0) : m_index(index), m_scene(scene) {}
  /// A typed id converts to the untyped id of the same kind.
  template <class Other>
    requires(std::is_void_v<Data> && !std::is_void_v<Other>)
  constexpr Id(Id<Tag, Other> other) : m_index(other.index()), m_scene(other.scene()) {}

  /// Position in the registry, which is also the order of registration.
  constexpr std::uint32_t index() const { return m_index; }
  /// Serial of the scene that issued the id (0: made by hand, not checked).
  constexpr std::uint32_t scene() const { return m_scene; }
  /// False for a default-constructed id.
  constexpr bool valid() const { return m_index != invalid_index; }

  /// Ids compare by index (an id the scene issued equals one a plan rebuilt from the index).
  friend constexpr bool operator==(Id a, Id b) { return a.m_index == b.m_index; }
  friend constexpr auto operator<=>(Id a, Id b) { return a.m_index <=> b.m_index; }

 private:
  std::uint32_t m_index = invalid_index;
  std::uint32_t m_scene = 0;
};

/// A ray type; Payload is its payload type (void: untyped).
template <class Payload = void>
using RayId = Id<RayTag, Payload>;
/// A hit group.
using HitGroupId = Id<HitGroupTag>;
/// A geometry (one geometry of a BLAS, with its instances).
using GeometryId = Id<GeometryTag>;
/// A global signature (descriptor set layouts + push constants).
using GlobalSignatureId = Id<GlobalSignatureTag>;
/// A local signature; Arguments is its root arguments type (void: untyped).
template <class Arguments = void>
using LocalSignatureId = Id<LocalSignatureTag, Arguments>;
/// A callable shader; Data is the type it is called with (void: untyped).
template <class Data = void>
using CallableId = Id<CallableTag, Data>;
/// A shader-table entry, in the order entries were added.
using EntryId = Id<EntryTag>;

}  // namespace proceduray
