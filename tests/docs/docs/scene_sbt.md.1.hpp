// docs/scene_sbt.md's ```cpp block (the registry and the SBT, by hand).
#include <iostream>
#include <vector>
#include "tests/docs/doc_types.hpp"
using namespace doc_types;
struct ProceduralRootArguments {
  glm::vec4 albedo;
  std::uint32_t instance_index;
};
PROCEDURAY_STRUCT(ProceduralRootArguments, scalar, albedo, instance_index);
// @declarations
void usage(const std::vector<proceduray::InstanceTransform>& transforms, const proceduray::DeviceLimits& limits) {
  // @statements
}
