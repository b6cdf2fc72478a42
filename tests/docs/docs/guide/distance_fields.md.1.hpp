// docs/guide/distance_fields.md's ```cpp block: declaring the field (examples/06_your_field/main.cpp).
#include "tests/docs/field_names.hpp"
using namespace doc_field;
// @declarations
void usage(pr::Scene<Interface>& s, const pr::DistanceField& field, pr::RayId<Radiance> radiance,
           pr::LocalSignatureId<Material> material) {
  // @statements
}
