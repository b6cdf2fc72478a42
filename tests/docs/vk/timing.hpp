#include "tests/docs/vk/vk_names.hpp"
#include <proceduray/vk/timing.hpp>
using namespace doc_vk;

// @declarations
void usage(proceduray::vk::Renderer& renderer, std::span<const double> samples) {
  const auto constants = [](std::uint32_t) { return SceneConstants{}; };
  const auto slot = constants_slot;
  // @statements
}
