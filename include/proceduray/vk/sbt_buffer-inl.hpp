// The bodies of proceduray/vk/sbt_buffer.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/sbt_buffer.hpp"

#if PROCEDURAY_BODIES
namespace proceduray::vk {

PROCEDURAY_DECL void SbtBuffer::place(const Context& ctx) {
  if (m_layout.properties.handle_size != ctx.sbt_properties().handle_size ||
      m_layout.properties.base_alignment != ctx.sbt_properties().base_alignment) {
    throw UsageError("SbtBuffer: the table was laid out for handle size " +
                     std::to_string(m_layout.properties.handle_size) + " and base alignment " +
                     std::to_string(m_layout.properties.base_alignment) + " but " + ctx.name() + " has " +
                     std::to_string(ctx.sbt_properties().handle_size) + " and " +
                     std::to_string(ctx.sbt_properties().base_alignment) +
                     "; lay it out with ctx.sbt_properties() (or build it with ctx.limits())");
  }
  m_buffer = Buffer(ctx, m_layout.size + m_layout.properties.base_alignment,
                    VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT);
  const VkDeviceSize align = m_layout.properties.base_alignment;
  const VkDeviceAddress base = (m_buffer.address() + align - 1) / align * align;
  m_start = base - m_buffer.address();
  for (std::uint32_t k = 0; k < 4; ++k) {
    const SbtRegion& region = m_layout.regions[k];
    m_regions[k] = region.count > 0 ? VkStridedDeviceAddressRegionKHR{base + region.offset, region.stride, region.size}
                                    : VkStridedDeviceAddressRegionKHR{};
  }
}

PROCEDURAY_DECL SbtBuffer::SbtBuffer(const Context& ctx, const Pipeline& pipeline, const proceduray::Plan& plan,
                                     const SbtLayout& layout, std::span<const MeshAddresses> meshes)
    : m_layout(layout) {
  place(ctx);
  if (pipeline.group_count() != plan.pipeline().groups.size()) {
    throw UsageError("SbtBuffer: the pipeline has " + std::to_string(pipeline.group_count()) +
                                " groups but the table's plan has " + std::to_string(plan.pipeline().groups.size()) +
                                "; make the pipeline from the same plan");
  }
  std::vector<std::byte> handles;
  for (std::uint32_t g = 0; g < pipeline.group_count(); ++g) {
    const auto h = pipeline.group_handle(g);
    handles.insert(handles.end(), h.begin(), h.end());
  }
  plan.write(m_layout, {static_cast<std::byte*>(m_buffer.data()) + m_start, m_layout.size}, handles, meshes);
}

PROCEDURAY_DECL SbtBuffer::SbtBuffer(const Context& ctx, const Pipeline& pipeline, const SbtLayout& layout,
                                     std::span<const RecordWrite> records)
    : m_layout(layout) {
  place(ctx);
  std::array<std::vector<bool>, 4> written;
  for (std::uint32_t k = 0; k < 4; ++k) written[k].assign(layout.regions[k].count, false);

  for (const RecordWrite& r : records) {
    const auto k = static_cast<std::uint32_t>(r.region);
    const std::uint64_t at = layout.record_offset(r.region, r.index);  // throws past the region
    const std::uint64_t room = layout.regions[k].stride - layout.properties.handle_size;
    if (r.data.size() > room) {
      throw UsageError("SbtBuffer: " + std::string(to_string(r.region)) + " record " +
                       std::to_string(r.index) + " has " + std::to_string(r.data.size()) +
                       " bytes of data but the layout left room for " + std::to_string(room) +
                       "; lay the table out with the region's largest root arguments");
    }
    if (written[k][r.index]) {
      throw UsageError("SbtBuffer: " + std::string(to_string(r.region)) + " record " +
                       std::to_string(r.index) + " is given twice");
    }
    written[k][r.index] = true;
    const auto handle = pipeline.group_handle(r.group);  // throws for an unknown group
    m_buffer.write(handle, m_start + at);
    if (!r.data.empty()) m_buffer.write(r.data, m_start + at + layout.properties.handle_size);
  }
  for (std::uint32_t k = 0; k < 4; ++k) {
    for (std::uint32_t i = 0; i < layout.regions[k].count; ++i) {
      if (!written[k][i]) {
        throw UsageError("SbtBuffer: " + std::string(to_string(static_cast<SbtRegionKind>(k))) +
                         " record " + std::to_string(i) +
                         " was laid out but never given; a trace reaching it would run no shader");
      }
    }
  }
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
