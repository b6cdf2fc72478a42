// The control: a value of the slot's own type compiles.
// expect-success
#include <proceduray/shader/field_list.hpp>
#include <proceduray/vk/renderer.hpp>

namespace demo {
struct Constants {
  glm::vec4 sky;
};
PROCEDURAY_STRUCT(Constants, scalar, sky);
}  // namespace demo

constexpr proceduray::UniformSlot<demo::Constants> constants{.binding = 2, .name = "constants"};
constexpr proceduray::PushConstantSlot<demo::Constants> pushed{.name = "pushed"};

void write(proceduray::vk::Renderer& renderer) {
  renderer.set(constants, demo::Constants{});
  renderer.set_push(pushed, demo::Constants{});  // the control of push_wrong_type too
}
