// docs/guide/renderer.md's ```cpp block (the frame loop).
#include "tests/docs/vk/vk_names.hpp"
namespace pr = proceduray;
using namespace doc_vk;
// @declarations
SceneConstants constants_at(int frame);
void usage(pr::vk::Renderer& renderer) {
  // @statements
}
