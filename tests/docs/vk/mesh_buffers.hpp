#include "tests/docs/vk/vk_names.hpp"
using namespace doc_vk;

// @declarations
void usage(const proceduray::vk::Context& ctx, const DocScene& scene, const proceduray::Plan& plan,
           const proceduray::vk::Pipeline& pipeline, const proceduray::SbtLayout& layout) {
  // @statements
}
