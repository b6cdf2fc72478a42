// A triangle mesh's vertex and triangle data as a hit shader reads them: two buffer device
// addresses in a record, which the renderer fills, and GLSL accessors generated for the vertex type.
//
//   struct Vertex { glm::vec3 position; glm::vec3 normal; glm::vec2 uv; };
//   PROCEDURAY_STRUCT(Vertex, scalar, position, normal, uv);
//   struct MeshArgs { proceduray::MeshRef<Vertex> mesh; glm::vec4 tint; };   // a root arguments type
//   PROCEDURAY_STRUCT(MeshArgs, scalar, mesh, tint);
//   std::string glsl = proceduray::glsl_mesh_functions(proceduray::type_ops<proceduray::MeshRef<Vertex>>);
//   // GLSL (compile() adds these for every MeshRef in a record):
//   //   struct VertexMesh { VertexRef vertices; Uvec3Ref triangles; };
//   //   Vertex vertex(VertexMesh m, uint i);                         m.vertices.data[i]
//   //   uvec3  triangle_indices(VertexMesh m, uint primitive);       m.triangles.data[primitive]
//   //   Vertex interpolate(Vertex a, Vertex b, Vertex c, vec3 w);   float members: a*w.x + b*w.y + c*w.z
//   //   Vertex interpolate(VertexMesh m, uint primitive, vec2 barycentrics);   at a triangle hit
//   // in a closest-hit shader: Vertex v = interpolate(arguments.mesh, gl_PrimitiveID, bary);
//
// The vertex type is any registered struct, so its layout is checked on both sides like every
// other struct; an unregistered one does not compile. Interpolation mixes float (and double)
// scalars, vectors and matrices; other members (integers, addresses, arrays, nested structs)
// take the first corner's value. A triangle geometry gives its vertices in GeometryDesc::vertex_data.
#pragma once

#include <proceduray/shader/device_address.hpp>
#include <proceduray/shader/glsl_codegen.hpp>
#include <proceduray/shader/glsl_type.hpp>

#include <glm/glm.hpp>

#include <array>
#include <cstddef>
#include <string>
#include <string_view>

namespace proceduray {

/// Device addresses of one triangle geometry's vertices (Vertex, in GeometryDesc::vertex_data
/// order) and triangles (three indices each, GeometryDesc::mesh.indices): put one in a hit
/// record's root arguments, and the renderer writes the geometry's buffers into it.
template <class Vertex>
struct MeshRef {
  static_assert(RegisteredStruct<Vertex>,
                "MeshRef<Vertex>: the vertex type must be registered with PROCEDURAY_STRUCT (its GLSL struct "
                "is read through a buffer reference); register it before using MeshRef");
  using vertex_type = Vertex;
  DeviceAddress<Vertex> vertices;
  DeviceAddress<glm::uvec3> triangles;
};

namespace detail {

/// "<Vertex>Mesh", the GLSL name of MeshRef<Vertex>, as static storage.
template <class Vertex>
struct MeshRefName {
  static constexpr std::string_view base = FieldsOf<Vertex>::glsl_name;
  static constexpr std::string_view suffix = "Mesh";
  static constexpr std::array<char, base.size() + suffix.size()> chars = [] {
    std::array<char, base.size() + suffix.size()> out{};
    for (std::size_t i = 0; i < base.size(); ++i) out[i] = base[i];
    for (std::size_t i = 0; i < suffix.size(); ++i) out[base.size() + i] = suffix[i];
    return out;
  }();
  static constexpr std::string_view value{chars.data(), chars.size()};
};

/// The field list of MeshRef<Vertex>, as PROCEDURAY_STRUCT would write it.
template <class Vertex>
struct MeshRefFields {
  static constexpr std::string_view glsl_name = MeshRefName<Vertex>::value;
  static constexpr LayoutRule rule = LayoutRule::scalar;
  static constexpr Field fields[] = {
      {"vertices", offsetof(MeshRef<Vertex>, vertices), sizeof(DeviceAddress<Vertex>), &type_ops<DeviceAddress<Vertex>>},
      {"triangles", offsetof(MeshRef<Vertex>, triangles), sizeof(DeviceAddress<glm::uvec3>),
       &type_ops<DeviceAddress<glm::uvec3>>}};
};

/// `weight` applied to member `name` of a, b and c, or a's value for members that do not mix.
inline std::string mixed_member(const TypeOps& type, std::string_view name) {
  const std::string n(name);
  const bool mixes = (type.kind == TypeKind::scalar || type.kind == TypeKind::vector || type.kind == TypeKind::matrix) &&
                     (type.glsl_name.starts_with("float") || type.glsl_name.starts_with("double") ||
                      type.glsl_name.starts_with("vec") || type.glsl_name.starts_with("dvec") ||
                      type.glsl_name.starts_with("mat") || type.glsl_name.starts_with("dmat"));
  if (!mixes) return "    o." + n + " = a." + n + ";\n";
  return "    o." + n + " = a." + n + " * w.x + b." + n + " * w.y + c." + n + " * w.z;\n";
}

}  // namespace detail

/// MeshRef's registration: found by argument-dependent lookup like PROCEDURAY_STRUCT's.
template <class Vertex>
detail::MeshRefFields<Vertex> proceduray_fields(detail::TypeTag<MeshRef<Vertex>>) {
  return {};
}

/// The accessors of one MeshRef type (`mesh`: type_ops<MeshRef<V>>): vertex, triangle_indices and
/// the two interpolate overloads, for V's struct. Empty for a type that is no MeshRef.
inline std::string glsl_mesh_functions(const TypeOps& mesh) {
  if (mesh.mesh_vertex == nullptr) return {};
  const TypeOps& v = *mesh.mesh_vertex;
  const std::string m(mesh.glsl_name), vt(v.glsl_name);
  std::string out = vt + " vertex(" + m + " m, uint i) { return m.vertices.data[i]; }\n";
  out += "uvec3 triangle_indices(" + m + " m, uint primitive) { return m.triangles.data[primitive]; }\n";
  out += vt + " interpolate(" + vt + " a, " + vt + " b, " + vt + " c, vec3 w) {\n    " + vt + " o;\n";
  for (std::size_t i = 0; i < v.field_count; ++i) {
    out += detail::mixed_member(*v.fields[i].type, v.fields[i].name);  // an array's kind is array: kept whole
  }
  out += "    return o;\n}\n";
  out += vt + " interpolate(" + m + " m, uint primitive, vec2 barycentrics) {\n"
         "    uvec3 t = triangle_indices(m, primitive);\n"
         "    return interpolate(vertex(m, t.x), vertex(m, t.y), vertex(m, t.z),\n"
         "                       vec3(1.0 - barycentrics.x - barycentrics.y, barycentrics.x, barycentrics.y));\n}\n";
  return out;
}

}  // namespace proceduray
