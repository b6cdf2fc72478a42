// The bodies of proceduray/scene/sbt_layout.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/sbt_layout.hpp"

#if PROCEDURAY_BODIES
namespace proceduray {

PROCEDURAY_DECL const char* to_string(SbtRegionKind kind) {
  constexpr const char* names[] = {"raygen", "miss", "hit", "callable"};
  return names[static_cast<std::uint32_t>(kind)];
}

PROCEDURAY_DECL SbtLayout layout_sbt(const SbtProperties& props, const std::array<SbtRegionRecords, 4>& records) {
  using detail::align_up;
  using detail::is_power_of_two;
  if (props.handle_size == 0 || !is_power_of_two(props.handle_alignment) || !is_power_of_two(props.base_alignment) ||
      props.base_alignment < props.handle_alignment) {
    throw UsageError(
        "layout_sbt: device properties handle_size " + std::to_string(props.handle_size) + ", handle_alignment " +
        std::to_string(props.handle_alignment) + ", base_alignment " + std::to_string(props.base_alignment) +
        " are impossible; alignments must be powers of two with handle_alignment <= base_alignment "
        "(read them from VkPhysicalDeviceRayTracingPipelinePropertiesKHR)");
  }
  if (records[0].count == 0) {
    throw UsageError("layout_sbt: the raygen region is empty; a trace needs one raygen record: add one");
  }
  SbtLayout layout;
  layout.properties = props;
  std::uint64_t cursor = 0;
  for (std::uint32_t k = 0; k < 4; ++k) {
    const auto kind = static_cast<SbtRegionKind>(k);
    const SbtRegionRecords& in = records[k];
    SbtRegion& out = layout.regions[k];
    out.count = in.count;
    if (in.count == 0) continue;
    const std::uint64_t record = std::uint64_t{props.handle_size} + in.max_arguments_size;
    out.stride = align_up(record, kind == SbtRegionKind::raygen ? props.base_alignment : props.handle_alignment);
    if (out.stride > props.max_stride) {
      throw DeviceLimitError("layout_sbt: " + std::string(to_string(kind)) + " record stride " +
                             std::to_string(out.stride) + " bytes (handle " + std::to_string(props.handle_size) +
                             " + data " + std::to_string(in.max_arguments_size) + ", aligned) exceeds the device's "
                             "maxShaderGroupStride " + std::to_string(props.max_stride) +
                             "; move large root arguments into a buffer and store its device address instead");
    }
    out.offset = align_up(cursor, props.base_alignment);
    // Vulkan requires the raygen region's size to equal its stride: a trace reads one raygen record.
    out.size = kind == SbtRegionKind::raygen ? out.stride : out.stride * in.count;
    cursor = out.offset + out.stride * in.count;
  }
  layout.size = cursor;
  return layout;
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
