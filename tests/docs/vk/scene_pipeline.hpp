#include "tests/docs/vk/vk_names.hpp"
using namespace doc_vk;

// @declarations
void usage(const proceduray::vk::Context& ctx, proceduray::Plan& plan, const proceduray::vk::Bindings& bindings) {
  // @statements
}
