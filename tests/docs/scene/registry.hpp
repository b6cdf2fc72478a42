#include "tests/docs/scene/scene_names.hpp"
using namespace doc_scene;
using proceduray::Ray;
// @declarations
void usage() {
  // @statements
}
