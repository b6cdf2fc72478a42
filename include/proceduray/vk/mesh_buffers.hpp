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

}  // namespace proceduray::vk

#include "proceduray/vk/mesh_buffers-inl.hpp"  // the bodies (config.hpp)
