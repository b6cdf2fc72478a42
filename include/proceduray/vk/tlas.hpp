// The top-level structure: instances of BLASes with their transforms and SBT offsets, checked,
// packed into Vulkan's layout and built; refittable when asked.
//
//   VkAabbPositionsKHR box{-1, -1, -1, 1, 1, 1};
//   const proceduray::vk::AabbGeometry boxes{.boxes = {&box, 1}};
//   auto blas = proceduray::vk::build_blas(ctx, {&boxes, 1});
//   std::vector<proceduray::vk::Instance> instances{
//       {.blas = &blas, .transform = proceduray::instance_transform(glm::translate(glm::mat4(1), {-1.5f, 0, 0})), .sbt_offset = 0},
//       {.blas = &blas, .transform = proceduray::instance_transform(glm::translate(glm::mat4(1), {+1.5f, 0, 0})), .sbt_offset = 1}};
//   auto tlas = proceduray::vk::build_tlas(ctx, instances);                // built and waited for
//   proceduray::vk::Tlas moving(ctx, instances, {.allow_update = true});
//   instances[0].transform = proceduray::instance_transform(moved);  moving.update(ctx, instances);        // refit and wait
//   ctx.submit([&](VkCommandBuffer cmd) { moving.record_update(ctx, cmd, instances); });  // or record it
//
// Instances are checked by the scene's rules (scene/geometry.hpp): a non-finite or singular
// transform throws InvalidGeometryError, an index past 24 bits DeviceLimitError, no BLAS UsageError;
// each message names the call and the instance's index in the list given.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/error.hpp>
#include <proceduray/scene/device_limits.hpp>
#include <proceduray/scene/geometry.hpp>
#include <proceduray/vk/acceleration.hpp>
#include <proceduray/vk/buffer.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace proceduray::vk {

/// One instance of a BLAS in the TLAS.
struct Instance {
  const AccelerationStructure* blas = nullptr;  ///< required
  InstanceTransform transform = identity_transform();  ///< object to world, rows as Vulkan takes them (instance_transform(mat4))
  std::uint32_t custom_index = 0;               ///< gl_InstanceCustomIndexEXT, 24 bits
  std::uint32_t sbt_offset = 0;                 ///< instanceShaderBindingTableRecordOffset, 24 bits
  std::uint8_t mask = 0xFF;                     ///< visibility mask tested against the ray's cull mask
  VkGeometryInstanceFlagsKHR flags = 0;         ///< e.g. VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR
};

namespace detail {

/// Throws InvalidGeometryError for a non-finite or singular transform: the scene's rule
/// (proceduray::detail::check_transform), applied in place; `where` is built only on failure.
template <class Where>
void check_matrix(const InstanceTransform& t, Where where) {
  if (!proceduray::detail::valid_transform(t)) proceduray::validate(t, where());  // throws
}

/// Throws for an instance Vulkan cannot take: no BLAS (UsageError), indices past 24 bits
/// (DeviceLimitError), a non-finite or singular transform (InvalidGeometryError).
PROCEDURAY_DECL void check_instance(const Instance& in, std::size_t i, std::string_view operation = "build_tlas");

/// Packs instances into Vulkan's layout; throws for bad input (check_instance), naming the instance.
PROCEDURAY_DECL void pack_instances(std::span<const Instance> instances, std::span<VkAccelerationStructureInstanceKHR> packed,
                                    std::string_view operation = "build_tlas", bool check = true);

}  // namespace detail

