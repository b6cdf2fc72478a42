#include "tests/docs/vk/vk_names.hpp"
using namespace doc_vk;
inline const proceduray::GeometryDesc sphere_geometry = proceduray::GeometryDesc::procedural({{glm::vec3(-1), glm::vec3(1)}});
// @declarations
void usage(const proceduray::vk::Context& ctx, const proceduray::vk::RendererOptions& options) {
  // @statements
}
