// The acceleration structures of a compiled scene and their updates: one BLAS per planned BLAS
// (compacted when Static, refittable when DynamicGeometry), the TLAS over the planned instances
// (refittable when anything is dynamic), and the per-frame work the update policies allow.
//
//   proceduray::vk::SceneAcceleration structures(ctx, plan);   // the plan's geometry, as it is
//   structures.set_transform(ball, 1, moved);          // DynamicTransform: TLAS refit next frame
//   structures.set_aabbs(blob, boxes);                 // DynamicGeometry: BLAS refit, or rebuild
//   ctx.submit([&](VkCommandBuffer cmd) {
//     proceduray::vk::FrameWork work = structures.record(cmd);   // refits and the TLAS update, then a barrier
//     // ... vkCmdTraceRaysKHR over structures.tlas() ...
//   });
//
// `plan` must outlive it (it resolves geometry ids through the plan). Setters take the name of
// the call the user made, for messages (the Renderer passes "Renderer::set_transform", say).
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/error.hpp>
#include <proceduray/scene/plan.hpp>
#include <proceduray/vk/acceleration.hpp>
#include <proceduray/vk/frame.hpp>
#include <proceduray/vk/refittable_blas.hpp>
#include <proceduray/vk/scene_instances.hpp>
#include <proceduray/vk/tlas.hpp>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace proceduray::vk {

/// A compiled scene's BLASes and TLAS, and their updates.
class SceneAcceleration {
 public:
  /// Builds every BLAS and the TLAS from `plan` and its geometry data (not copied for Static
  /// geometry: `plan` must outlive it), and waits: all Static BLASes in one submit and compacted in a second
  /// (build_blases), each DynamicGeometry one refittable in its own, then the TLAS.
  SceneAcceleration(const Context& ctx, const proceduray::Plan& plan,
                    const BuildOptions& options = {});
  SceneAcceleration(const SceneAcceleration&) = delete;
  SceneAcceleration& operator=(const SceneAcceleration&) = delete;

  /// Move, mask, show or hide instances (SceneInstances): the TLAS work happens at the next record().
  void set_transform(GeometryId geometry, std::uint32_t instance, const glm::mat4& object_to_world,
                     std::string_view op = "SceneAcceleration::set_transform") {
    m_instances->set_transform(geometry, instance, object_to_world, op);
  }
  void set_transforms(GeometryId geometry, std::span<const glm::mat4> object_to_world,
                      std::string_view op = "SceneAcceleration::set_transforms") {
    m_instances->set_transforms(geometry, object_to_world, op);
  }
  void set_mask(GeometryId geometry, std::uint32_t instance, std::uint32_t mask,
                std::string_view op = "SceneAcceleration::set_mask") {
    m_instances->set_mask(geometry, instance, mask, op);
  }
  void set_visible(GeometryId geometry, std::uint32_t instance, bool visible,
                   std::string_view op = "SceneAcceleration::set_visible") {
    m_instances->set_visible(geometry, instance, visible, op);
  }
  /// Adds an instance of `geometry`'s BLAS, or removes one (SceneInstances::add, remove): a TLAS
  /// build at the next record(). An add past the TLAS's capacity replaces it now with one of twice
  /// the room (built and waited for; no frame may be using the old one), and take_tlas_replaced()
  /// says so once, for the descriptor sets that hold its handle.
  std::uint32_t add_instance(GeometryId geometry, const glm::mat4& object_to_world, std::uint32_t mask = 0xFF,
                             std::string_view op = "SceneAcceleration::add_instance");
  void remove_instance(GeometryId geometry, std::uint32_t instance, std::string_view op = "SceneAcceleration::remove_instance") {
    m_instances->remove(geometry, instance, op);
  }
  /// True once after add_instance replaced the TLAS (its handle changed).
  bool take_tlas_replaced() noexcept { return std::exchange(m_tlas_replaced, false); }
  /// The instances, their indices and TLAS places.
  const SceneInstances& instances() const noexcept { return *m_instances; }
  /// New boxes for a DynamicGeometry procedural geometry: refit for the same count, else rebuild.
  void set_aabbs(GeometryId geometry, std::span<const Aabb> boxes, std::string_view op = "SceneAcceleration::set_aabbs");
  /// New positions (same count) for a DynamicGeometry triangle geometry: refit.
  void set_vertices(GeometryId geometry, std::span<const glm::vec3> vertices,
                    std::string_view op = "SceneAcceleration::set_vertices");
  /// A new mesh for a DynamicGeometry triangle geometry: refit for the same indices, else rebuild.
  void set_mesh(GeometryId geometry, TriangleMesh mesh, std::string_view op = "SceneAcceleration::set_mesh");

  /// Rebuilds what changed topology (each rebuild waits), then records into `cmd` the refits and
  /// the TLAS update or rebuild the changes since the last call need, each followed by a barrier
  /// for ray tracing. Returns the work; FrameWork{} when nothing changed.
  FrameWork record(VkCommandBuffer cmd);

  /// The TLAS (its handle stays the same across updates and rebuilds, not across a replacement).
  const Tlas& tlas() const noexcept { return m_tlas; }
  /// Bytes of every BLAS (Static ones after compaction).
  VkDeviceSize blas_bytes() const noexcept {
    VkDeviceSize total = 0;
    for (const auto& b : m_blases) total += b.get().size();
    return total;
  }

 private:
  /// One scene BLAS: a compacted Static one, or a refittable one with the data it was given.
  struct BlasSlot {
    AccelerationStructure fixed;
    std::unique_ptr<RefittableBlas> dynamic;
    std::vector<std::vector<VkAabbPositionsKHR>> boxes;  // DynamicGeometry procedural: per geometry
    std::vector<TriangleMesh> meshes;                    // DynamicGeometry triangles: per geometry
    bool changed = false;                                // set_* since the last frame
    const AccelerationStructure& get() const { return dynamic ? dynamic->structure() : fixed; }
  };
  /// Builds every Static (and DynamicTransform) BLAS in one batch: two submits, compacted per `options`.
  void build_static_blases(const BuildOptions& options);
  /// Copies the data of DynamicGeometry BLAS `b` and builds it refittable (one submit).
  void build_refittable_blas(std::uint32_t b);
  const PlannedBlas& dynamic_geometry(GeometryId geometry, GeometryKind kind, std::string_view operation) const;
  /// Rebuilds changed BLASes whose topology changed (each waits) and returns the ones to refit.
  std::vector<std::uint32_t> prepare_blases(FrameWork& work);
  void record_refit(VkCommandBuffer cmd, std::uint32_t blas);
  std::vector<AabbGeometry> aabb_geometries(std::uint32_t blas) const;
  std::vector<TriangleGeometry> triangle_geometries(std::uint32_t blas) const;

  const Context* m_ctx;
  const proceduray::Plan* m_plan;
  std::vector<BlasSlot> m_blases;  // index = planned BLAS; never reallocated (instances point into it)
  std::unique_ptr<SceneInstances> m_instances;  // its list points into m_blases
  Tlas m_tlas;
  bool m_tlas_replaced = false;
};

// An Aabb goes to the BLAS build as it is: six floats, min then max, like VkAabbPositionsKHR.
static_assert(sizeof(Aabb) == sizeof(VkAabbPositionsKHR) && offsetof(Aabb, max) == offsetof(VkAabbPositionsKHR, maxX));

}  // namespace proceduray::vk

#include "proceduray/vk/scene_acceleration-inl.hpp"  // the bodies (config.hpp)
