#include "tests/docs/vk/vk_names.hpp"
using namespace doc_vk;

// @declarations
void usage(const proceduray::vk::Context& ctx, const DocScene& scene, const SceneConstants& constants, std::span<const Tint> tints, const FrameKnobs& knobs, proceduray::GeometryId pacman, const glm::mat4& moved, const glm::mat4& placed, proceduray::GeometryId blob, proceduray::Aabb box, std::span<std::uint8_t> my_pixels, const proceduray::TextureSlot& ground_slot, const proceduray::TextureData& ground) {
  // @statements
}
