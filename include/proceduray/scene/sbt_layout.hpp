// Shader binding table layout: pure arithmetic over a device's SBT properties.
//
//   proceduray::SbtProperties props{.handle_size = 32, .handle_alignment = 16,
//                                   .base_alignment = 32, .max_stride = 16384};
//   auto layout = proceduray::layout_sbt(props, {{
//       {.count = 1, .max_arguments_size = 0},    // raygen
//       {.count = 2, .max_arguments_size = 0},    // miss
//       {.count = 4, .max_arguments_size = 16},   // hit
//       {}}});                                // callable
//   layout.arguments_offset(proceduray::SbtRegionKind::hit, 3);  // where record 3's data goes
//
// The buffer this describes must itself start at a multiple of base_alignment.
//
//   offset 0          base-aligned       base-aligned             base-aligned
//   | raygen record  | miss 0 | miss 1 | hit 0 | hit 1 | ...     | callable ...
//   |<- stride ----->|<-stride->        |<-stride->
//   record = [ group handle (handle_size) | root arguments (shaderRecordEXT) | pad ]
//   stride = align(handle_size + max data of the region, handle_alignment)
//   raygen: stride = size = align(handle_size + data, base_alignment) (Vulkan requires size == stride)
//
// Impossible properties or an index past a region throw proceduray::UsageError; a stride past
// the device's maxShaderGroupStride, proceduray::DeviceLimitError.
#pragma once

#include <proceduray/config.hpp>

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "proceduray/error.hpp"

namespace proceduray {

/// Ray-tracing pipeline properties the SBT layout depends on (VkPhysicalDeviceRayTracingPipelinePropertiesKHR).
struct SbtProperties {
  std::uint32_t handle_size = 32;        ///< shaderGroupHandleSize
  std::uint32_t handle_alignment = 32;   ///< shaderGroupHandleAlignment: record stride multiple
  std::uint32_t base_alignment = 64;     ///< shaderGroupBaseAlignment: region start multiple
  std::uint32_t max_stride = 4096;       ///< maxShaderGroupStride
};

/// The four SBT regions, in the order they are laid out.
enum class SbtRegionKind : std::uint32_t { raygen = 0, miss = 1, hit = 2, callable = 3 };

PROCEDURAY_DECL const char* to_string(SbtRegionKind kind);

/// What one region holds: its record count and the largest root arguments (bytes after the handle).
struct SbtRegionRecords {
  std::uint32_t count = 0;          ///< records in the region; 0 = empty region
  std::uint32_t max_arguments_size = 0;  ///< largest shaderRecordEXT block of the region; 0 = handles only
};

/// One region as vkCmdTraceRaysKHR sees it, offsets relative to the SBT buffer start.
struct SbtRegion {
  std::uint64_t offset = 0;  ///< start, a multiple of base_alignment
  std::uint64_t stride = 0;  ///< bytes between records; 0 for an empty region
  std::uint64_t size = 0;    ///< bytes the trace call reads (raygen: one record)
  std::uint32_t count = 0;   ///< records in the region
};

/// The computed table: where every region and record lies.
struct SbtLayout {
  SbtProperties properties;
  std::array<SbtRegion, 4> regions{};
  std::uint64_t size = 0;  ///< bytes of the whole buffer

  const SbtRegion& region(SbtRegionKind kind) const { return regions[static_cast<std::uint32_t>(kind)]; }

  /// Byte offset of a record's handle; throws UsageError past the region's count.
  std::uint64_t record_offset(SbtRegionKind kind, std::uint32_t index) const {
    const SbtRegion& r = region(kind);
    if (index >= r.count) {
      throw UsageError("SbtLayout::record_offset: " + std::string(to_string(kind)) + " record " +
                       std::to_string(index) + " does not exist; the region holds " + std::to_string(r.count) +
                       " records: use an index below that");
    }
    return r.offset + std::uint64_t{index} * r.stride;
  }

  /// Byte offset of a record's data (its shaderRecordEXT block), right after the handle.
  std::uint64_t arguments_offset(SbtRegionKind kind, std::uint32_t index) const {
    return record_offset(kind, index) + properties.handle_size;
  }
};

namespace detail {
constexpr bool is_power_of_two(std::uint64_t v) { return v != 0 && (v & (v - 1)) == 0; }
constexpr std::uint64_t align_up(std::uint64_t v, std::uint64_t a) { return (v + a - 1) / a * a; }
}  // namespace detail

/// Lays out the four regions; throws UsageError for impossible properties and DeviceLimitError
/// when a record stride exceeds the device's maximum.
PROCEDURAY_DECL SbtLayout layout_sbt(const SbtProperties& props, const std::array<SbtRegionRecords, 4>& records);

}  // namespace proceduray

#include "proceduray/scene/sbt_layout-inl.hpp"  // the bodies (config.hpp)
