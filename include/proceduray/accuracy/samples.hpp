// The method under test per pixel, from the per-pixel outputs a device wrote (scene/outputs.hpp,
// read back as vk::Outputs): the bridge between a render and measure() (metrics.hpp).
//
//   const std::size_t pixels = 64 * 48;
//   std::vector<float> t(pixels, -1.0f), normal(4 * pixels);            // a frame's outputs (vk::Frame::outputs)
//   std::vector<std::uint32_t> steps(pixels), flags(pixels);
//   const std::vector<proceduray::accuracy::Sample> samples =
//       proceduray::accuracy::samples_from(pixels, t, normal, steps, flags);   // all misses here
//
// A pixel hit when its t is >= 0 (the t image is cleared to -1, "nothing written"); a NaN t is a
// hit with a NaN t, so measure() counts it as non-finite instead of a miss. normal holds four
// floats per pixel (xyz, unused), steps and flags one uint each; an empty span means the scene did
// not ask for that output (normal 0, steps 0, flags 0). Wrong sizes throw UsageError.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "proceduray/accuracy/metrics.hpp"
#include "proceduray/error.hpp"

namespace proceduray::accuracy {

inline std::vector<Sample> samples_from(std::size_t pixels, std::span<const float> t, std::span<const float> normal = {},
                                        std::span<const std::uint32_t> steps = {},
                                        std::span<const std::uint32_t> flags = {}) {
  const auto check = [&](std::size_t got, std::size_t per_pixel, const char* what) {
    if (got != 0 && got != pixels * per_pixel) {
      throw UsageError(std::string("samples_from: ") + what + " has " + std::to_string(got) + " values for " +
                       std::to_string(pixels) + " pixels; give " + std::to_string(per_pixel) +
                       " per pixel (a frame's outputs of the same size), or none");
    }
  };
  if (t.size() != pixels) {
    throw UsageError("samples_from: t has " + std::to_string(t.size()) + " values for " + std::to_string(pixels) +
                     " pixels; the scene must ask for Output::t and the frame must be read back");
  }
  check(normal.size(), 4, "normal");
  check(steps.size(), 1, "steps");
  check(flags.size(), 1, "flags");
  std::vector<Sample> out(pixels);
  for (std::size_t i = 0; i < pixels; ++i) {
    Sample& s = out[i];
    s.hit = t[i] >= 0.0f || std::isnan(t[i]);
    s.t = t[i];
    if (!normal.empty()) s.normal = glm::dvec3(normal[4 * i], normal[4 * i + 1], normal[4 * i + 2]);
    if (!steps.empty()) s.steps = steps[i];
    if (!flags.empty()) s.flags = flags[i];
  }
  return out;
}

}  // namespace proceduray::accuracy
