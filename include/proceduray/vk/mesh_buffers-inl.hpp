// The bodies of proceduray/vk/mesh_buffers.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/mesh_buffers.hpp"

#if PROCEDURAY_BODIES

namespace proceduray::vk {

PROCEDURAY_DECL MeshBuffers::MeshBuffers(const Context& ctx, const proceduray::Plan& plan)
    : m_addresses(plan.geometries().size()) {
  if (!plan.reads_meshes()) return;  // most scenes: no buffers, no per-record scan
  std::vector<bool> read(plan.geometries().size(), false);
  for (const SbtRecord& r : plan.records(SbtRegionKind::hit)) {
    if (r.mesh_offset != no_index) read[r.geometry] = true;
  }
  m_buffers.reserve(2 * static_cast<std::size_t>(std::count(read.begin(), read.end(), true)));  // references stay valid
  constexpr VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
  for (std::uint32_t g = 0; g < read.size(); ++g) {
    if (!read[g]) continue;
    const PlannedGeometry& desc = plan.geometries()[g];
    Buffer& vertices = m_buffers.emplace_back(ctx, desc.vertex_bytes.size(), usage);
    vertices.write(std::span<const std::byte>(desc.vertex_bytes));
    Buffer& triangles = m_buffers.emplace_back(ctx, desc.mesh.indices.size() * sizeof(std::uint32_t), usage);
    triangles.write(std::span<const std::uint32_t>(desc.mesh.indices));
    m_addresses[g] = {vertices.address(), triangles.address()};
    m_bytes += vertices.size() + triangles.size();
  }
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
