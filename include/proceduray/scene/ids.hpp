// Strong ids for scene entities: an index into the scene's registry, typed by entity kind
// and, for rays, local signatures and callables, by the data type they carry.
//
//   proceduray::RayId<RayPayload> radiance = scene.add_ray<RayPayload>("Radiance", {.miss = "miss"});
//   proceduray::RayId<> any_ray = radiance;          // typed ids convert to untyped ones
//   proceduray::LocalSignatureId<Arguments> sig = scene.add_local_signature<Arguments>("Procedural");
//
// Ids are never raw integers: a GeometryId does not convert to a HitGroupId.
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
  /// Wraps a registry index; only the registry should call this.
  constexpr explicit Id(std::uint32_t index) : m_index(index) {}
  /// A typed id converts to the untyped id of the same kind.
  template <class Other>
    requires(std::is_void_v<Data> && !std::is_void_v<Other>)
  constexpr Id(Id<Tag, Other> other) : m_index(other.index()) {}

  /// Position in the registry, which is also the order of registration.
  constexpr std::uint32_t index() const { return m_index; }
  /// False for a default-constructed id.
  constexpr bool valid() const { return m_index != invalid_index; }

  friend constexpr bool operator==(Id, Id) = default;
  friend constexpr auto operator<=>(Id, Id) = default;

 private:
  std::uint32_t m_index = invalid_index;
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
