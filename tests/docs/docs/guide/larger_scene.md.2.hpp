// docs/guide/larger_scene.md's second ```cpp block (constants of the scene's own).
#include "tests/docs/vk/vk_names.hpp"
using namespace doc_vk;
inline constexpr std::uint32_t flag_shadows = 1u, flag_reflections = 2u;
// @declarations
void usage(DocScene& scene) {
  // @statements
}
