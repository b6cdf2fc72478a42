// docs/guide/meshes.md's ```cpp block (vertex data in hit shaders): the scene's interface lists the
// block's own MeshArgs, so the prelude declares it after the block's declarations.
#include "tests/docs/vk/vk_names.hpp"
namespace pr = proceduray;
using namespace doc_vk;
// @declarations
using MeshInterface = pr::ShaderInterface<pr::Payload<RadiancePayload>, pr::RootComponent<SceneConstants>,
                                          pr::RootArguments<MeshArgs>, pr::Attributes<>>;
void usage(pr::Scene<MeshInterface>& scene, const pr::TriangleMesh& mesh, const std::vector<Vertex>& vertices,
           pr::RayId<RadiancePayload> primary, pr::HitGroupId floor_group, glm::vec4 tint) {
  // @statements
}
