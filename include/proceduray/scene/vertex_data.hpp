// A triangle geometry's vertices as hit shaders read them: one registered struct per vertex, in
// the order of TriangleMesh::vertices, uploaded by the renderer and reached through a MeshRef
// (shader/mesh_ref.hpp) in the geometry's hit records.
//
//   struct Vertex { glm::vec3 position; glm::vec3 normal; glm::vec2 uv; };
//   PROCEDURAY_STRUCT(Vertex, scalar, position, normal, uv);
//   std::vector<Vertex> vertices(4);
//   proceduray::GeometryDesc floor = proceduray::GeometryDesc::triangles(mesh);
//   floor.vertex_data = proceduray::VertexData::of(std::span<const Vertex>(vertices));   // one per position
//
// The positions stay in TriangleMesh::vertices: the BLAS is built from them, and the vertex
// struct may repeat them or not. add_geometry refuses vertex data on procedural geometry or with
// a count other than the mesh's (InvalidGeometryError).
#pragma once

#include <proceduray/shader/glsl_type.hpp>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

namespace proceduray {

/// Per-vertex data of a triangle geometry, typed by a registered struct.
struct VertexData {
  const TypeOps* type = nullptr;  ///< the vertex struct; nullptr: the geometry has none
  std::vector<std::byte> bytes;   ///< count * sizeof(vertex), as the struct lies in memory
  std::uint32_t count = 0;        ///< vertices

  /// The vertices of a registered struct type.
  template <class Vertex>
  static VertexData of(std::span<const Vertex> vertices) {
    static_assert(RegisteredStruct<Vertex>,
                  "VertexData::of: the vertex type must be registered with PROCEDURAY_STRUCT, so that its layout "
                  "is proven equal in C++ and GLSL; register it");
    VertexData d{&type_ops<Vertex>, std::vector<std::byte>(vertices.size_bytes()),
                 static_cast<std::uint32_t>(vertices.size())};
    if (!vertices.empty()) std::memcpy(d.bytes.data(), vertices.data(), vertices.size_bytes());
    return d;
  }
  /// True when there is vertex data.
  explicit operator bool() const noexcept { return type != nullptr; }
};

}  // namespace proceduray
