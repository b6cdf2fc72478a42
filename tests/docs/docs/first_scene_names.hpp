// What the docs pages' excerpts of the first scene take as given: its structs, interface and slot,
// as tests/consumer/first_scene.cpp declares them.
#pragma once

#include <proceduray/proceduray.hpp>

namespace doc_first_scene {
namespace pr = proceduray;
struct Colour {
  glm::vec3 rgb;
};
PROCEDURAY_STRUCT(Colour, scalar, rgb);
struct BallHit {
  glm::vec3 normal;
};
PROCEDURAY_STRUCT(BallHit, scalar, normal);
struct Paint {
  glm::vec4 albedo;
};
PROCEDURAY_STRUCT(Paint, scalar, albedo);
struct Constants {
  pr::Camera camera;
  glm::vec4 sky;
};
PROCEDURAY_STRUCT(Constants, scalar, camera, sky);
inline constexpr pr::UniformSlot<Constants> constants_slot{.binding = 2, .name = "constants"};
using Interface = pr::ShaderInterface<pr::Payload<Colour>, pr::RootComponent<Constants>, pr::RootArguments<Paint>,
                                      pr::Attributes<BallHit>>;
}  // namespace doc_first_scene
