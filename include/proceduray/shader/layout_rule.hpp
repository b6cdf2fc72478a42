// Block layout rules a GPU-visible struct can follow (GLSL `layout(scalar|std430|std140)`).
//
//   PROCEDURAY_STRUCT(Sphere, scalar, center, radius);   // names the rule by its GLSL spelling
//   proceduray::to_string(proceduray::LayoutRule::std430);  // "std430"
#pragma once

#include <cstdint>
#include <string_view>

namespace proceduray {

/// A GLSL block layout rule; scalar (GL_EXT_scalar_block_layout, core in Vulkan 1.2) is the house default.
enum class LayoutRule : std::uint32_t { scalar = 0, std430 = 1, std140 = 2 };

/// The rule's GLSL layout qualifier, e.g. "std430".
constexpr std::string_view to_string(LayoutRule rule) {
  switch (rule) {
    case LayoutRule::scalar: return "scalar";
    case LayoutRule::std430: return "std430";
    case LayoutRule::std140: return "std140";
  }
  return "?";
}

}  // namespace proceduray
