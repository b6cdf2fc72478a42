#include <examples/common/set_constants.hpp>
#include "tests/docs/vk/vk_names.hpp"
using namespace doc_vk;
// @declarations
void usage(proceduray::vk::Renderer& renderer, proceduray::UniformSlot<SceneConstants> slot, const SceneConstants& constants) {
  // @statements
}
