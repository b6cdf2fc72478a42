#include "tests/docs/vk/vk_names.hpp"
#include <cstdio>
using namespace doc_vk;
// @declarations
void usage(proceduray::vk::Renderer& renderer, proceduray::GeometryId pacman, proceduray::InstanceTransform moved) {
  // @statements
}
