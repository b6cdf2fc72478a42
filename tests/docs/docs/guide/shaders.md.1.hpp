// docs/guide/shaders.md's ```cpp block (a scene's generator program).
#include "tests/docs/vk/vk_names.hpp"
using namespace doc_vk;
// @declarations
void usage() {
  // @statements
}
