// A hit group: closest-hit, any-hit and intersection shaders for triangles or procedural geometry.
//
//   auto pacman = scene.add_hit_group<PacmanAttributes>("Pacman", {
//       .kind = proceduray::HitGroupKind::procedural,
//       .closest_hit = "pacman.rchit", .intersection = "pacman.rint"});
//   auto plane = scene.add_hit_group("Triangle", {.closest_hit = "plane.rchit"});
//
// A triangles group has no intersection shader (the built-in one is used); a procedural
// group must have one. validate() throws HitGroupKindError otherwise.
#pragma once

#include <proceduray/config.hpp>

#include <cstdint>
#include <string>
#include <string_view>
#include <typeindex>
#include <typeinfo>

#include "proceduray/scene/errors.hpp"
#include "proceduray/shader/glsl_type.hpp"

namespace proceduray {

/// Which geometry a hit group handles.
enum class HitGroupKind : std::uint32_t { triangles = 0, procedural = 1 };

PROCEDURAY_DECL const char* to_string(HitGroupKind kind);

/// What the user declares for a hit group; empty shader names mean "none".
struct HitGroupDesc {
  HitGroupKind kind = HitGroupKind::triangles;  ///< default: triangles
  std::string closest_hit;                      ///< closest-hit shader name; empty = none
  std::string any_hit;                          ///< any-hit shader name; empty = none
  std::string intersection;                     ///< intersection shader; required for procedural, forbidden for triangles
};

/// Bytes of the built-in triangle hit attributes (vec2 barycentrics).
inline constexpr std::uint32_t triangle_attribute_size = 8;

/// A registered hit group.
struct HitGroup {
  HitGroupDesc desc;                               ///< as declared
  std::uint32_t attribute_size = 0;                ///< hit attribute bytes (triangles: 8, procedural: sizeof(Attributes))
  std::type_index attribute_type = typeid(void);   ///< Attributes; void for triangles' built-in ones
  const TypeOps* attribute_glsl = nullptr;         ///< Attributes' GLSL description; null for triangles
};

/// Throws HitGroupKindError when the shaders do not fit the kind.
PROCEDURAY_DECL void validate(const HitGroupDesc& desc, std::string_view id, std::string_view operation);

}  // namespace proceduray

#include "proceduray/scene/hit_group-inl.hpp"  // the bodies (config.hpp)
