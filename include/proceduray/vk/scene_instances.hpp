// The instances of a compiled scene's TLAS and what their changes need: moves (DynamicTransform
// geometry) and visibility are a TLAS update; a mask change, an added or a removed instance is a
// TLAS build. SceneAcceleration owns one; take() tells it what to record before the next trace.
//
//   proceduray::vk::SceneInstances instances(plan, list);      // the plan's instances, in TLAS order
//   instances.set_visible(ball, 1, false, "my_call");           // hidden: mask 0, the TLAS updated
//   instances.set_transform(ball, 0, moved, "my_call");         // DynamicTransform geometry only
//   std::uint32_t i = instances.add(ball, moved, 0xFF, blas, "my_call");   // instance handle 2: a build
//   instances.remove(ball, 0, "my_call");                        // slot 0 and its custom index are free
//   std::uint32_t j = instances.add(ball, moved, 0xFF, blas, "my_call");   // slot 0 again: handle 0x01000000
//   instances.set_visible(ball, 0, false, "my_call");            // throws: handle 0 was removed
//   if (instances.take() == proceduray::vk::TlasWork::update) tlas.record_update(ctx, cmd, instances.list());
//
// An instance handle is its slot among the geometry's instances (GeometryDesc::instances first,
// so a declared instance's handle is its index) in the low 24 bits and the slot's generation in
// the high 8. Removing an instance frees its slot and its custom index (gl_InstanceCustomIndexEXT)
// for the next add and bumps the slot's generation, so a stale handle is refused instead of
// reaching the new instance (until the same slot has been reused 256 times). Adding and removing
// forever keeps memory flat. An instance's place in the TLAS list (gl_InstanceID) may change when
// another is removed. `op` names the user's call, for messages. `plan` must outlive it.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/error.hpp>
#include <proceduray/scene/plan.hpp>
#include <proceduray/vk/tlas.hpp>

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace proceduray::vk {

/// What the TLAS needs before the next trace.
enum class TlasWork { none, update, build };

/// A scene's TLAS instances, their masks and visibility, and the TLAS work their changes need.
class SceneInstances {
 public:
  /// `list`: the plan's instances in TLAS order (Plan::instances), each pointing at its BLAS.
  SceneInstances(const proceduray::Plan& plan, std::vector<Instance> list);

  /// Moves one instance of a DynamicTransform geometry: a TLAS update. Throws for a Static geometry,
  /// a bad or removed index, or a matrix that is not finite and affine.
  void set_transform(GeometryId geometry, std::uint32_t instance, const glm::mat4& object_to_world, std::string_view op);
  /// Moves every instance there is (instances(geometry) order, one matrix each): one TLAS update;
  /// nothing moves if one is bad.
  void set_transforms(GeometryId geometry, std::span<const glm::mat4> object_to_world, std::string_view op);
  /// Changes one instance's mask, any policy: a TLAS build. A hidden instance keeps it for when it is shown.
  void set_mask(GeometryId geometry, std::uint32_t instance, std::uint32_t mask, std::string_view op);
  /// Hides (mask 0: no ray's cull mask meets it) or shows one instance, any policy: a TLAS update,
  /// no rebuild. Setting what it already is does nothing.
  void set_visible(GeometryId geometry, std::uint32_t instance, bool visible, std::string_view op);
  /// Whether one instance is shown; throws for a bad or removed index.
  bool visible(GeometryId geometry, std::uint32_t instance, std::string_view op) const {
    return !m_hidden[tlas_index(geometry, instance, op)];
  }

  /// Adds an instance of the BLAS `geometry` lives in (every geometry of a shared BLAS gets it),
  /// using the BLAS's shared hit records, so no other instance's SBT offset changes: a TLAS build.
  /// `blas` is that BLAS's structure. Returns the new instance index. Throws UsageError when the
  /// BLAS has no shared records (every instance has entries of its own), InvalidGeometryError for
  /// a bad matrix or a mask over 0xFF.
  std::uint32_t add(GeometryId geometry, const glm::mat4& object_to_world, std::uint32_t mask,
                    const AccelerationStructure& blas, std::string_view op);
  /// Removes one instance: a TLAS build. Its slot and custom index go to the next add(); its handle
  /// is refused from now on (UsageError), also once the slot holds a new instance.
  void remove(GeometryId geometry, std::uint32_t instance, std::string_view op);
  /// The handles of the instances `geometry` has now, in slot order (removed ones left out).
  std::vector<std::uint32_t> instances(GeometryId geometry, std::string_view op) const;
  /// The TLAS list index (gl_InstanceID) of one instance; throws for a bad or removed index.
  std::uint32_t tlas_index(GeometryId geometry, std::uint32_t instance, std::string_view op) const;
  /// The custom index (gl_InstanceCustomIndexEXT) the next add() gives: a removed instance's, else
  /// one past every index so far.
  std::uint32_t next_custom_index() const noexcept { return m_free_custom.empty() ? m_next_custom : m_free_custom.back(); }
  /// One past the highest custom index given so far: per-instance storage buffers need this many
  /// elements. Adds that reuse removed instances' indices do not raise it.
  std::uint32_t custom_index_bound() const noexcept { return m_next_custom; }
  /// Slots of every geometry's instances ever needed at once, removed ones waiting for reuse included
  /// (what add/remove loops must keep flat).
  std::size_t slot_count() const noexcept;

  /// The instances as the TLAS takes them (hidden ones with mask 0).
  std::span<const Instance> list() const noexcept { return m_list; }
  /// A BLAS was refit: the TLAS holds its old bounds and needs an update.
  void blas_refit() noexcept { m_update = true; }
  /// BLAS `blas` (Plan::blases index) was rebuilt: its instances point at `structure`, the TLAS is built again.
  void blas_rebuilt(std::uint32_t blas, const AccelerationStructure& structure);
  /// What the changes since the last call need (a build covers an update), and forgets them.
  TlasWork take() noexcept {
    const TlasWork work = m_rebuild ? TlasWork::build : m_update ? TlasWork::update : TlasWork::none;
    m_update = m_rebuild = false;
    return work;
  }

 private:
  static constexpr std::uint32_t removed = 0xFFFF'FFFFu;
  static constexpr std::uint32_t slot_bits = 24;  // the rest of a handle is the slot's generation
  static constexpr std::uint32_t slot_mask = (1u << slot_bits) - 1;
  /// Which (BLAS, slot) a TLAS list entry is.
  struct Owner {
    std::uint32_t blas = 0;
    std::uint32_t slot = 0;
  };
  /// One instance slot of a BLAS: its TLAS index (`removed` while free) and generation.
  struct Slot {
    std::uint32_t tlas = removed;
    std::uint32_t generation = 0;  // 0..255
  };
  std::uint32_t handle(std::uint32_t slot, const Slot& s) const noexcept { return slot | s.generation << slot_bits; }
  void check_movable(GeometryId geometry, std::string_view operation) const;
  /// The TLAS index of (geometry, instance) of a movable geometry; throws InvalidGeometryError or UsageError.
  std::uint32_t movable_instance(GeometryId geometry, std::uint32_t instance, std::string_view op) const;
  /// InvalidGeometryError naming `op`, the geometry and the instance for a non-finite or singular matrix.
  void check_transform(GeometryId geometry, std::uint32_t instance, const InstanceTransform& t, std::string_view op) const;
  void check_affine(GeometryId geometry, std::uint32_t instance, const glm::mat4& m, std::string_view op) const;
  void check_mask(GeometryId geometry, std::uint32_t instance, std::uint32_t mask, std::string_view op) const;

  const proceduray::Plan* m_plan;
  std::vector<Instance> m_list;       // index = TLAS index
  std::vector<Owner> m_owners;        // index = TLAS index
  std::vector<std::uint8_t> m_masks;  // index = TLAS index; as set: a hidden instance's mask waits here
  std::vector<bool> m_hidden;         // index = TLAS index
  std::vector<std::vector<Slot>> m_slots;          // [BLAS][slot]
  std::vector<std::vector<std::uint32_t>> m_free;  // [BLAS]: free slots, reused last-freed first
  std::vector<std::uint32_t> m_free_custom;        // custom indices of removed instances
  std::uint32_t m_next_custom = 0;
  bool m_update = false;
  bool m_rebuild = false;
};

}  // namespace proceduray::vk

#include "proceduray/vk/scene_instances-inl.hpp"  // the bodies (config.hpp)
