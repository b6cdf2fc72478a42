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

#if PROCEDURAY_BODIES

#include <proceduray/error.hpp>
#include <proceduray/scene/errors.hpp>

#include <tiny_obj_loader.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <tuple>

namespace proceduray {
namespace detail {

/// The mesh of a parsed file: corners deduplicated, indices checked, normals completed.
PROCEDURAY_DECL ObjMesh obj_mesh(const tinyobj::attrib_t& attrib, const std::vector<tinyobj::shape_t>& shapes,
                                 std::string_view name) {
  const auto positions = static_cast<long long>(attrib.vertices.size() / 3);
  const auto normals = static_cast<long long>(attrib.normals.size() / 3);
  const auto uvs = static_cast<long long>(attrib.texcoords.size() / 2);
  const std::string where = "load_obj: '" + std::string(name) + "'";
  bool all_normals = true, all_uvs = true;
  std::size_t corners = 0;
  for (const tinyobj::shape_t& shape : shapes) {
    for (std::size_t c = 0; c < shape.mesh.indices.size(); ++c) {
      const tinyobj::index_t& i = shape.mesh.indices[c];
      const auto check = [&](int index, long long count, const char* what, const char* line) {
        if (index >= 0 && index < count) return;
        throw InvalidGeometryError(where + " shape \"" + shape.name + "\" face " + std::to_string(c / 3 + 1) + " uses " +
                                   what + " " + std::to_string(index + 1) + " but the file has " +
                                   std::to_string(count) + " (`" + line + "` lines); fix the face's index or add the " +
                                   what);
      };
      check(i.vertex_index, positions, "position", "v");
      if (i.normal_index >= 0) check(i.normal_index, normals, "normal", "vn");
      if (i.texcoord_index >= 0) check(i.texcoord_index, uvs, "texture coordinate", "vt");
      all_normals = all_normals && i.normal_index >= 0;
      all_uvs = all_uvs && i.texcoord_index >= 0;
      ++corners;
    }
  }
  if (corners == 0) throw InvalidGeometryError(where + " has no faces (`f` lines); a mesh needs at least one triangle");
  for (float x : attrib.vertices) {
    if (!std::isfinite(x)) throw InvalidGeometryError(where + " has a position that is not finite; fix its `v` line");
  }
  ObjMesh mesh;
  mesh.normals_computed = !all_normals;
  // One vertex per distinct (position, normal, uv) triple; -1 where that part is not used.
  std::map<std::tuple<int, int, int>, std::uint32_t> vertex_of;
  for (const tinyobj::shape_t& shape : shapes) {
    for (const tinyobj::index_t& i : shape.mesh.indices) {
      const std::tuple key(i.vertex_index, all_normals ? i.normal_index : -1, all_uvs ? i.texcoord_index : -1);
      auto [it, added] = vertex_of.try_emplace(key, static_cast<std::uint32_t>(mesh.positions.size()));
      if (added) {
        const float* p = &attrib.vertices[3 * static_cast<std::size_t>(i.vertex_index)];
        mesh.positions.emplace_back(p[0], p[1], p[2]);
        if (all_normals) {
          const float* n = &attrib.normals[3 * static_cast<std::size_t>(i.normal_index)];
          const glm::vec3 v(n[0], n[1], n[2]);
          const float length = glm::length(v);
          mesh.normals.push_back(length > 0.0f && std::isfinite(length) ? v / length : glm::vec3(0, 0, 1));
        }
        if (all_uvs) {
          const float* t = &attrib.texcoords[2 * static_cast<std::size_t>(i.texcoord_index)];
          mesh.uvs.emplace_back(t[0], t[1]);
        }
      }
      mesh.indices.push_back(it->second);
    }
  }
  if (!all_normals) {
    // Positions with equal coordinates are one point (exporters repeat them at seams and poles).
    std::map<std::tuple<float, float, float>, std::size_t> point_of_coordinates;
    std::vector<std::size_t> point(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      const glm::vec3& p = mesh.positions[v];
      point[v] = point_of_coordinates.try_emplace({p.x, p.y, p.z}, point_of_coordinates.size()).first->second;
    }
    // Weighted by the triangle's angle at the point (Thürmer and Wüthrich 1998): unlike area
    // weights, the result does not depend on how the faces were split into triangles.
    std::vector<glm::vec3> sum(point_of_coordinates.size(), glm::vec3(0.0f));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const glm::vec3 p[3] = {mesh.positions[mesh.indices[t]], mesh.positions[mesh.indices[t + 1]],
                              mesh.positions[mesh.indices[t + 2]]};
      const glm::vec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
      const float length = glm::length(n);
      if (!(length > 0.0f)) continue;  // no area, no direction
      for (std::size_t k = 0; k < 3; ++k) {
        const glm::vec3 e1 = p[(k + 1) % 3] - p[k], e2 = p[(k + 2) % 3] - p[k];
        const float angle = std::atan2(glm::length(glm::cross(e1, e2)), glm::dot(e1, e2));
        sum[point[mesh.indices[t + k]]] += n * (angle / length);
      }
    }
    mesh.normals.reserve(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      const glm::vec3 n = sum[point[v]];
      const float length = glm::length(n);
      mesh.normals.push_back(length > 0.0f ? n / length : glm::vec3(0, 0, 1));
    }
  }
  return mesh;
}

/// Parses `text` with tinyobjloader; throws InvalidGeometryError with its message.
PROCEDURAY_DECL ObjMesh parse_obj_text(const std::string& text, std::string_view name) {
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(text, std::string(), config) || !reader.Valid()) {
    std::string message = reader.Error();
    while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
    throw InvalidGeometryError("load_obj: '" + std::string(name) + "' is not a valid OBJ file: " +
                               (message.empty() ? std::string("tinyobjloader gave no reason") : message));
  }
  return obj_mesh(reader.GetAttrib(), reader.GetShapes(), name);
}

}  // namespace detail

PROCEDURAY_DECL ObjMesh parse_obj(std::string_view text, std::string_view name) {
  return detail::parse_obj_text(std::string(text), name);
}

PROCEDURAY_DECL ObjMesh load_obj(const std::filesystem::path& path) {
  // Read here rather than by tinyobjloader, so a missing file is told apart from a bad one.
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw EnvironmentError("load_obj: cannot read '" + path.string() +
                           "'; check the path (relative paths start at the working directory)");
  }
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw EnvironmentError("load_obj: reading '" + path.string() + "' failed");
  return detail::parse_obj_text(text, path.string());
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
