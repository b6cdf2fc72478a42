// docs/guide/first_scene.md's third ```cpp block (the scene).
#include "tests/docs/docs/first_scene_names.hpp"
namespace pr = proceduray;
using namespace doc_first_scene;
// @declarations
void usage() {
  // @statements
}
