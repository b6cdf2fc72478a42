#include "tests/docs/vk/vk_names.hpp"
using namespace doc_vk;

// @declarations
void usage(const proceduray::vk::Context& ctx, const std::array<std::filesystem::path, 6>& faces) {
  // @statements
}
