#include "tests/docs/vk/vk_names.hpp"
using namespace doc_vk;

// @declarations
void usage(const proceduray::vk::Context& ctx, const proceduray::Plan& plan, const proceduray::vk::SceneAcceleration& structures, const SceneConstants& constants, std::span<const Tint> tints, const FrameKnobs& knobs, const proceduray::vk::StorageImage& image, VkCommandBuffer frame_cmd) {
  // @statements
}
