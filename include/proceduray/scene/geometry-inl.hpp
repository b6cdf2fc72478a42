// The bodies of proceduray/scene/geometry.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/geometry.hpp"

#if PROCEDURAY_BODIES
namespace proceduray {

PROCEDURAY_DECL const char* to_string(GeometryKind kind) { return kind == GeometryKind::triangles ? "triangles" : "procedural"; }

PROCEDURAY_DECL const char* to_string(UpdatePolicy policy) {
  constexpr const char* names[] = {"Static", "DynamicTransform", "DynamicGeometry"};
  return names[static_cast<std::uint32_t>(policy)];
}

PROCEDURAY_DECL InstanceTransform instance_transform(const glm::mat4& m) {
  InstanceTransform t;
  for (int r = 0; r < 3; ++r) t[r] = glm::vec4(m[0][r], m[1][r], m[2][r], m[3][r]);
  return t;
}

PROCEDURAY_DECL InstanceTransform identity_transform() { return instance_transform(glm::mat4(1.0f)); }

PROCEDURAY_DECL glm::mat4 matrix_of(const InstanceTransform& t) {
  glm::mat4 m(1.0f);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) m[c][r] = t[r][c];
  return m;
}

}  // namespace proceduray

namespace proceduray::detail {

PROCEDURAY_DECL std::string vec_string(const glm::vec3& v) {
  return std::string("(") + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ")";
}

PROCEDURAY_DECL bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

PROCEDURAY_DECL bool valid_box(const Aabb& box) {
  return finite(box.min) && finite(box.max) && box.min.x <= box.max.x && box.min.y <= box.max.y &&
         box.min.z <= box.max.z;
}

}  // namespace proceduray::detail

namespace proceduray {

PROCEDURAY_DECL void validate(const Aabb& box, std::string_view where) {
  if (!detail::finite(box.min) || !detail::finite(box.max)) {
    throw InvalidGeometryError(std::string(where) + " has non-finite bounds min " + detail::vec_string(box.min) +
                               " max " + detail::vec_string(box.max) + "; give finite bounds (NaN or inf "
                               "breaks BVH builds)");
  }
  if (box.min.x > box.max.x || box.min.y > box.max.y || box.min.z > box.max.z) {
    throw InvalidGeometryError(std::string(where) + " has min " + detail::vec_string(box.min) + " > max " +
                               detail::vec_string(box.max) + "; swap the corners so min <= max on every axis");
  }
}

}  // namespace proceduray

namespace proceduray::detail {

PROCEDURAY_DECL TransformCheck check_transform(const InstanceTransform& t) {
  return check_transform_at([&t](int r, int c) { return t[r][c]; });
}

PROCEDURAY_DECL bool valid_transform(const InstanceTransform& t) {
  const TransformCheck c = check_transform(t);
  return c.row < 0 && !c.singular;
}

}  // namespace proceduray::detail

