#include "tests/docs/vk/vk_names.hpp"
using namespace doc_vk;

// @declarations
void usage(const proceduray::vk::Context& ctx, proceduray::vk::DescriptorSet& set, VkCommandBuffer frame_cmd, const proceduray::vk::Buffer& readback) {
  // @statements
}
