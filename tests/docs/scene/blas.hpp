#include "tests/docs/scene/scene_names.hpp"
using namespace doc_scene;

// @declarations
void usage(proceduray::GeometryDesc& desc, proceduray::GeometryId geometry_id) {
  // @statements
}
