// shader/mesh_ref.hpp: MeshRef<V> is a registered struct named after V, two addresses wide, marked
// so the scene finds it, and its generated accessors interpolate float members only.
#include <proceduray/shader/field_list.hpp>
#include <proceduray/shader/mesh_ref.hpp>

#include <doctest/doctest.h>

#include <string>

namespace mesh_ref_test {
struct Corner {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 uv;
  std::uint32_t material;
  float weight;
};
PROCEDURAY_STRUCT(Corner, scalar, position, normal, uv, material, weight);
struct Packed {  // std430: a vec4 first, so the array stride is 32 both ways
  glm::vec4 colour;
  glm::ivec4 ids;
};
PROCEDURAY_STRUCT(Packed, std430, colour, ids);
struct MeshArgs {
  proceduray::MeshRef<Corner> mesh;
  glm::vec4 tint;
};
PROCEDURAY_STRUCT(MeshArgs, scalar, mesh, tint);
}  // namespace mesh_ref_test

using namespace proceduray;
using mesh_ref_test::Corner;

TEST_CASE("mesh_ref: MeshRef<V> is the struct VMesh of two addresses, marked with its vertex type") {
  const TypeOps& t = type_ops<MeshRef<Corner>>;
  CHECK(t.kind == TypeKind::structure);
  CHECK(t.glsl_name == "CornerMesh");
  static_assert(type_ops<MeshRef<mesh_ref_test::Packed>>.glsl_name == "PackedMesh");
  CHECK(t.cpp_size == 16);
  REQUIRE(t.field_count == 2);
  CHECK(t.fields[0].name == "vertices");
  CHECK(t.fields[0].offset == 0);
  CHECK(t.fields[0].type->pointee() == &type_ops<Corner>);
  CHECK(t.fields[1].name == "triangles");
  CHECK(t.fields[1].offset == 8);
  CHECK(t.fields[1].type->pointee() == &type_ops<glm::uvec3>);
  CHECK(t.mesh_vertex == &type_ops<Corner>);
  CHECK(type_ops<Corner>.mesh_vertex == nullptr);  // only MeshRefs carry the mark
  static_assert(type_ops<DeviceAddress<Corner>>.mesh_vertex == nullptr);
  static_assert(type_ops<mesh_ref_test::MeshArgs>.fields[0].type == &t);
}

TEST_CASE("mesh_ref: declarations read the vertex and triangle buffers through buffer references") {
  const TypeOps* roots[] = {&type_ops<mesh_ref_test::MeshArgs>};
  const std::string glsl = glsl_declarations(roots);
  CHECK(glsl.find("#extension GL_EXT_buffer_reference : require") != std::string::npos);
  CHECK(glsl.find("struct CornerMesh {\n    CornerRef vertices;\n    Uvec3Ref triangles;\n};") != std::string::npos);
  CHECK(glsl.find("buffer_reference_align = 4) buffer CornerRef {\n    Corner data[];") != std::string::npos);
  CHECK(glsl.find("buffer Uvec3Ref {\n    uvec3 data[];") != std::string::npos);
}

TEST_CASE("mesh_ref: accessors interpolate float members and keep the first corner's others") {
  const std::string f = glsl_mesh_functions(type_ops<MeshRef<Corner>>);
  CHECK(f.find("Corner vertex(CornerMesh m, uint i) { return m.vertices.data[i]; }") != std::string::npos);
  CHECK(f.find("uvec3 triangle_indices(CornerMesh m, uint primitive) { return m.triangles.data[primitive]; }") !=
        std::string::npos);
  CHECK(f.find("o.position = a.position * w.x + b.position * w.y + c.position * w.z;") != std::string::npos);
  CHECK(f.find("o.normal = a.normal * w.x") != std::string::npos);
  CHECK(f.find("o.uv = a.uv * w.x") != std::string::npos);
  CHECK(f.find("o.weight = a.weight * w.x") != std::string::npos);
  CHECK(f.find("o.material = a.material;") != std::string::npos);  // an index does not mix
  CHECK(f.find("Corner interpolate(CornerMesh m, uint primitive, vec2 barycentrics)") != std::string::npos);
  // Vulkan's barycentrics (u, v) weigh the second and third corners: w = (1 - u - v, u, v).
  CHECK(f.find("vec3(1.0 - barycentrics.x - barycentrics.y, barycentrics.x, barycentrics.y)") != std::string::npos);
  const std::string packed = glsl_mesh_functions(type_ops<MeshRef<mesh_ref_test::Packed>>);
  CHECK(packed.find("o.ids = a.ids;") != std::string::npos);  // an integer vector does not mix either
  CHECK(packed.find("o.colour = a.colour * w.x") != std::string::npos);
  CHECK(glsl_mesh_functions(type_ops<Corner>).empty());  // not a MeshRef
}
