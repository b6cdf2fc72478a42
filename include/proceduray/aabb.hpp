// An axis-aligned box: what a procedural geometry's bounds are (scene/geometry.hpp), and what the
// march helpers compute for their primitives (march/metaballs.hpp, march/sphere_set.hpp). It sits
// at the bottom of the house, beside error.hpp, so both layers take it without one including the
// other.
//
//   proceduray::Aabb box{glm::vec3(-1.0f), glm::vec3(1.0f)};   // the default: the unit box
//   bool same = box == proceduray::Aabb{};
#pragma once

#include <glm/glm.hpp>

namespace proceduray {

/// An axis-aligned box in BLAS space.
struct Aabb {
  glm::vec3 min{-1.0f};  ///< default: the unit box's corner (-1, -1, -1)
  glm::vec3 max{1.0f};   ///< default: (1, 1, 1)
  friend bool operator==(const Aabb&, const Aabb&) = default;
};

}  // namespace proceduray
