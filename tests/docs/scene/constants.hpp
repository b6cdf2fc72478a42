#include "tests/docs/scene/scene_names.hpp"
using namespace doc_scene;
inline constexpr std::uint32_t flag_shadows = 1u, flag_reflections = 2u;

// @declarations
void usage(DocScene& scene) {
  // @statements
}
