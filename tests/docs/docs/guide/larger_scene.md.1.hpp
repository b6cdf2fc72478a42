// docs/guide/larger_scene.md's first ```cpp block (the paper scene, from examples/02_paper_scene).
#include "tests/docs/vk/vk_names.hpp"
using namespace doc_vk;
/// Stands for a value of the block's own record type (MaterialRecord is declared by the block).
struct AnyRecord {
  template <class T>
  operator T() const { return T{}; }
};
inline constexpr AnyRecord yellow{}, blue{};
inline const proceduray::Aabb box{glm::vec3(-1), glm::vec3(1)};
inline const std::vector<proceduray::Placement> placements{{.translation = {-1, 0, 0}}, {.translation = {1, 0, 0}}};
// @declarations
void usage(const proceduray::vk::RendererOptions& options, const SceneConstants& constants) {
  // @statements
}
