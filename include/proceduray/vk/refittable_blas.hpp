// A bottom-level structure that stays refittable: its inputs and scratch are kept, so new
// boxes or vertices with the same topology update it in place (no new memory, same device
// address, so TLAS instances keep pointing at it).
//
//   proceduray::vk::RefittableBlas blas(ctx, std::span<const proceduray::vk::AabbGeometry>(geometries));
//   boxes[0].maxY = 2.0f;                                        // same number of boxes
//   if (blas.same_topology(geometries))
//     ctx.submit([&](VkCommandBuffer cmd) { blas.record_refit(ctx, cmd, geometries); });
//   else
//     blas = proceduray::vk::RefittableBlas(ctx, geometries);   // rebuild: a new address
//
// A refit is cheap but keeps the old tree's shape: after large motion, rebuilding traces faster.
// It is never compacted (compaction drops the update ability).
#pragma once

#include <proceduray/vk/acceleration.hpp>

#include <algorithm>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace proceduray::vk {

/// A BLAS built with ALLOW_UPDATE, with its inputs and scratch kept for refits.
class RefittableBlas {
 public:
  RefittableBlas() = default;
  /// Builds over procedural geometries and waits; throws for bad boxes. `planned`: the boxes come
  /// from a Plan, and later ones from setters that check them (SceneAcceleration): not checked here.
  RefittableBlas(const Context& ctx, std::span<const AabbGeometry> geometries, bool fast_trace = true, bool planned = false)
      : m_input(detail::aabb_input(ctx, geometries, "RefittableBlas", !planned)), m_planned(planned) {
    build(ctx, fast_trace);
  }
  /// Builds over triangle geometries and waits; throws for a bad mesh.
  RefittableBlas(const Context& ctx, std::span<const TriangleGeometry> geometries, bool fast_trace = true,
                 bool planned = false)
      : m_input(detail::triangle_input(ctx, geometries, "RefittableBlas", !planned)), m_planned(planned) {
    for (const TriangleGeometry& t : geometries) {
      m_indices.insert(m_indices.end(), t.indices.begin(), t.indices.end());
      m_vertex_counts.push_back(static_cast<std::uint32_t>(t.vertices.size()));
    }
    build(ctx, fast_trace);
  }

  const AccelerationStructure& structure() const noexcept { return m_structure; }

  /// True when `geometries` have this BLAS's box counts, so a refit can take them.
  bool same_topology(std::span<const AabbGeometry> geometries) const {
    if (!m_vertex_counts.empty() || geometries.size() != m_input.counts.size()) return false;
    for (std::size_t g = 0; g < geometries.size(); ++g) {
      if (geometries[g].boxes.size() != m_input.counts[g]) return false;
    }
    return true;
  }
  /// True when `geometries` have this BLAS's vertex counts and the very same indices.
  bool same_topology(std::span<const TriangleGeometry> geometries) const {
    if (geometries.size() != m_vertex_counts.size()) return false;
    std::size_t at = 0;
    for (std::size_t g = 0; g < geometries.size(); ++g) {
      const TriangleGeometry& t = geometries[g];
      if (t.vertices.size() != m_vertex_counts[g] || at + t.indices.size() > m_indices.size()) return false;
      if (!std::equal(t.indices.begin(), t.indices.end(), m_indices.begin() + static_cast<std::ptrdiff_t>(at))) return false;
      at += t.indices.size();
    }
    return at == m_indices.size();
  }

  /// Writes new boxes and records the refit into `cmd`, with a barrier for the TLAS build and
  /// traces after it. Throws when the topology differs: build a new RefittableBlas for that.
  void record_refit(const Context& ctx, VkCommandBuffer cmd, std::span<const AabbGeometry> geometries) {
    if (!m_planned) detail::check_aabbs(geometries, "RefittableBlas::record_refit");
    if (!same_topology(geometries)) throw topology_error();
    detail::write_aabbs(m_input, geometries);
    record(ctx, cmd, VK_BUILD_ACCELERATION_STRUCTURE_MODE_UPDATE_KHR);
  }
  /// The same for new vertex positions (indices unchanged).
  void record_refit(const Context& ctx, VkCommandBuffer cmd, std::span<const TriangleGeometry> geometries) {
    if (!m_planned) detail::check_triangles(geometries, "RefittableBlas::record_refit");
    if (!same_topology(geometries)) throw topology_error();
    detail::write_vertices(m_input, geometries);
    record(ctx, cmd, VK_BUILD_ACCELERATION_STRUCTURE_MODE_UPDATE_KHR);
  }

 private:
  static UsageError topology_error() {
    return UsageError("RefittableBlas::record_refit: the geometry has other primitive counts or indices "
                                 "than the BLAS was built with; a refit keeps the topology: build a new "
                                 "RefittableBlas instead");
  }
  /// This BLAS's build (or refit) for the build primitive.
  detail::BuildCommand command(VkBuildAccelerationStructureModeKHR mode) const {
    return {.type = VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, .flags = m_flags, .mode = mode,
            .geometries = m_input.geometries, .counts = m_input.counts, .dst = m_structure.get(),
            .scratch = m_scratch.address};
  }
  void build(const Context& ctx, bool fast_trace) {
    m_flags = detail::build_flags({.compact = false, .allow_update = true, .fast_trace = fast_trace}, false);
    const auto sizes = detail::build_sizes(ctx, command(VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR));
    m_structure = AccelerationStructure(ctx, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, sizes.accelerationStructureSize);
    m_scratch = detail::Scratch(ctx, std::max(sizes.buildScratchSize, sizes.updateScratchSize));
    ctx.submit([&](VkCommandBuffer cmd) { record(ctx, cmd, VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR); });
  }
  void record(const Context& ctx, VkCommandBuffer cmd, VkBuildAccelerationStructureModeKHR mode) {
    const detail::BuildCommand c = command(mode);
    // The TLAS build that follows reads this structure, and so do the traces.
    detail::record_builds(ctx, cmd, {&c, 1}, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR |
                                                 VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR);
  }

  detail::BlasInput m_input;
  AccelerationStructure m_structure;
  detail::Scratch m_scratch;
  VkBuildAccelerationStructureFlagsKHR m_flags = 0;
  std::vector<std::uint32_t> m_indices;        // triangles: every index, for topology checks
  std::vector<std::uint32_t> m_vertex_counts;  // triangles: per geometry
  bool m_planned = false;                      // input checked before it gets here
};

}  // namespace proceduray::vk
