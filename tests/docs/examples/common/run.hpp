#include <examples/common/run.hpp>
#include "tests/docs/vk/vk_names.hpp"
using namespace doc_vk;
inline SceneConstants constants(const examples::Options&, std::uint32_t) { return {}; }
// @declarations
int usage(int argc, char** argv, const proceduray::vk::Context& ctx, proceduray::vk::Renderer& renderer,
          const examples::Options& o, proceduray::UniformSlot<SceneConstants> slot) {
  // @statements
}
