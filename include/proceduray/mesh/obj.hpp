// Wavefront OBJ files as triangle meshes with normals and texture coordinates, read by Debian's
// tinyobjloader (libtinyobjloader-dev: a maintained parser of the whole format, relative
// indices and polygons included, so none is written here).
//
//   proceduray::ObjMesh mesh = proceduray::load_obj("models/ship.obj");   // every shape, one mesh
//   scene.add_geometry("ship", proceduray::GeometryDesc::triangles(mesh.triangles()));
//   mesh.normals[i];          // unit length, one per vertex (computed when the file has none)
//   if (mesh.has_uvs()) mesh.uvs[i];
//   proceduray::ObjMesh quad = proceduray::parse_obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n", "quad");
//   proceduray::GeometryDesc smooth = proceduray::GeometryDesc::triangles(mesh.triangles());
//   smooth.vertex_data = mesh.vertex_data();   // ObjVertex per vertex: MeshRef<ObjVertex> in its records
//
// A vertex is one distinct (position, normal, texture coordinate) triple of the file, so a cube
// with a normal per face has 24 vertices. Normals the file lacks (any corner without `vn`) are
// computed for the whole mesh: at each point, the sum of the normals of the triangles around it
// weighted by their angle there, normalised (smooth shading; positions with equal coordinates are one
// point, so seams and poles stay smooth; a point whose triangles have no area gets +Z). Bad content throws InvalidGeometryError naming the file, the face and the fix;
// a file that cannot be read throws EnvironmentError.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/scene/geometry.hpp>
#include <proceduray/scene/vertex_data.hpp>
#include <proceduray/shader/field_list.hpp>

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

namespace proceduray {

/// One vertex of an ObjMesh as hit shaders read it (GLSL struct ObjVertex, through MeshRef<ObjVertex>).
struct ObjVertex {
  glm::vec3 position;
  glm::vec3 normal;  ///< unit length
  glm::vec2 uv;      ///< (0, 0) when the file has no texture coordinates
};
PROCEDURAY_STRUCT(ObjVertex, scalar, position, normal, uv);

/// A triangle mesh with per-vertex normals and (when the file has them) texture coordinates.
struct ObjMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;      ///< one per position, unit length
  std::vector<glm::vec2> uvs;          ///< one per position when every corner has a `vt`, else empty
  std::vector<std::uint32_t> indices;  ///< three per triangle, counter-clockwise as in the file
  bool normals_computed = false;       ///< the file lacked normals; they were computed (see above)

  bool has_uvs() const noexcept { return !uvs.empty(); }
  std::uint32_t triangle_count() const noexcept { return static_cast<std::uint32_t>(indices.size() / 3); }
  /// The positions and indices, for the BLAS (GeometryDesc::triangles).
  TriangleMesh triangles() const { return {positions, indices}; }
  /// Position, normal and texture coordinate per vertex, for GeometryDesc::vertex_data.
  VertexData vertex_data() const {
    std::vector<ObjVertex> v(positions.size());
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = {positions[i], normals[i], has_uvs() ? uvs[i] : glm::vec2(0.0f)};
    return VertexData::of(std::span<const ObjVertex>(v));
  }
};

/// Reads an OBJ file (materials are ignored); polygons are split into triangles.
PROCEDURAY_DECL ObjMesh load_obj(const std::filesystem::path& path);
/// Parses OBJ text; `name` stands for the file in messages.
PROCEDURAY_DECL ObjMesh parse_obj(std::string_view text, std::string_view name = "OBJ text");

}  // namespace proceduray

#include "proceduray/mesh/obj-inl.hpp"  // the bodies (config.hpp)
