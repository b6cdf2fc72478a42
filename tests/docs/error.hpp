#include "tests/docs/vk/vk_names.hpp"
#include <cstdio>
using namespace doc_vk;
// @declarations
void usage(proceduray::vk::Renderer& renderer, proceduray::GeometryId pacman, const glm::mat4& moved) {
  // @statements
}
