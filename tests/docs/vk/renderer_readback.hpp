#include "tests/docs/vk/vk_names.hpp"
using namespace doc_vk;

// @declarations
void usage(proceduray::vk::Renderer& renderer, std::span<std::uint8_t> my_pixels) {
  // @statements
}
