#include "tests/docs/vk/vk_names.hpp"
using namespace doc_vk;

// @declarations
void usage(const proceduray::vk::Context& ctx, const proceduray::Scene& scene, const proceduray::Plan& plan,
           const proceduray::vk::Pipeline& pipeline, const proceduray::SbtLayout& layout) {
  // @statements
}