/// A top-level structure with its instance buffer; refittable when built with allow_update.
class Tlas {
 public:
  Tlas() = default;
  /// Builds over `instances` (an empty list gives a TLAS that every ray misses) and waits. Sized
  /// for `capacity` instances (at least the list's), so record_build may later take up to that many.
  Tlas(const Context& ctx, std::span<const Instance> instances, const BuildOptions& options = {},
       std::uint32_t capacity = 0)
      : m_count(static_cast<std::uint32_t>(instances.size())),
        m_capacity(std::max(capacity, static_cast<std::uint32_t>(instances.size()))),
        m_flags(detail::build_flags(options, false)),
        m_planned(options.planned),
        m_instances(ctx, std::max<VkDeviceSize>(1, m_capacity) * sizeof(VkAccelerationStructureInstanceKHR),
                    VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
                        VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT) {
    write(instances, "Tlas");
    m_geometry = make<VkAccelerationStructureGeometryKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR);
    m_geometry.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
    m_geometry.geometry.instances = make<VkAccelerationStructureGeometryInstancesDataKHR>(
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR);
    m_geometry.geometry.instances.data.deviceAddress = m_instances.address();
    detail::BuildCommand sizing = command(VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR);
    sizing.counts = {&m_capacity, 1};
    const auto sizes = detail::build_sizes(ctx, sizing);
    m_structure = AccelerationStructure(ctx, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, sizes.accelerationStructureSize);
    // Kept for refits: an update needs scratch of updateScratchSize, a build of buildScratchSize.
    m_scratch = detail::Scratch(ctx, std::max(sizes.buildScratchSize, sizes.updateScratchSize));
    ctx.submit([&](VkCommandBuffer cmd) { record(ctx, cmd, VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR); });
  }

  const AccelerationStructure& structure() const noexcept { return m_structure; }
  VkAccelerationStructureKHR get() const noexcept { return m_structure.get(); }
  std::uint32_t instance_count() const noexcept { return m_count; }
  /// The most instances record_build takes without a new Tlas.
  std::uint32_t capacity() const noexcept { return m_capacity; }
  bool updatable() const noexcept { return (m_flags & VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_UPDATE_BIT_KHR) != 0; }

  /// Refits for new transforms (same instances, same BLASes): records into `cmd` with a barrier for tracing.
  void record_update(const Context& ctx, VkCommandBuffer cmd, std::span<const Instance> instances) {
    if (!updatable()) {
      throw UsageError("Tlas::update: this TLAS was built without BuildOptions::allow_update; build it with "
                       "allow_update = true to move instances");
    }
    if (instances.size() != m_count) {
      throw UsageError("Tlas::update: " + std::to_string(instances.size()) + " instances given, the TLAS has " +
                       std::to_string(m_count) + "; an update may move instances, not add or remove them "
                       "(record_build does, up to capacity())");
    }
    write(instances, "Tlas::update");
    record(ctx, cmd, VK_BUILD_ACCELERATION_STRUCTURE_MODE_UPDATE_KHR);
  }
  /// Rebuilds in place (the handle stays) over up to capacity() instances: BLASes replaced, masks
  /// changed, instances added or removed. Records into `cmd`.
  void record_build(const Context& ctx, VkCommandBuffer cmd, std::span<const Instance> instances) {
    if (instances.size() > m_capacity) {
      throw UsageError("Tlas::record_build: " + std::to_string(instances.size()) + " instances given, the TLAS has " +
                       "room for " + std::to_string(m_capacity) + "; build a new Tlas with a larger capacity");
    }
    write(instances, "Tlas::record_build");
    m_count = static_cast<std::uint32_t>(instances.size());
    record(ctx, cmd, VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR);
  }
  /// Refits and waits.
  void update(const Context& ctx, std::span<const Instance> instances) {
    ctx.submit([&](VkCommandBuffer cmd) { record_update(ctx, cmd, instances); });
  }

 private:
  /// This TLAS's build (or update) for the build primitive.
  detail::BuildCommand command(VkBuildAccelerationStructureModeKHR mode) const {
    return {.type = VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, .flags = m_flags, .mode = mode,
            .geometries = {&m_geometry, 1}, .counts = {&m_count, 1}, .dst = m_structure.get(),
            .scratch = m_scratch.address};
  }
  void write(std::span<const Instance> instances, std::string_view operation) {
    auto* packed = static_cast<VkAccelerationStructureInstanceKHR*>(m_instances.data());
    detail::pack_instances(instances, {packed, instances.size()}, operation, !m_planned);
  }
  void record(const Context& ctx, VkCommandBuffer cmd, VkBuildAccelerationStructureModeKHR mode) {
    const detail::BuildCommand c = command(mode);
    detail::record_builds(ctx, cmd, {&c, 1}, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR);  // traces read it
  }

  std::uint32_t m_count = 0;
  std::uint32_t m_capacity = 0;
  VkBuildAccelerationStructureFlagsKHR m_flags = 0;
  bool m_planned = false;  // BuildOptions::planned: instances checked where they were given
  Buffer m_instances;
  AccelerationStructure m_structure;
  detail::Scratch m_scratch;
  VkAccelerationStructureGeometryKHR m_geometry{};
};

/// Builds a TLAS over `instances` and waits (see Tlas for refittable ones).
PROCEDURAY_DECL AccelerationStructure build_tlas(const Context& ctx, std::span<const Instance> instances);

}  // namespace proceduray::vk

#include "proceduray/vk/tlas-inl.hpp"  // the bodies (config.hpp)
