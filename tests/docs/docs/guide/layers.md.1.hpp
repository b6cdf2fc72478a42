// docs/guide/layers.md's ```cpp block (layers, update policies, any-hit and callable shaders).
#include "tests/docs/vk/vk_names.hpp"
namespace pr = proceduray;
using namespace doc_vk;
// @declarations
void usage(DocScene& scene, pr::vk::Renderer& renderer, const pr::Aabb& box,
           const std::vector<pr::InstanceTransform>& transforms, pr::LocalSignatureId<TintArgs> tint_signature,
           pr::GeometryId ball_id, pr::GeometryId blob_id, const glm::mat4& moved, const glm::mat4& placed, const std::vector<pr::Aabb>& boxes,
           std::uint32_t w, std::uint32_t h) {
  // @statements
}
