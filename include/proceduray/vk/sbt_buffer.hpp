// The SBT buffer: group handles and root arguments written where layout_sbt says.
//
//   auto layout = layout_sbt(ctx.sbt_properties(), {{{1, 0}, {1, 0}, {2, sizeof(Colour)}, {}}});
//   std::vector<proceduray::vk::RecordWrite> records{
//       {SbtRegionKind::raygen, 0, /*group*/ 0},
//       {SbtRegionKind::miss, 0, 1},
//       {SbtRegionKind::hit, 0, 2, proceduray::vk::bytes_of(red)},
//       {SbtRegionKind::hit, 1, 2, proceduray::vk::bytes_of(blue)}};
//   proceduray::vk::SbtBuffer sbt(ctx, pipeline, layout, records);
//   sbt.regions();   // the four VkStridedDeviceAddressRegionKHR for vkCmdTraceRaysKHR
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/scene/sbt_layout.hpp>
#include <proceduray/scene/plan.hpp>
#include <proceduray/vk/pipeline.hpp>

#include <array>
#include <span>
#include <type_traits>
#include <vector>

namespace proceduray::vk {

/// The bytes of a trivially copyable value, for root arguments.
template <class T>
std::span<const std::byte> bytes_of(const T& value) {
  static_assert(std::is_trivially_copyable_v<T>, "bytes_of: root arguments must be trivially copyable");
  return std::as_bytes(std::span<const T>(&value, 1));
}

/// One record to write: which region and slot, which pipeline group's handle, and its data.
struct RecordWrite {
  SbtRegionKind region = SbtRegionKind::hit;
  std::uint32_t index = 0;  ///< slot within the region
  std::uint32_t group = 0;  ///< pipeline group whose handle heads the record
  std::span<const std::byte> data{};  ///< shaderRecordEXT bytes; at most the region's max_arguments_size
};

/// A host-visible buffer holding the SBT, its start aligned to shaderGroupBaseAlignment.
class SbtBuffer {
 public:
  SbtBuffer(const Context& ctx, const Pipeline& pipeline, const SbtLayout& layout,
            std::span<const RecordWrite> records);
  /// A compiled scene's table as `layout` places it: its records and data, with `pipeline`'s
  /// handles in plan.pipeline().groups order, and `meshes` (by geometry: MeshBuffers::addresses)
  /// in the records that hold a MeshRef.
  SbtBuffer(const Context& ctx, const Pipeline& pipeline, const proceduray::Plan& plan, const SbtLayout& layout,
            std::span<const MeshAddresses> meshes = {});

  /// Raygen, miss, hit and callable regions with device addresses, in vkCmdTraceRaysKHR's order.
  const std::array<VkStridedDeviceAddressRegionKHR, 4>& regions() const noexcept { return m_regions; }
  const SbtLayout& layout() const noexcept { return m_layout; }
  /// The table's bytes as the device sees them (for tests and printing).
  std::span<const std::byte> bytes() const {
    return {static_cast<const std::byte*>(m_buffer.data()) + m_start, m_layout.size};
  }

 private:
  void place(const Context& ctx);

  SbtLayout m_layout;
  Buffer m_buffer;
  VkDeviceSize m_start = 0;  // bytes skipped so the table starts base-aligned
  std::array<VkStridedDeviceAddressRegionKHR, 4> m_regions{};
};

}  // namespace proceduray::vk

#include "proceduray/vk/sbt_buffer-inl.hpp"  // the bodies (config.hpp)
