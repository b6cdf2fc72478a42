// The vertex and triangle buffers of a compiled scene's triangle geometries that carry vertex
// data (GeometryDesc::vertex_data), uploaded once, and their device addresses for the MeshRefs
// in hit records (shader/mesh_ref.hpp). The Renderer makes one; SbtBuffer writes the addresses.
//
//   proceduray::vk::MeshBuffers meshes(ctx, plan);          // the plan's vertex data and indices
//   proceduray::vk::SbtBuffer sbt(ctx, pipeline, plan, layout, meshes.addresses());
//   meshes.bytes();                                                 // device memory they hold
//
// Only geometries whose records read a mesh get buffers: vertex data no record reads is not
// uploaded. The buffers hold the data as the plan had it when built.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/scene/plan.hpp>
#include <proceduray/vk/buffer.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace proceduray::vk {

/// Per-geometry vertex and triangle buffers, and their addresses by geometry index.
class MeshBuffers {
 public:
  MeshBuffers(const Context& ctx, const proceduray::Plan& plan);

  /// One per geometry of the scene, by geometry index; zero for those without buffers.
  std::span<const MeshAddresses> addresses() const noexcept { return m_addresses; }
  /// Bytes of every buffer.
  VkDeviceSize bytes() const noexcept { return m_bytes; }

 private:
  std::vector<Buffer> m_buffers;
  std::vector<MeshAddresses> m_addresses;
  VkDeviceSize m_bytes = 0;
};

#if PROCEDURAY_BODIES

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

#endif  // PROCEDURAY_BODIES

}  // namespace proceduray::vk
