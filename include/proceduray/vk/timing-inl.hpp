// The bodies of proceduray/vk/timing.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/timing.hpp"

#if PROCEDURAY_BODIES
namespace proceduray::vk {

PROCEDURAY_DECL Stats stats(std::span<const double> samples) {
  if (samples.empty()) throw UsageError("stats: no samples; time at least one frame");
  std::vector<double> v(samples.begin(), samples.end());
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  const double median = n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  return {v.front(), median, v.back(), n};
}

PROCEDURAY_DECL FrameTimes time_frames(Renderer& renderer, std::uint32_t width, std::uint32_t height, TimingOptions options) {
  return time_frames(renderer, width, height, options, [](std::uint32_t) {});
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
