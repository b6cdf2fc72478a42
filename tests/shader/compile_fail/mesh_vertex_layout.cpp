// A vertex struct whose C++ layout differs from GLSL's is refused where it is registered, before
// any MeshRef reads it: after two floats, C++ puts a dvec2 at offset 8 and std430 at 16.
// expect: the C++ offset or inner layout differs from the std430 layout
#include <proceduray/shader/field_list.hpp>
#include <proceduray/shader/mesh_ref.hpp>

namespace demo {
struct Vertex {
  float weight;
  float pad;
  glm::dvec2 uv;
  glm::vec3 normal;
};
PROCEDURAY_STRUCT(Vertex, std430, weight, pad, uv, normal);
struct MeshArgs {
  proceduray::MeshRef<Vertex> mesh;
};
PROCEDURAY_STRUCT(MeshArgs, scalar, mesh);
}  // namespace demo
