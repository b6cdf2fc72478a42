// Vertex data is typed by a registered struct, so that its layout is proven equal in C++ and GLSL.
// expect: static assertion failed: VertexData::of: the vertex type must be registered with PROCEDURAY_STRUCT
#include <proceduray/scene/vertex_data.hpp>

#include <glm/glm.hpp>

namespace demo {
struct Vertex {
  glm::vec3 position;
};
inline const Vertex corners[3]{};
inline const proceduray::VertexData data = proceduray::VertexData::of(std::span<const Vertex>(corners));
}  // namespace demo
