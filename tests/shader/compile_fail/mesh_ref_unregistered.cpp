// A MeshRef's vertex type is read through a buffer reference: without a registration there is no
// GLSL struct to read, and no proof that the layouts agree.
// expect: static assertion failed: MeshRef<Vertex>: the vertex type must be registered with PROCEDURAY_STRUCT
#include <proceduray/shader/field_list.hpp>
#include <proceduray/shader/mesh_ref.hpp>

namespace demo {
struct Vertex {
  glm::vec3 position;
};
struct MeshArgs {
  proceduray::MeshRef<Vertex> mesh;
};
inline MeshArgs args{};
}  // namespace demo
