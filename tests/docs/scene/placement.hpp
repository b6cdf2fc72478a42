#include "tests/docs/scene/scene_names.hpp"
using namespace doc_scene;

// @declarations
void usage(DocScene& scene, std::span<const proceduray::Placement> placements) {
  // @statements
}
