// Geometry: triangles (vertices + indices) or procedural (AABBs), its instance transforms and
// masks, its opaque flag, how it changes over time and the BLAS it lives in.
//
//   auto pacman = scene.add_geometry("Pacman", proceduray::GeometryDesc::procedural(
//       {{glm::vec3(-0.5f), glm::vec3(0.5f)}},                       // one AABB
//       {proceduray::instance_transform(glm::translate(glm::mat4(1), {0, 1, 0}))}));
//
// Each geometry gets its own BLAS unless `blas` names one shared with other geometries of
// the same kind; its geometry index is its position in that BLAS (registration order).
// Instances belong to the BLAS: geometries sharing one declare the same instances, or none,
// and the same masks and update policy.
//
// The update policy says what the renderer may rebuild, so it does only that work:
//   Static            built once and compacted; moving or reshaping it is an error
//   DynamicTransform  instances move (Renderer::set_transform): TLAS refit, no BLAS work
//   DynamicGeometry   boxes or vertices change too: BLAS refit for the same primitive count
//                     and indices, BLAS rebuild when the topology changes, then a TLAS update
#pragma once

#include <proceduray/aabb.hpp>
#include <proceduray/config.hpp>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "proceduray/scene/errors.hpp"
#include "proceduray/scene/vertex_data.hpp"

namespace proceduray {

/// Triangles or AABBs; a BLAS holds one kind.
enum class GeometryKind : std::uint32_t { triangles = 0, procedural = 1 };

PROCEDURAY_DECL const char* to_string(GeometryKind kind);

/// How a geometry changes after it is built. CamelCase as engines name them (`static` is a keyword).
enum class UpdatePolicy : std::uint32_t { Static = 0, DynamicTransform = 1, DynamicGeometry = 2 };

PROCEDURAY_DECL const char* to_string(UpdatePolicy policy);

/// A triangle mesh: positions and a triangle list.
struct TriangleMesh {
  std::vector<glm::vec3> vertices;      ///< positions
  std::vector<std::uint32_t> indices;   ///< three per triangle
  friend bool operator==(const TriangleMesh&, const TriangleMesh&) = default;
};

/// An instance's object-to-world transform as Vulkan takes it: the three rows of a 3x4 affine
/// matrix, t[r][c] = row r, column c, memory-identical to VkTransformMatrixKHR, so the TLAS gets
/// these bytes as they are. A struct rather than glm::mat3x4: glm converts any matrix into a
/// mat3x4 implicitly, keeping the first three *columns* of a column-major mat4, which is not its
/// rows; here a glm::mat4 goes in only through instance_transform(), which transposes.
struct InstanceTransform {
  glm::vec4 rows[3]{};  ///< all zero by default (not a valid transform: use identity_transform())

  glm::vec4& operator[](int r) {
    assert(r >= 0 && r < 3 && "InstanceTransform has rows 0..2: t[row][column]");
    return rows[r];
  }
  const glm::vec4& operator[](int r) const {
    assert(r >= 0 && r < 3 && "InstanceTransform has rows 0..2: t[row][column]");
    return rows[r];
  }
  friend bool operator==(const InstanceTransform& a, const InstanceTransform& b) {
    return a.rows[0] == b.rows[0] && a.rows[1] == b.rows[1] && a.rows[2] == b.rows[2];
  }
};
static_assert(sizeof(InstanceTransform) == 12 * sizeof(float), "InstanceTransform must be VkTransformMatrixKHR's 48 bytes");

/// Converts a column-major glm::mat4 (affine: its last row is dropped) to an InstanceTransform.
PROCEDURAY_DECL InstanceTransform instance_transform(const glm::mat4& m);

/// The identity instance transform.
PROCEDURAY_DECL InstanceTransform identity_transform();

/// The affine glm::mat4 of an InstanceTransform (last row (0, 0, 0, 1)), e.g. to transform points.
PROCEDURAY_DECL glm::mat4 matrix_of(const InstanceTransform& t);

/// What the user declares for a geometry.
struct GeometryDesc {
  GeometryKind kind = GeometryKind::procedural;  ///< default: procedural
  TriangleMesh mesh;                             ///< triangles only
  VertexData vertex_data;                        ///< triangles only: what hit shaders read per vertex (MeshRef)
  std::vector<Aabb> aabbs;                       ///< procedural only: one or more boxes
  std::vector<InstanceTransform> instances;      ///< TLAS instances of its BLAS; empty = inherit from the BLAS
  bool opaque = true;                            ///< VK_GEOMETRY_OPAQUE_BIT; default on (any-hit skipped)
  std::string blas;                              ///< BLAS shared with other geometries; empty = its own BLAS
  /// Instance mask of every instance (Layers bits, 0..0xFF); default all. Wider than Vulkan's 8
  /// bits so that 0x100 is refused by name instead of truncating to 0 in the caller.
  std::uint32_t mask = 0xFF;
  std::vector<std::uint32_t> instance_masks;     ///< per-instance masks overriding `mask`; empty or one per instance
  UpdatePolicy update = UpdatePolicy::Static;    ///< what may change after the build; default Static
  /// Keep hit records for instances added at run time (Renderer::add_instance) even when every
  /// declared instance has entries of its own, or none is declared; they then need entries for
  /// the whole geometry or a default hit. Instances without own entries share them anyway.
  bool may_add_instances = false;

