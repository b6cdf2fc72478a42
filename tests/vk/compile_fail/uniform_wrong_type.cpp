// Writing a value of another type to a typed uniform does not compile.
// expect-gcc: cannot convert
// expect: demo::Camera
// expect: demo::Constants
// expect-clang: no known conversion from 'demo::Camera' to 'const std::type_identity_t<Constants>' (aka 'const demo::Constants')
#include <proceduray/shader/field_list.hpp>
#include <proceduray/vk/renderer.hpp>

namespace demo {
struct Constants {
  glm::vec4 sky;
};
PROCEDURAY_STRUCT(Constants, scalar, sky);
struct Camera {
  glm::vec4 eye;
};
PROCEDURAY_STRUCT(Camera, scalar, eye);
}  // namespace demo

constexpr proceduray::UniformSlot<demo::Constants> constants{.binding = 2, .name = "constants"};

void write(proceduray::vk::Renderer& renderer) { renderer.set(constants, demo::Camera{}); }
