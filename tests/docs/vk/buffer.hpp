#include "tests/docs/vk/vk_names.hpp"
using namespace doc_vk;

// @declarations
void usage(const proceduray::vk::Context& ctx, std::span<const VkAabbPositionsKHR> boxes, VkDeviceSize bytes) {
  // @statements
}
