#include "tests/docs/vk/vk_names.hpp"
using namespace doc_vk;

// @declarations
void usage(const proceduray::vk::Context& ctx, const proceduray::Plan& plan, std::uint32_t width, std::uint32_t height,
           proceduray::vk::Bindings& bindings, VkCommandBuffer frame_cmd,
           const proceduray::vk::Buffer& readback, VkDeviceSize offset) {
  // @statements
}
