// The bodies of proceduray/mesh/obj.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/mesh/obj.hpp"

#if PROCEDURAY_BODIES
#include <proceduray/error.hpp>
#include <proceduray/scene/errors.hpp>

#include <tiny_obj_loader.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <tuple>

namespace proceduray {
namespace detail {

/// Which parts every corner has, after checking each index against the file's counts.
struct ObjCorners {
  bool all_normals = true;
  bool all_uvs = true;
};

PROCEDURAY_DECL ObjCorners check_obj_corners(const tinyobj::attrib_t& attrib, const std::vector<tinyobj::shape_t>& shapes,
                                             const std::string& where) {
  const auto positions = static_cast<long long>(attrib.vertices.size() / 3);
  const auto normals = static_cast<long long>(attrib.normals.size() / 3);
  const auto uvs = static_cast<long long>(attrib.texcoords.size() / 2);
  ObjCorners out;
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
      out.all_normals = out.all_normals && i.normal_index >= 0;
      out.all_uvs = out.all_uvs && i.texcoord_index >= 0;
      ++corners;
    }
  }
  if (corners == 0) throw InvalidGeometryError(where + " has no faces (`f` lines); a mesh needs at least one triangle");
  for (float x : attrib.vertices) {
    if (!std::isfinite(x)) throw InvalidGeometryError(where + " has a position that is not finite; fix its `v` line");
  }
  return out;
}

/// Unit normals per vertex where the file gives none: weighted by the triangle's angle at the
/// point (Thürmer and Wüthrich 1998), over every vertex at the same coordinates.
PROCEDURAY_DECL std::vector<glm::vec3> angle_weighted_normals(const std::vector<glm::vec3>& positions,
                                                              const std::vector<std::uint32_t>& indices) {
  // Positions with equal coordinates are one point (exporters repeat them at seams and poles).
  std::map<std::tuple<float, float, float>, std::size_t> point_of_coordinates;
  std::vector<std::size_t> point(positions.size());
  for (std::size_t v = 0; v < positions.size(); ++v) {
    const glm::vec3& p = positions[v];
    point[v] = point_of_coordinates.try_emplace({p.x, p.y, p.z}, point_of_coordinates.size()).first->second;
  }
  // Unlike area weights, angle weights do not depend on how the faces were split into triangles.
  std::vector<glm::vec3> sum(point_of_coordinates.size(), glm::vec3(0.0f));
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const glm::vec3 p[3] = {positions[indices[t]], positions[indices[t + 1]], positions[indices[t + 2]]};
    const glm::vec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
    const float length = glm::length(n);
    if (!(length > 0.0f)) continue;  // no area, no direction
    for (std::size_t k = 0; k < 3; ++k) {
      const glm::vec3 e1 = p[(k + 1) % 3] - p[k], e2 = p[(k + 2) % 3] - p[k];
      const float angle = std::atan2(glm::length(glm::cross(e1, e2)), glm::dot(e1, e2));
      sum[point[indices[t + k]]] += n * (angle / length);
    }
  }
  std::vector<glm::vec3> normals;
  normals.reserve(positions.size());
  for (std::size_t v = 0; v < positions.size(); ++v) {
    const glm::vec3 n = sum[point[v]];
    const float length = glm::length(n);
    normals.push_back(length > 0.0f ? n / length : glm::vec3(0, 0, 1));
  }
  return normals;
}

