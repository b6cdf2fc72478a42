// Push constants of another type than the slot's do not compile.
// expect-gcc: cannot convert
// expect: demo::Camera
// expect: demo::Knobs
// expect-clang: no known conversion from 'demo::Camera' to 'const std::type_identity_t<Knobs>' (aka 'const demo::Knobs')
#include <proceduray/shader/field_list.hpp>
#include <proceduray/vk/renderer.hpp>

namespace demo {
struct Knobs {
  glm::vec4 tint;
};
PROCEDURAY_STRUCT(Knobs, scalar, tint);
struct Camera {
  glm::vec4 eye;
};
PROCEDURAY_STRUCT(Camera, scalar, eye);
}  // namespace demo

constexpr proceduray::PushConstantSlot<demo::Knobs> knobs{.name = "knobs"};

void write(proceduray::vk::Renderer& renderer) { renderer.set_push(knobs, demo::Camera{}); }
