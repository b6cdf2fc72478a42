#include "tests/docs/vk/vk_names.hpp"
using namespace doc_vk;

// @declarations
void usage(const proceduray::vk::Context& ctx, const DocScene& scene, const proceduray::Plan& plan, proceduray::GeometryId ball, const glm::mat4& moved, proceduray::GeometryId blob, std::span<const proceduray::Aabb> boxes) {
  // @statements
}
