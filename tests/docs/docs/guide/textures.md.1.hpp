// docs/guide/textures.md's ```cpp block (textures).
#include "tests/docs/vk/vk_names.hpp"
namespace pr = proceduray;
using namespace doc_vk;
// @declarations
void usage(DocScene& scene, pr::vk::Renderer& renderer, const pr::Binding& tlas_binding,
           const pr::Binding& image_binding, const pr::Binding& constants) {
  // @statements
}
