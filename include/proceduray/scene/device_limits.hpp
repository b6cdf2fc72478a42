// The device limits a compiled scene is checked against when its SBT is laid out: the SBT
// properties plus ray-tracing and acceleration-structure limits.
//
//   proceduray::DeviceLimits limits{.sbt = {.handle_size = 32, .handle_alignment = 16,
//                                           .base_alignment = 32, .max_stride = 16384}};
//   auto layout = proceduray::compile(scene).layout(limits);   // throws DeviceLimitError when the scene does not fit
//
// Fill it from VkPhysicalDeviceRayTracingPipelinePropertiesKHR and
// VkPhysicalDeviceAccelerationStructurePropertiesKHR; the defaults are the smallest values
// seen on the devices in shared/device-profiles.
#pragma once

#include <cstdint>
#include <string>

#include "proceduray/scene/sbt_layout.hpp"

namespace proceduray {

/// Largest instanceShaderBindingTableRecordOffset / instanceCustomIndex: both are 24-bit fields.
inline constexpr std::uint32_t max_instance_sbt_offset = 0xFF'FFFFu;

/// The one rule for a TLAS instance's 24-bit fields (SBT offset, custom index), used by the scene
/// and by vk::build_tlas.
constexpr bool fits_instance_field(std::uint64_t value) noexcept { return value <= max_instance_sbt_offset; }

/// Limits a compiled scene must respect (Plan::layout).
struct DeviceLimits {
  SbtProperties sbt;                                  ///< handle size and alignments, max stride
  std::uint32_t max_ray_recursion_depth = 31;         ///< maxRayRecursionDepth
  std::uint32_t max_ray_hit_attribute_size = 32;      ///< maxRayHitAttributeSize (bytes)
  std::uint64_t max_geometry_count = 16'777'215;      ///< maxGeometryCount: geometries per BLAS
  std::uint64_t max_instance_count = 16'777'215;      ///< maxInstanceCount: instances in the TLAS
  std::uint32_t max_push_constants_size = 128;        ///< maxPushConstantsSize (bytes); 128 on every device
  std::string device;                                 ///< the device's name, for messages; empty: unnamed
};

}  // namespace proceduray
