#include "tests/docs/scene/scene_names.hpp"
#include <proceduray/scene/field.hpp>
using namespace doc_scene;

// @declarations
void usage() {
  // @statements
}
