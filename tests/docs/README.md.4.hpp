// README.md's fourth ```cpp block (vertex data in hit shaders).
#include "tests/docs/vk/vk_names.hpp"
namespace pr = proceduray;
using namespace doc_vk;
// @declarations
void usage(pr::Scene& scene, const pr::TriangleMesh& mesh, const std::vector<Vertex>& vertices,
           pr::RayId<> primary, pr::HitGroupId floor_group, glm::vec4 tint) {
  // @statements
}