namespace proceduray {

PROCEDURAY_DECL void validate(const InstanceTransform& t, std::string_view where) {
  const detail::TransformCheck c = detail::check_transform(t);
  if (c.row >= 0) {
    throw InvalidGeometryError(std::string(where) + " has a non-finite element at row " + std::to_string(c.row) +
                               " column " + std::to_string(c.column) + " (" + std::to_string(t[c.row][c.column]) +
                               "); give a finite affine transform");
  }
  if (c.singular) {
    char determinant[32];
    std::snprintf(determinant, sizeof determinant, "%g", c.determinant);
    throw InvalidGeometryError(std::string(where) + " is singular (determinant " + determinant +
                               "); an instance needs an invertible 3x3 part with |determinant| >= 1e-30 and "
                               ">= 1e-9 x its largest element cubed: check for a zero or tiny (< 1e-10) scale");
  }
}

PROCEDURAY_DECL void validate(const GeometryDesc& desc, std::string_view id, std::string_view operation) {
  // Messages are built only on failure: registering a million geometries must not format a million strings.
  auto place = [&] { return std::string(operation) + ": geometry \"" + std::string(id) + "\""; };
  if (desc.kind == GeometryKind::procedural) {
    if (desc.aabbs.empty()) {
      throw InvalidGeometryError(place() + " is procedural with no AABB; give it at least one box");
    }
    if (!desc.mesh.vertices.empty() || !desc.mesh.indices.empty() || desc.vertex_data) {
      throw InvalidGeometryError(place() + " is procedural but has a triangle mesh or vertex data; use kind = triangles "
                                 "or drop them");
    }
    for (std::size_t i = 0; i < desc.aabbs.size(); ++i) {
      if (!detail::valid_box(desc.aabbs[i])) validate(desc.aabbs[i], place() + " AABB " + std::to_string(i));
    }
  } else {
    const TriangleMesh& m = desc.mesh;
    if (m.indices.empty() || m.indices.size() % 3 != 0) {
      throw InvalidGeometryError(place() + " has " + std::to_string(m.indices.size()) +
                                 " indices; a triangle list needs a non-zero multiple of 3");
    }
    if (!desc.aabbs.empty()) {
      throw InvalidGeometryError(place() + " is triangles but has AABBs; use kind = procedural or drop the AABBs");
    }
    if (desc.vertex_data && desc.vertex_data.count != m.vertices.size()) {
      throw InvalidGeometryError(place() + " has vertex data for " + std::to_string(desc.vertex_data.count) +
                                 " vertices but " + std::to_string(m.vertices.size()) + " positions; give one " +
                                 std::string(desc.vertex_data.type->glsl_name) + " per position, in the same order");
    }
    for (std::size_t i = 0; i < m.indices.size(); ++i) {
      if (m.indices[i] >= m.vertices.size()) {
        throw InvalidGeometryError(place() + " index " + std::to_string(i) + " is " + std::to_string(m.indices[i]) +
                                   " but there are " + std::to_string(m.vertices.size()) + " vertices; fix the index buffer");
      }
    }
    for (std::size_t i = 0; i < m.vertices.size(); ++i) {
      if (!detail::finite(m.vertices[i])) {
        throw InvalidGeometryError(place() + " vertex " + std::to_string(i) + " is " + detail::vec_string(m.vertices[i]) +
                                   "; give finite positions");
      }
    }
  }
  if (!desc.instance_masks.empty() && desc.instance_masks.size() != desc.instances.size()) {
    throw InvalidGeometryError(place() + " has " + std::to_string(desc.instance_masks.size()) + " instance masks for " +
                               std::to_string(desc.instances.size()) + " instances; give one mask per instance, or "
                               "none and set `mask` for all");
  }
  const auto check_mask = [&](std::uint32_t mask, const std::string& what) {
    if (mask > 0xFFu) {
      throw InvalidGeometryError(place() + " " + what + " is 0x" + detail::hex(mask) +
                                 ", more than Vulkan's 8 instance-mask bits; use layer bits (Scene::layer_mask), 0..0xFF");
    }
  };
  check_mask(desc.mask, "mask");
  for (std::size_t i = 0; i < desc.instance_masks.size(); ++i) {
    check_mask(desc.instance_masks[i], "instance mask " + std::to_string(i));
  }
  if (static_cast<std::uint32_t>(desc.update) > static_cast<std::uint32_t>(UpdatePolicy::DynamicGeometry)) {
    throw InvalidGeometryError(place() + " has update policy " + std::to_string(static_cast<std::uint32_t>(desc.update)) +
                               "; use UpdatePolicy::Static, DynamicTransform or DynamicGeometry");
  }
  for (std::size_t i = 0; i < desc.instances.size(); ++i) {
    if (!detail::valid_transform(desc.instances[i])) {
      validate(desc.instances[i], place() + " instance " + std::to_string(i) + " transform");
    }
  }
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
