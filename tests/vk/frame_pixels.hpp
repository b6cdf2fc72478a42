// Reading a Frame's pixels in tests: bounds-checked access and colour comparison in 8-bit levels.
//
//   glm::ivec3 c = frame_pixels::rgb(frame, {x, y});          // REQUIREs (x, y) inside the frame
//   CHECK(frame_pixels::near(c, frame_pixels::bytes(colour)));  // within 2 levels per channel
//   const frame_pixels::Diff d = frame_pixels::diff(a.rgba, b.rgba, 1);   // two whole images
#pragma once

#include <proceduray/vk/renderer.hpp>

#include <doctest/doctest.h>

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>

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

/// How two images of the same size differ, channel by channel.
struct Diff {
  int worst = 0;          ///< the largest difference, in levels
  std::size_t over = 0;   ///< channels that differ by more than the `by` given to diff
};
/// Compares a and b (REQUIREs equal sizes).
inline Diff diff(std::span<const std::uint8_t> a, std::span<const std::uint8_t> b, int by) {
  REQUIRE(a.size() == b.size());
  Diff d;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const int level = std::abs(int(a[i]) - int(b[i]));
    d.worst = level > d.worst ? level : d.worst;
    d.over += level > by;
  }
  return d;
}

}  // namespace frame_pixels
