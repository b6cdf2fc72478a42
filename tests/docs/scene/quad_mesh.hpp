#include "tests/docs/scene/scene_names.hpp"
using namespace doc_scene;

// @declarations
void usage(DocScene& scene) {
  // @statements
}
