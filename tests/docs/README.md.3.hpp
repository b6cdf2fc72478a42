// README.md's third ```cpp block: declaring the field under a budget (examples/06_your_field/main.cpp).
#include "tests/docs/field_names.hpp"
using namespace doc_field;
// @declarations
void usage(pr::Scene<Interface>& s, const pr::DistanceField& field, pr::RayId<Radiance> radiance,
           pr::LocalSignatureId<Material> material, const pr::Calibration& table, std::uint32_t width,
           std::uint32_t height) {
  // @statements
}
