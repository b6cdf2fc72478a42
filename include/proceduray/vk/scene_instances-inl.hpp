// The bodies of proceduray/vk/scene_instances.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/scene_instances.hpp"

#if PROCEDURAY_BODIES

namespace proceduray::vk {

PROCEDURAY_DECL SceneInstances::SceneInstances(const proceduray::Plan& plan, std::vector<Instance> list)
    : m_plan(&plan), m_list(std::move(list)), m_hidden(m_list.size(), false),
      m_slots(plan.blases().size()), m_free(plan.blases().size()),
      m_next_custom(static_cast<std::uint32_t>(m_list.size())) {
  const auto planned = plan.instances();
  if (m_list.size() != planned.size()) {
    throw UsageError("SceneInstances: " + std::to_string(m_list.size()) + " instances given, the plan has " +
                     std::to_string(planned.size()) + "; give one per Plan::instances() entry, in that order");
  }
  for (std::uint32_t k = 0; k < m_list.size(); ++k) {
    m_masks.push_back(m_list[k].mask);
    const std::uint32_t blas = planned[k].blas;
    m_owners.push_back({blas, static_cast<std::uint32_t>(m_slots[blas].size())});
    m_slots[blas].push_back({k, 0});
  }
}

PROCEDURAY_DECL std::size_t SceneInstances::slot_count() const noexcept {
  std::size_t n = 0;
  for (const std::vector<Slot>& slots : m_slots) n += slots.size();
  return n;
}

PROCEDURAY_DECL std::uint32_t SceneInstances::tlas_index(GeometryId geometry, std::uint32_t instance,
                                                         std::string_view op) const {
  const PlannedGeometry& g = m_plan->geometry(geometry, op);  // UnknownIdError for another scene's id
  const std::vector<Slot>& slots = m_slots[g.blas];
  const std::uint32_t slot = instance & slot_mask, generation = instance >> slot_bits;
  if (slot >= slots.size()) {
    throw InvalidGeometryError(std::string(op) + ": geometry \"" + g.name + "\" has " + std::to_string(slots.size()) +
                               " instance slots, no instance " + std::to_string(instance) + "; pass an instance index below " +
                               std::to_string(slots.size()) + " (GeometryDesc::instances, then the added ones) or a "
                               "handle add_instance returned");
  }
  const Slot& s = slots[slot];
  if (s.generation != generation) {
    throw UsageError(std::string(op) + ": instance " + std::to_string(instance) + " of geometry \"" + g.name +
                     "\" was removed (remove_instance) and its slot " + std::to_string(slot) + " now holds " +
                     (s.tlas == removed ? std::string("nothing") : "instance " + std::to_string(handle(slot, s))) +
                     "; use a handle of a live instance (instances(geometry)), or add_instance for a new one");
  }
  if (s.tlas == removed) {
    throw UsageError(std::string(op) + ": instance " + std::to_string(instance) + " of geometry \"" + g.name +
                     "\" was removed (remove_instance); use a handle of a live instance (instances(geometry)), "
                     "or add_instance for a new one");
  }
  return s.tlas;
}

PROCEDURAY_DECL std::vector<std::uint32_t> SceneInstances::instances(GeometryId geometry, std::string_view op) const {
  const std::vector<Slot>& slots = m_slots[m_plan->geometry(geometry, op).blas];
  std::vector<std::uint32_t> out;
  for (std::uint32_t i = 0; i < slots.size(); ++i) {
    if (slots[i].tlas != removed) out.push_back(handle(i, slots[i]));
  }
  return out;
}

PROCEDURAY_DECL std::uint32_t SceneInstances::add(GeometryId geometry, const glm::mat4& object_to_world, std::uint32_t mask,
                                                  const AccelerationStructure& blas, std::string_view op) {
  const PlannedGeometry& g = m_plan->geometry(geometry, op);
  const PlannedBlas& planned = m_plan->blases()[g.blas];
  std::vector<Slot>& slots = m_slots[g.blas];
  std::vector<std::uint32_t>& free = m_free[g.blas];
  const std::uint32_t slot = free.empty() ? static_cast<std::uint32_t>(slots.size()) : free.back();
  const std::uint32_t instance = slot | (free.empty() ? 0u : slots[slot].generation << slot_bits);
  if (planned.shared_sbt_offset == no_index) {
    throw UsageError(std::string(op) + ": geometry \"" + g.name + "\" has no hit records a new instance could use: " +
                     (planned.instance_count == 0 ? "it declares no instances" : "every instance has entries of its own") +
                     "; set GeometryDesc::may_add_instances = true and give the geometry entries of its own "
                     "(Scene::add_hit without an instance) or a default hit per ray");
  }
  check_mask(geometry, instance, mask, op);
  check_affine(geometry, instance, object_to_world, op);
  const InstanceTransform rows = instance_transform(object_to_world);
  check_transform(geometry, instance, rows, op);
  const std::uint32_t custom = next_custom_index();
  if (!fits_instance_field(custom) || slot > slot_mask) {
    throw DeviceLimitError(std::string(op) + ": instance custom index " + std::to_string(custom) +
                           " would pass the 24 bits of instanceCustomIndex: the scene has " +
                           std::to_string(m_list.size()) + " live instances; remove_instance some before adding more");
  }
  const auto k = static_cast<std::uint32_t>(m_list.size());
  m_list.push_back({.blas = &blas, .transform = rows, .custom_index = custom,
                    .sbt_offset = planned.shared_sbt_offset, .mask = static_cast<std::uint8_t>(mask)});
  m_owners.push_back({g.blas, slot});
  m_masks.push_back(static_cast<std::uint8_t>(mask));
  m_hidden.push_back(false);
  if (m_free_custom.empty()) {
    ++m_next_custom;
  } else {
    m_free_custom.pop_back();
  }
  if (free.empty()) {
    slots.push_back({k, 0});
  } else {
    free.pop_back();
    slots[slot].tlas = k;
  }
  m_rebuild = true;
  return instance;
}

PROCEDURAY_DECL void SceneInstances::remove(GeometryId geometry, std::uint32_t instance, std::string_view op) {
  const std::uint32_t k = tlas_index(geometry, instance, op);  // throws for a bad or removed index
  const std::uint32_t blas = m_plan->geometry(geometry).blas, slot = instance & slot_mask;
  m_free_custom.push_back(m_list[k].custom_index);
  const auto last = static_cast<std::uint32_t>(m_list.size() - 1);
  // The last entry takes the hole, so the list stays dense; only its gl_InstanceID changes.
  m_list[k] = m_list[last];
  m_owners[k] = m_owners[last];
  m_masks[k] = m_masks[last];
  m_hidden[k] = m_hidden[last];
  m_slots[m_owners[k].blas][m_owners[k].slot].tlas = k;
  m_list.pop_back();
  m_owners.pop_back();
  m_masks.pop_back();
  m_hidden.pop_back();
  Slot& s = m_slots[blas][slot];
  s.tlas = removed;
  s.generation = (s.generation + 1) & (0xFFu);  // the handle just removed no longer matches
  m_free[blas].push_back(slot);
  m_rebuild = true;
}

PROCEDURAY_DECL void SceneInstances::blas_rebuilt(std::uint32_t blas, const AccelerationStructure& structure) {
  for (const Slot& s : m_slots[blas]) {
    if (s.tlas != removed) m_list[s.tlas].blas = &structure;
  }
  m_rebuild = true;
}


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
  const std::uint32_t k = tlas_index(geometry, instance, op);  // InvalidGeometryError for a bad index
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
  const std::vector<std::uint32_t> live = instances(geometry, op);
  if (object_to_world.size() != live.size()) {
    throw InvalidGeometryError(std::string(op) + ": geometry \"" + m_plan->geometry(geometry).name + "\" has " +
                               std::to_string(live.size()) + " instances, " + std::to_string(object_to_world.size()) +
                               " transforms given; give one per instance (SceneInstances::instances order)");
  }
  // All are checked (and converted, once, into Vulkan's rows) before any moves, so a bad matrix
  // leaves every instance where it was.
  std::vector<InstanceTransform> rows(live.size());
  for (std::size_t i = 0; i < live.size(); ++i) {
    check_affine(geometry, live[i], object_to_world[i], op);
    rows[i] = instance_transform(object_to_world[i]);
    check_transform(geometry, live[i], rows[i], op);
  }
  const std::vector<Slot>& slots = m_slots[m_plan->geometry(geometry).blas];
  for (std::size_t i = 0; i < live.size(); ++i) m_list[slots[live[i] & slot_mask].tlas].transform = rows[i];
  m_update = true;
}

