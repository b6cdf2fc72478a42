#include "tests/docs/vk/vk_names.hpp"
using namespace doc_vk;
// @declarations
void usage(const proceduray::vk::RendererOptions& options, std::span<const proceduray::vk::AabbGeometry> geometries) {
  // @statements
}
