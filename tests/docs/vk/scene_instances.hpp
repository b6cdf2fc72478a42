#include "tests/docs/vk/vk_names.hpp"
using namespace doc_vk;

// @declarations
void usage(const proceduray::vk::Context& ctx, VkCommandBuffer cmd, const proceduray::Plan& plan,
           std::vector<proceduray::vk::Instance> list, proceduray::vk::Tlas& tlas, proceduray::GeometryId ball,
           const glm::mat4& moved, const proceduray::vk::AccelerationStructure& blas) {
  // @statements
}
