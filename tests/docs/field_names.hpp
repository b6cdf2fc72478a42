// What the distance-field excerpts of README.md and docs/guide/distance_fields.md take as given:
// the names examples/06_your_field/main.cpp declares around them.
#pragma once

#include <proceduray/proceduray.hpp>
#include <proceduray/shader/glsl_cpp.hpp>

#include <cstdio>
#include <filesystem>
#include <string>

namespace doc_field {
namespace pr = proceduray;
template <class T>
struct gyroid {  // what including gyroid.glsl in a class template gives
  static T gyroid_distance(glm::vec<3, T> p) { return glm::length(p) - T(1); }
};
PROCEDURAY_DEFINE_STRUCT(Radiance, scalar, (glm::vec3, colour));
PROCEDURAY_DEFINE_STRUCT(Material, scalar, (glm::vec3, albedo));
using Interface = pr::ShaderInterface<pr::Payload<Radiance>, pr::RootComponent<>, pr::RootArguments<Material>,
                                      pr::Attributes<pr::FieldHit>>;
inline std::filesystem::path shaders() { return "shaders"; }
inline pr::Camera camera(std::uint32_t w, std::uint32_t h) { return pr::look_at({0, 0, 3}, {0, 0, 0}, 45, w, h); }
}  // namespace doc_field
