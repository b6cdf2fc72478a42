#include "tests/docs/scene/scene_names.hpp"
#include <proceduray/scene/distance_field.hpp>
using namespace doc_scene;

// @declarations
void usage(proceduray::Scene<Interface>& scene, proceduray::RayId<Radiance> radiance,
           proceduray::LocalSignatureId<Material> material, const Material& gold) {
  // @statements
}
