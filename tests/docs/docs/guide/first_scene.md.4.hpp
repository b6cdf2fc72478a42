// docs/guide/first_scene.md's fourth ```cpp block (the renderer).
#include "tests/docs/docs/first_scene_names.hpp"
namespace pr = proceduray;
using namespace doc_first_scene;
// @declarations
void usage(const pr::Scene<Interface>& scene) {
  // @statements
}
