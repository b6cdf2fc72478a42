#include "tests/docs/vk/vk_names.hpp"
using namespace doc_vk;
using proceduray::BindingKind;
// @declarations
void usage(DocScene& scene, proceduray::vk::Renderer& renderer, const SceneConstants& value,
           std::span<const Tint> per_instance, const FrameKnobs& frame_knobs) {
  // @statements
}