  /// A procedural geometry.
  static GeometryDesc procedural(std::vector<Aabb> aabbs, std::vector<InstanceTransform> instances = {identity_transform()}) {
    GeometryDesc d;
    d.kind = GeometryKind::procedural;
    d.aabbs = std::move(aabbs);
    d.instances = std::move(instances);
    return d;
  }
  /// A triangle geometry.
  static GeometryDesc triangles(TriangleMesh mesh, std::vector<InstanceTransform> instances = {identity_transform()}) {
    GeometryDesc d;
    d.kind = GeometryKind::triangles;
    d.mesh = std::move(mesh);
    d.instances = std::move(instances);
    return d;
  }
};

/// A registered geometry.
struct Geometry {
  GeometryDesc desc;               ///< as declared (instances moved to the BLAS)
  std::uint32_t blas = 0;          ///< index of its BLAS in Scene::blases()
  std::uint32_t geometry_index = 0;  ///< position in its BLAS: Vulkan's geometryIndex
};

namespace detail {
PROCEDURAY_DECL std::string vec_string(const glm::vec3& v);
PROCEDURAY_DECL bool finite(const glm::vec3& v);

/// Finite bounds with min <= max on every axis (what validate(Aabb) checks).
PROCEDURAY_DECL bool valid_box(const Aabb& box);
}  // namespace detail

/// Throws InvalidGeometryError for an AABB with min > max or non-finite bounds.
PROCEDURAY_DECL void validate(const Aabb& box, std::string_view where);

namespace detail {
/// What validate(InstanceTransform) finds: the first non-finite element (row -1: none) and the determinant.
struct TransformCheck {
  int row = -1, column = -1;
  double determinant = 0.0;
  bool singular = false;
};

/// Below this |determinant| a transform is singular whatever its scale (see check_transform_at).
inline constexpr double min_transform_determinant = 1e-30;
/// Below this fraction of largest^3, |determinant| is singular: the 3x3 part is nearly flat.
inline constexpr double min_relative_determinant = 1e-9;

/// The one rule for an instance's 3x4 object-to-world matrix, element (row r, column c) = at(r, c);
/// the scene (add_geometry) and the backend (Renderer::set_transform, vk::build_tlas) both apply it.
/// Singular when |det| <= 1e-9 * largest^3 (relative: a nearly flat matrix at any unit of length)
/// or |det| < 1e-30 (absolute: the device inverts the matrix in float; this keeps det and 1/det
/// normal floats with margin, and refuses uniform scales below ~1e-10, such as 1e-11, which the
/// relative test alone accepts). The floor is the backend's former rule, so the union of the two
/// former rules: a transform both accepted is still accepted. No allocation, no formatting.
template <class At>
TransformCheck check_transform_at(At at) {
  TransformCheck out;
  float largest = 0.0f;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) {
      const float v = at(r, c);
      if (!std::isfinite(v)) {
        out.row = r;
        out.column = c;
        return out;
      }
      if (c < 3) largest = std::max(largest, std::fabs(v));
    }
  }
  const glm::mat3 linear{at(0, 0), at(1, 0), at(2, 0), at(0, 1), at(1, 1), at(2, 1), at(0, 2), at(1, 2), at(2, 2)};
  out.determinant = glm::determinant(linear);
  const double scale = double{largest} * largest * largest;
  const double magnitude = std::fabs(out.determinant);
  out.singular = !(magnitude > min_relative_determinant * scale) || !(magnitude >= min_transform_determinant);
  return out;
}
PROCEDURAY_DECL TransformCheck check_transform(const InstanceTransform& t);
/// Finite and invertible: validate(InstanceTransform) would not throw.
PROCEDURAY_DECL bool valid_transform(const InstanceTransform& t);
}  // namespace detail

/// Throws InvalidGeometryError for a non-finite or singular transform (detail::check_transform_at's rule).
PROCEDURAY_DECL void validate(const InstanceTransform& t, std::string_view where);

/// Throws InvalidGeometryError for an empty or out-of-range mesh, no AABBs, a bad AABB or transform.
PROCEDURAY_DECL void validate(const GeometryDesc& desc, std::string_view id, std::string_view operation);

}  // namespace proceduray

#include "proceduray/scene/geometry-inl.hpp"  // the bodies (config.hpp)
