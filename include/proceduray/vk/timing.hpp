// Timing a renderer the way the examples and benchmarks do, so users do not write it again:
// warm-up frames first (the first trace pays for driver compiles and caches), then frames timed
// by the GPU timestamps around the trace, reported as min / median / max, and Mrays/s.
//
//   proceduray::vk::FrameTimes t = proceduray::vk::time_frames(renderer, 1024, 768, {.frames = 20, .warm_up = 2},
//       [&](std::uint32_t frame) { renderer.set(slot, constants(frame)); });   // before every frame
//   t.trace_ms.median;             // GPU milliseconds per frame
//   t.mrays_per_s(2.0);            // at two rays per pixel (say, a primary and a shadow ray)
//   proceduray::vk::Stats s = proceduray::vk::stats(samples);   // any list of numbers
//
// Medians, not means: one frame that waited for the compositor or a page fault moves a mean,
// not a median. Speed belongs in benchmarks that print these numbers, never in unit tests.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/error.hpp>
#include <proceduray/vk/renderer.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace proceduray::vk {

/// The spread of a list of numbers.
struct Stats {
  double min = 0;
  double median = 0;  ///< the middle value; the mean of the two middle ones for an even count
  double max = 0;
  std::size_t count = 0;
};

/// Min, median and max of `samples`; throws UsageError for an empty list.
PROCEDURAY_DECL Stats stats(std::span<const double> samples);

/// How time_frames runs.
struct TimingOptions {
  std::uint32_t frames = 20;  ///< frames timed, at least 1
  std::uint32_t warm_up = 2;  ///< frames traced first and not counted
  bool read_last = false;     ///< read the last timed frame's pixels back into FrameTimes::last
};

/// What time_frames measured.
struct FrameTimes {
  Stats trace_ms;             ///< GPU time of the trace, per frame (timestamps)
  Stats host_ms;              ///< host work before each submit
  Stats wall_ms;              ///< render() call to its return, per frame
  std::uint32_t width = 0, height = 0;
  bool tlas_refit = false;    ///< any timed frame refit or rebuilt the TLAS
  Frame last;                 ///< the last timed frame (pixels only with read_last)
  /// Millions of rays per second at the median trace time, counting `rays_per_pixel` rays a pixel.
  double mrays_per_s(double rays_per_pixel = 1.0) const {
    return trace_ms.median > 0 ? rays_per_pixel * width * height / (trace_ms.median * 1e3) : 0.0;
  }
};

/// Traces options.warm_up frames, then options.frames timed ones, calling update(frame) before
/// each (frame counts from 0 across warm-up and timed frames); throws UsageError for 0 frames.
template <class Update>
FrameTimes time_frames(Renderer& renderer, std::uint32_t width, std::uint32_t height, TimingOptions options,
                       Update update) {
  if (options.frames == 0) {
    throw UsageError("time_frames: 0 frames to time at " + std::to_string(width) + "x" + std::to_string(height) +
                     "; time at least one (TimingOptions::frames)");
  }
  std::uint32_t frame = 0;
  for (std::uint32_t i = 0; i < options.warm_up; ++i) {
    update(frame++);
    (void)renderer.render(width, height, false);
  }
  std::vector<double> trace, host, wall;
  FrameTimes out{.width = width, .height = height};
  for (std::uint32_t i = 0; i < options.frames; ++i) {
    update(frame++);
    const bool last = i + 1 == options.frames;
    const auto start = std::chrono::steady_clock::now();
    Frame f = renderer.render(width, height, last && options.read_last);
    wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    trace.push_back(f.trace_ms);
    host.push_back(f.host_ms);
    out.tlas_refit = out.tlas_refit || f.tlas_refit;
    if (last) out.last = std::move(f);
  }
  out.trace_ms = stats(trace);
  out.host_ms = stats(host);
  out.wall_ms = stats(wall);
  return out;
}

/// time_frames with nothing to update between frames.
PROCEDURAY_DECL FrameTimes time_frames(Renderer& renderer, std::uint32_t width, std::uint32_t height, TimingOptions options = {});

}  // namespace proceduray::vk

#include "proceduray/vk/timing-inl.hpp"  // the bodies (config.hpp)
