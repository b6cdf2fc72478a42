// The instances of a compiled scene's TLAS and what their changes need: moves (DynamicTransform
// geometry) and visibility are a TLAS update, a mask change is a TLAS build. SceneAcceleration
// owns one; take() tells it what to record before the next trace.
//
//   proceduray::vk::SceneInstances instances(plan, list);      // the plan's instances, in TLAS order
//   instances.set_visible(ball, 1, false, "my_call");           // hidden: mask 0, the TLAS updated
//   instances.set_transform(ball, 0, moved, "my_call");         // DynamicTransform geometry only
//   if (instances.take() == proceduray::vk::TlasWork::update) tlas.record_update(ctx, cmd, instances.list());
//
// `op` names the call the user made, for messages. `plan` must outlive it.
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
  SceneInstances(const proceduray::Plan& plan, std::vector<Instance> list)
      : m_plan(&plan), m_list(std::move(list)), m_hidden(m_list.size(), false) {
    for (const Instance& i : m_list) m_masks.push_back(i.mask);
  }

  /// Moves one instance of a DynamicTransform geometry: a TLAS update. Throws for a Static geometry,
  /// a bad index, or a matrix that is not finite and affine.
  void set_transform(GeometryId geometry, std::uint32_t instance, const glm::mat4& object_to_world, std::string_view op);
  /// Moves every instance (one matrix each, in order): one TLAS update; nothing moves if one is bad.
  void set_transforms(GeometryId geometry, std::span<const glm::mat4> object_to_world, std::string_view op);
  /// Changes one instance's mask, any policy: a TLAS build. A hidden instance keeps it for when it is shown.
  void set_mask(GeometryId geometry, std::uint32_t instance, std::uint32_t mask, std::string_view op);
  /// Hides (mask 0: no ray's cull mask meets it) or shows one instance, any policy: a TLAS update,
  /// no rebuild. Setting what it already is does nothing.
  void set_visible(GeometryId geometry, std::uint32_t instance, bool visible, std::string_view op);
  /// Whether one instance is shown; throws for a bad index.
  bool visible(GeometryId geometry, std::uint32_t instance, std::string_view op) const {
    return !m_hidden[m_plan->tlas_index(geometry, instance, op)];
  }

  /// The instances as the TLAS takes them (hidden ones with mask 0).
  std::span<const Instance> list() const noexcept { return m_list; }
  /// A BLAS was refit: the TLAS holds its old bounds and needs an update.
  void blas_refit() noexcept { m_update = true; }
  /// A BLAS was rebuilt: its instances point at `structure` and the TLAS is built again.
  void blas_rebuilt(const PlannedBlas& blas, const AccelerationStructure& structure) {
    for (std::uint32_t k = 0; k < blas.instance_count; ++k) m_list[blas.first_instance + k].blas = &structure;
    m_rebuild = true;
  }
  /// What the changes since the last call need (a build covers an update), and forgets them.
  TlasWork take() noexcept {
    const TlasWork work = m_rebuild ? TlasWork::build : m_update ? TlasWork::update : TlasWork::none;
    m_update = m_rebuild = false;
    return work;
  }

 private:
  void check_movable(GeometryId geometry, std::string_view operation) const;
  /// The TLAS index of (geometry, instance) of a movable geometry; throws InvalidGeometryError or UsageError.
  std::uint32_t movable_instance(GeometryId geometry, std::uint32_t instance, std::string_view op) const;
  /// InvalidGeometryError naming `op`, the geometry and the instance for a non-finite or singular matrix.
  void check_transform(GeometryId geometry, std::uint32_t instance, const InstanceTransform& t, std::string_view op) const;
  void check_affine(GeometryId geometry, std::uint32_t instance, const glm::mat4& m, std::string_view op) const;

  const proceduray::Plan* m_plan;
  std::vector<Instance> m_list;       // index = TLAS index
  std::vector<std::uint8_t> m_masks;  // as set: a hidden instance's mask waits here
  std::vector<bool> m_hidden;
  bool m_update = false;
  bool m_rebuild = false;
};

#if PROCEDURAY_BODIES

PROCEDURAY_DECL void SceneInstances::check_movable(GeometryId geometry, std::string_view operation) const {
  const PlannedGeometry& g = m_plan->geometry(geometry, operation);
  if (m_plan->blases()[g.blas].update == UpdatePolicy::Static) {
    throw UsageError(std::string(operation) + ": geometry \"" + g.name +
                                "\" is Static, so its instances were built not to move; declare it with "
                                "update = UpdatePolicy::DynamicTransform");
  }
}

PROCEDURAY_DECL std::uint32_t SceneInstances::movable_instance(GeometryId geometry, std::uint32_t instance,
                                                               std::string_view op) const {
  const std::uint32_t k = m_plan->tlas_index(geometry, instance, op);  // InvalidGeometryError for a bad index
  check_movable(geometry, op);
  return k;
}