PROCEDURAY_DECL void SceneInstances::check_mask(GeometryId geometry, std::uint32_t instance, std::uint32_t mask,
                                                std::string_view op) const {
  if (mask > 0xFF) {  // an int would otherwise lose its high bits and could become 0: the instance vanishes
    throw UsageError(std::string(op) + ": mask 0x" + proceduray::detail::hex(mask) + " of geometry \"" +
                     m_plan->geometry(geometry).name + "\" instance " + std::to_string(instance) +
                     " has more than Vulkan's 8 instance-mask bits; use layer bits (Scene::layer_mask), 0..0xFF");
  }
}

PROCEDURAY_DECL void SceneInstances::set_mask(GeometryId geometry, std::uint32_t instance, std::uint32_t mask,
                                              std::string_view op) {
  const std::uint32_t k = tlas_index(geometry, instance, op);
  check_mask(geometry, instance, mask, op);
  if (m_masks[k] == mask) return;
  m_masks[k] = static_cast<std::uint8_t>(mask);
  if (m_hidden[k]) return;  // shown with it later
  m_list[k].mask = static_cast<std::uint8_t>(mask);
  m_rebuild = true;
}

PROCEDURAY_DECL void SceneInstances::set_visible(GeometryId geometry, std::uint32_t instance, bool visible,
                                                 std::string_view op) {
  const std::uint32_t k = tlas_index(geometry, instance, op);  // InvalidGeometryError for a bad index
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

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
