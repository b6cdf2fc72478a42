#include "tests/docs/scene/scene_names.hpp"
using namespace doc_scene;

// @declarations
void usage(DocScene& scene, proceduray::RayId<RadiancePayload> radiance, proceduray::HitGroupId pacman, proceduray::GeometryId geometry) {
  // @statements
}