/// The mesh of a parsed file: corners deduplicated, indices checked, normals completed.
PROCEDURAY_DECL ObjMesh obj_mesh(const tinyobj::attrib_t& attrib, const std::vector<tinyobj::shape_t>& shapes,
                                 std::string_view name) {
  const ObjCorners has = check_obj_corners(attrib, shapes, "load_obj: '" + std::string(name) + "'");
  ObjMesh mesh;
  mesh.normals_computed = !has.all_normals;
  // One vertex per distinct (position, normal, uv) triple; -1 where that part is not used.
  std::map<std::tuple<int, int, int>, std::uint32_t> vertex_of;
  for (const tinyobj::shape_t& shape : shapes) {
    for (const tinyobj::index_t& i : shape.mesh.indices) {
      const std::tuple key(i.vertex_index, has.all_normals ? i.normal_index : -1, has.all_uvs ? i.texcoord_index : -1);
      auto [it, added] = vertex_of.try_emplace(key, static_cast<std::uint32_t>(mesh.positions.size()));
      if (added) {
        const float* p = &attrib.vertices[3 * static_cast<std::size_t>(i.vertex_index)];
        mesh.positions.emplace_back(p[0], p[1], p[2]);
        if (has.all_normals) {
          const float* n = &attrib.normals[3 * static_cast<std::size_t>(i.normal_index)];
          const glm::vec3 v(n[0], n[1], n[2]);
          const float length = glm::length(v);
          mesh.normals.push_back(length > 0.0f && std::isfinite(length) ? v / length : glm::vec3(0, 0, 1));
        }
        if (has.all_uvs) {
          const float* t = &attrib.texcoords[2 * static_cast<std::size_t>(i.texcoord_index)];
          mesh.uvs.emplace_back(t[0], t[1]);
        }
      }
      mesh.indices.push_back(it->second);
    }
  }
  if (!has.all_normals) mesh.normals = angle_weighted_normals(mesh.positions, mesh.indices);
  return mesh;
}

/// What tinyobjloader does not say by itself, checked line by line before it parses: a `v`
/// coordinate that is not a finite number (it reads `nan` as 0) and a face index that is 0 or
/// reaches back (negative) past the start of the file (it reports the resolved value, not the
/// one written). Throws InvalidGeometryError naming the line and the value as written.
PROCEDURAY_DECL void check_obj_lines(const std::string& text, std::string_view name) {
  long long counts[3] = {0, 0, 0};  // v, vt, vn lines so far
  std::istringstream lines(text);
  std::string line;
  for (std::size_t number = 1; std::getline(lines, line); ++number) {
    std::istringstream words(line);
    std::string key;
    words >> key;
    const auto fail = [&](const std::string& what) {
      return InvalidGeometryError("load_obj: '" + std::string(name) + "' line " + std::to_string(number) + ": " + what);
    };
    if (key == "v" || key == "vt" || key == "vn") {
      ++counts[key == "v" ? 0 : key == "vt" ? 1 : 2];
      if (key != "v") continue;
      std::string word;
      for (int c = 0; c < 3 && words >> word; ++c) {
        char* end = nullptr;
        const double x = std::strtod(word.c_str(), &end);
        if (end == word.c_str() || *end != '\0' || !(std::abs(x) <= std::numeric_limits<float>::max())) {
          throw fail("position coordinate '" + word + "' is not a finite float; fix its `v` line");
        }
      }
    } else if (key == "f") {
      static constexpr const char* kinds[3] = {"position (`v`)", "texture coordinate (`vt`)", "normal (`vn`)"};
      for (std::string corner; words >> corner;) {
        std::istringstream parts(corner);
        std::string part;
        for (int k = 0; k < 3 && std::getline(parts, part, '/'); ++k) {
          if (part.empty()) continue;
          const long long index = std::atoll(part.c_str());
          if (index == 0 || (index < 0 && -index > counts[k])) {
            throw fail("face corner '" + corner + "' uses " + kinds[k] + " index " + part + (index == 0 ?
                       ", but OBJ indices start at 1" : ", reaching back past the " + std::to_string(counts[k]) +
                       " defined before it") + "; fix the face's index");
          }
        }
      }
    }
  }
}

/// Parses `text` with tinyobjloader; throws InvalidGeometryError with its message.
PROCEDURAY_DECL ObjMesh parse_obj_text(const std::string& text, std::string_view name) {
  check_obj_lines(text, name);
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
