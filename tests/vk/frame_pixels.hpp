// Reading a Frame's pixels in tests: bounds-checked access and colour comparison in 8-bit levels.
//
//   glm::ivec3 c = frame_pixels::rgb(frame, {x, y});          // REQUIREs (x, y) inside the frame
//   CHECK(frame_pixels::near(c, frame_pixels::bytes(colour)));  // within 2 levels per channel
#pragma once

#include <proceduray/vk/renderer.hpp>

#include <doctest/doctest.h>

#include <glm/glm.hpp>

#include <cstddef>

namespace frame_pixels {

/// Channels 0..3 of pixel p (RGBA8); fails the test when p is outside the frame.
inline glm::ivec4 rgba(const proceduray::vk::Frame& f, glm::ivec2 p) {
  REQUIRE(p.x >= 0);
  REQUIRE(p.y >= 0);
  REQUIRE(p.x < static_cast<int>(f.width));
  REQUIRE(p.y < static_cast<int>(f.height));
  const std::size_t i = (std::size_t(p.y) * f.width + std::size_t(p.x)) * 4;
  return {f.rgba[i], f.rgba[i + 1], f.rgba[i + 2], f.rgba[i + 3]};
}
/// Channels 0..2 of pixel p.
inline glm::ivec3 rgb(const proceduray::vk::Frame& f, glm::ivec2 p) { return glm::ivec3(rgba(f, p)); }

/// A linear colour in [0, 1] as the 8-bit levels the storage image holds.
inline glm::ivec4 bytes(glm::vec4 c) { return glm::ivec4(glm::round(glm::clamp(c, 0.0f, 1.0f) * 255.0f)); }
inline glm::ivec3 bytes(glm::vec3 c) { return glm::ivec3(glm::round(glm::clamp(c, 0.0f, 1.0f) * 255.0f)); }

/// Every channel within `tolerance` levels.
template <int N>
bool near(glm::vec<N, int> a, glm::vec<N, int> b, int tolerance = 2) {
  return glm::all(glm::lessThanEqual(glm::abs(a - b), glm::vec<N, int>(tolerance)));
}

}  // namespace frame_pixels