PROCEDURAY_DECL void SceneInstances::check_affine(GeometryId geometry, std::uint32_t instance, const glm::mat4& m,
                                                  std::string_view op) const {
  // An instance transform is 3x4: a projective last row would be dropped without a word.
  if (m[0][3] == 0.0f && m[1][3] == 0.0f && m[2][3] == 0.0f && m[3][3] == 1.0f) return;
  throw UsageError(std::string(op) + ": geometry \"" + m_plan->geometry(geometry, op).name + "\" instance " +
                   std::to_string(instance) + " matrix has last row (" + std::to_string(m[0][3]) + ", " +
                   std::to_string(m[1][3]) + ", " + std::to_string(m[2][3]) + ", " + std::to_string(m[3][3]) +
                   "), not (0, 0, 0, 1); an instance transform is affine: pass a rotation, scale and translation");
}

PROCEDURAY_DECL void SceneInstances::check_transform(GeometryId geometry, std::uint32_t instance, const InstanceTransform& t,
                                                     std::string_view op) const {
  detail::check_matrix(t, [&] {
    return std::string(op) + ": geometry \"" + m_plan->geometry(geometry).name + "\" instance " + std::to_string(instance) +
           " transform";
  });
}

PROCEDURAY_DECL void SceneInstances::set_transforms(GeometryId geometry, std::span<const glm::mat4> object_to_world,
                                                    std::string_view op) {
  check_movable(geometry, op);
  const PlannedGeometry& g = m_plan->geometry(geometry, op);
  const PlannedBlas& blas = m_plan->blases()[g.blas];
  if (object_to_world.size() != blas.instance_count) {
    throw InvalidGeometryError(std::string(op) + ": geometry \"" + g.name + "\" has " +
                               std::to_string(blas.instance_count) + " instances, " +
                               std::to_string(object_to_world.size()) + " transforms given; give one per instance");
  }
  // A BLAS's instances are consecutive in the TLAS. All are checked (and converted, once, into Vulkan's
  // rows) before any moves, so a bad matrix leaves every instance where it was.
  std::vector<InstanceTransform> rows(blas.instance_count);
  for (std::uint32_t i = 0; i < blas.instance_count; ++i) {
    check_affine(geometry, i, object_to_world[i], op);
    rows[i] = instance_transform(object_to_world[i]);
    check_transform(geometry, i, rows[i], op);
  }
  for (std::uint32_t i = 0; i < blas.instance_count; ++i) m_list[blas.first_instance + i].transform = rows[i];
  m_update = true;
}

PROCEDURAY_DECL void SceneInstances::set_mask(GeometryId geometry, std::uint32_t instance, std::uint32_t mask,
                                              std::string_view op) {
  const std::uint32_t k = m_plan->tlas_index(geometry, instance, op);
  if (mask > 0xFF) {  // an int would otherwise lose its high bits and could become 0: the instance vanishes
    throw UsageError(std::string(op) + ": mask 0x" + proceduray::detail::hex(mask) + " of geometry \"" +
                     m_plan->geometry(geometry).name + "\" instance " + std::to_string(instance) +
                     " has more than Vulkan's 8 instance-mask bits; use layer bits (Scene::layer_mask), 0..0xFF");
  }
  if (m_masks[k] == mask) return;
  m_masks[k] = static_cast<std::uint8_t>(mask);
  if (m_hidden[k]) return;  // shown with it later
  m_list[k].mask = static_cast<std::uint8_t>(mask);
  m_rebuild = true;
}

PROCEDURAY_DECL void SceneInstances::set_visible(GeometryId geometry, std::uint32_t instance, bool visible,
                                                 std::string_view op) {
  const std::uint32_t k = m_plan->tlas_index(geometry, instance, op);  // InvalidGeometryError for a bad index
  if (m_hidden[k] == !visible) return;
  m_hidden[k] = !visible;
  // Mask 0 meets no ray's cull mask; the instance keeps its place, so the TLAS is only updated.
  m_list[k].mask = visible ? m_masks[k] : std::uint8_t{0};
  m_update = true;
}

PROCEDURAY_DECL void SceneInstances::set_transform(GeometryId geometry, std::uint32_t instance, const glm::mat4& object_to_world,
                                                   std::string_view op) {
  const std::uint32_t k = movable_instance(geometry, instance, op);
  check_affine(geometry, instance, object_to_world, op);
  const InstanceTransform rows = instance_transform(object_to_world);  // the one conversion
  check_transform(geometry, instance, rows, op);                        // throws
  m_list[k].transform = rows;
  m_update = true;
}

#endif  // PROCEDURAY_BODIES

}  // namespace proceduray::vk
