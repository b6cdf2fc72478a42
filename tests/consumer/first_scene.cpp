// A first scene: one red ball under a sky, from the README (a test checks the two are the same).
#include <proceduray/proceduray.hpp>

namespace pr = proceduray;

struct Colour {  // the radiance ray's payload
  glm::vec3 rgb;
};
PROCEDURAY_STRUCT(Colour, scalar, rgb);
struct BallHit {  // what the intersection shader hands the closest-hit shader
  glm::vec3 normal;
};
PROCEDURAY_STRUCT(BallHit, scalar, normal);
struct Paint {  // the ball's hit record
  glm::vec4 albedo;
};
PROCEDURAY_STRUCT(Paint, scalar, albedo);
struct Constants {  // a uniform every shader reads as `constants`
  pr::Camera camera;
  glm::vec4 sky;
};
PROCEDURAY_STRUCT(Constants, scalar, camera, sky);
constexpr pr::UniformSlot<Constants> constants_slot{.binding = 2, .name = "constants"};
// The shader compatibility layer: each struct in its category.
using Interface = pr::ShaderInterface<pr::Payload<Colour>, pr::RootComponent<Constants>, pr::RootArguments<Paint>,
                                      pr::Attributes<BallHit>>;

int main() {
  pr::Scene<Interface> scene;
  auto radiance = scene.add_ray<Colour>("radiance", {.miss = "sky.rmiss"});
  scene.set_global_signature(pr::default_global_signature({constants_slot}));  // tlas, image, constants
  scene.add_raygen("camera.rgen");
  auto paint = scene.add_local_signature<Paint>("paint");
  pr::add_object<BallHit>(scene, "ball", {.geometry = pr::GeometryDesc::procedural({pr::Aabb{}}),
                                          .intersection = "ball.rint", .closest_hit = {{radiance, "ball.rchit"}}},
                          paint, {Paint{{1.0f, 0.2f, 0.1f, 1.0f}}});

  pr::vk::Context ctx;                                                      // a GPU if there is one, else lavapipe
  pr::vk::Renderer renderer(ctx, scene, {.shader_dirs = {"shaders"}});   // where camera.rgen, sky.rmiss... are
  renderer.set(constants_slot, {pr::look_at({0, 0, 4}, {0, 0, 0}, 45.0f, 320, 240), {0.4f, 0.6f, 0.9f, 1}});
  const pr::vk::Frame frame = renderer.render(320, 240);
  pr::write_png("first_scene.png", 320, 240, frame.rgba);
  const std::uint8_t* centre = &frame.rgba[(120 * 320 + 160) * 4];
  return centre[0] > 150 && centre[2] < 100 ? 0 : 1;  // red where the camera looks: the ball
}
