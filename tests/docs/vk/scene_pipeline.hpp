#include "tests/docs/vk/vk_names.hpp"
using namespace doc_vk;

// @declarations
void usage(const proceduray::vk::Context& ctx, const proceduray::Plan& plan, const proceduray::vk::Bindings& bindings,
           const std::vector<proceduray::StageTraces>& traces) {
  // @statements
}
