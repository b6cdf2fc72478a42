// Ground truth on a stratified sample: every pixel near a silhouette or a depth jump, and one in
// `stride` of the others at random, each of those standing for `stride` pixels. The truth is the
// dear part of a measurement (a bounded march plus bisection in double per pixel); most pixels
// of a frame are plain interior or background, where a sample estimates the rates as well as
// every pixel would, and the errors that matter concentrate at silhouettes, which are traced in
// full.
//
//   namespace acc = proceduray::accuracy;
//   const acc::Frame frame{.width = 320, .height = 240, .pixel_angle = 1.0e-3};
//   auto trace = [](std::uint32_t x, std::uint32_t) {    // the truth of one pixel: hit, miss or undetermined
//     return acc::Reference{.outcome = x < 100 ? acc::Outcome::hit : acc::Outcome::miss, .t = 5.0, .normal = {0.0, 0.0, 1.0}};
//   };
//   const acc::StratifiedTruth truth = acc::stratified_truth(frame, 8, 1, trace);  // one in 8 outside the band
//   std::vector<acc::Sample> samples(frame.pixels());                        // the render, read back per pixel
//   const acc::Metrics m = acc::measure_stratified(frame, samples, truth);   // estimates of measure()'s numbers
//   const acc::SampleConfidence c = acc::confidence(frame, samples, truth);  // upper 95% bounds of the rates
//
// How: a coarse pass traces every `cell`-th pixel each way (and the last row and column). A block
// of cell x cell pixels whose four corners disagree (hit against miss, an undetermined corner, or
// depths more than 2 * cell footprints apart) holds a silhouette or a jump; those blocks and their
// neighbours (the band: at least `cell` pixels each side, wider than PixelClass's 2-pixel
// classes) are traced in full. In the other blocks a pixel is traced when a hash of its index and
// `seed` picks it (probability 1 / stride); it is counted `stride` times, so counts and
// distributions estimate the whole frame's without bias. A pixel not traced takes its block's
// outcome for the pixel classes only. What the sample can miss: a feature smaller than a block
// that touches none of its corners lies outside the band; it is sampled like any interior pixel
// (its rates are estimated, their bound in SampleConfidence) and its silhouette is classed as
// interior. stride 1 traces every pixel: measure_stratified then equals measure().
#pragma once

#include <proceduray/accuracy/metrics.hpp>
#include <proceduray/accuracy/parallel.hpp>
#include <proceduray/error.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace proceduray::accuracy {

/// A frame's truth on a stratified sample.
struct StratifiedTruth {
  /// Per pixel, row-major: the truth where traced; elsewhere the block's outcome (classes only).
  std::vector<Reference> pixels;
  /// Per pixel: how many pixels it stands for (0: not traced; 1: traced in the band, or every
  /// pixel at stride 1; stride: a sample outside the band).
  std::vector<std::uint32_t> weight;
  std::uint32_t stride = 1;
  std::size_t traced = 0;        ///< pixels whose truth was computed (coarse pass included)
  std::size_t band = 0;          ///< pixels in the band (traced in full)
  std::size_t sampled = 0;       ///< pixels sampled outside the band
};

/// Upper 95% bounds of the rates a stratified measurement estimates (Wilson's interval on the
/// sampled part; the band is exact). At stride 1 the bounds equal the measured rates.
struct SampleConfidence {
  double false_miss_rate = 0.0;      ///< the estimate of Metrics::all.false_miss_rate()
  double false_miss_rate_95 = 0.0;   ///< its upper bound
  double wrong_surface_rate = 0.0;   ///< the estimate of Metrics::all.wrong_surface_rate()
  double wrong_surface_rate_95 = 0.0;
};

namespace detail {

/// A pixel's draw in [0, 1): splitmix64 of its index and the seed.
inline double sample_draw(std::uint64_t pixel, std::uint64_t seed) {
  std::uint64_t z = pixel + seed * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53;
}

/// Whether the corners of a block say it holds a silhouette or a depth jump.
inline bool block_changes(std::span<const Reference> corners, double pixel_angle, std::uint32_t cell) {
  const Outcome first = corners[0].outcome;
  double near = std::numeric_limits<double>::infinity(), far = 0.0;
  for (const Reference& c : corners) {
    if (c.outcome != first || c.outcome == Outcome::undetermined) return true;
    if (c.outcome == Outcome::hit) {
      near = std::min(near, c.t);
      far = std::max(far, c.t);
    }
  }
  return first == Outcome::hit && (far - near) / (near * pixel_angle) > 2.0 * cell;
}

/// Wilson's upper 95% bound of a proportion seen k times in n draws.
inline double wilson_upper(double k, double n) {
  if (n <= 0.0) return 1.0;
  constexpr double z = 1.959963984540054;
  const double p = k / n, z2n = z * z / n;
  return std::min(1.0, (p + z2n / 2.0 + z * std::sqrt(p * (1.0 - p) / n + z2n / (4.0 * n))) / (1.0 + z2n));
}

}  // namespace detail

/// The truth of `frame` on a stratified sample (rule in the header comment), traced on every core
/// by `trace(x, y)` -> Reference. Throws UsageError for a stride or cell of 0 (with the fix) or a
/// bad frame; what `trace` throws, for the lowest row that threw (parallel.hpp).
template <class Trace>
StratifiedTruth stratified_truth(const Frame& frame, std::uint32_t stride, std::uint64_t seed, const Trace& trace,
                                 std::uint32_t cell = 4) {
  constexpr std::string_view call = "accuracy::stratified_truth";
  detail::check_frame(frame, call);
  if (stride == 0 || cell == 0) {
    throw UsageError(std::string(call) + ": " + (stride == 0 ? "stride" : "cell") +
                     " is 0; give 1 (every pixel) or more (one pixel in that many outside the band)");
  }
  const std::uint32_t w = frame.width, h = frame.height;
  StratifiedTruth out;
  out.stride = stride;
  out.pixels.assign(frame.pixels(), Reference{});
  out.weight.assign(frame.pixels(), 0u);
  std::vector<std::uint8_t> traced(frame.pixels(), 0);
  auto trace_row = [&](std::uint32_t y, auto&& wanted) {
    for (std::uint32_t x = 0; x < w; ++x) {
      const std::size_t i = std::size_t{y} * w + x;
      if (traced[i] != 0 || !wanted(x)) continue;
      out.pixels[i] = trace(x, y);
      traced[i] = 1;
    }
  };
  if (stride == 1) {
    parallel_rows(h, [&](std::uint32_t y, std::uint32_t) { trace_row(y, [](std::uint32_t) { return true; }); });
    std::fill(out.weight.begin(), out.weight.end(), 1u);
    out.traced = out.band = frame.pixels();
    return out;
  }
  // Coarse pass: the corners of every block.
  auto corner = [&](std::uint32_t v, std::uint32_t n) { return v % cell == 0 || v + 1 == n; };
  parallel_rows(h, [&](std::uint32_t y, std::uint32_t) {
    if (corner(y, h)) trace_row(y, [&](std::uint32_t x) { return corner(x, w); });
  });
  const std::uint32_t bw = (w + cell - 1) / cell, bh = (h + cell - 1) / cell;
  std::vector<std::uint8_t> changes(std::size_t{bw} * bh, 0), band(std::size_t{bw} * bh, 0);
  for (std::uint32_t by = 0; by < bh; ++by) {
    for (std::uint32_t bx = 0; bx < bw; ++bx) {
      const std::uint32_t x0 = bx * cell, y0 = by * cell;
      const std::uint32_t x1 = std::min(x0 + cell, w - 1), y1 = std::min(y0 + cell, h - 1);
      const Reference corners[4] = {out.pixels[std::size_t{y0} * w + x0], out.pixels[std::size_t{y0} * w + x1],
                                    out.pixels[std::size_t{y1} * w + x0], out.pixels[std::size_t{y1} * w + x1]};
      changes[std::size_t{by} * bw + bx] = detail::block_changes(corners, frame.angle(std::size_t{y0} * w + x0), cell);
    }
  }
  for (std::uint32_t by = 0; by < bh; ++by) {
    for (std::uint32_t bx = 0; bx < bw; ++bx) {
      if (changes[std::size_t{by} * bw + bx] == 0) continue;
      for (std::uint32_t ny = by == 0 ? 0 : by - 1; ny <= std::min(by + 1, bh - 1); ++ny) {
        for (std::uint32_t nx = bx == 0 ? 0 : bx - 1; nx <= std::min(bx + 1, bw - 1); ++nx) band[std::size_t{ny} * bw + nx] = 1;
      }
    }
  }
  auto in_band = [&](std::uint32_t x, std::uint32_t y) { return band[std::size_t{y / cell} * bw + x / cell] != 0; };
  auto picked = [&](std::uint32_t x, std::uint32_t y) {
    return detail::sample_draw(std::size_t{y} * w + x, seed) * stride < 1.0;
  };
  // Fine pass: the band in full, a sample elsewhere.
  parallel_rows(h, [&](std::uint32_t y, std::uint32_t) {
    trace_row(y, [&](std::uint32_t x) { return in_band(x, y) || picked(x, y); });
  });
  for (std::uint32_t y = 0; y < h; ++y) {
    for (std::uint32_t x = 0; x < w; ++x) {
      const std::size_t i = std::size_t{y} * w + x;
      out.traced += traced[i];
      if (in_band(x, y)) {
        out.weight[i] = 1;
        ++out.band;
      } else if (picked(x, y)) {
        out.weight[i] = stride;
        ++out.sampled;
      } else if (traced[i] == 0) {
        // Not traced: the block's outcome for the classes (its corners agree; one of them).
        out.pixels[i] = out.pixels[std::size_t{std::min(y / cell * cell, h - 1)} * w + std::min(x / cell * cell, w - 1)];
      }
    }
  }
  return out;
}

namespace detail {
inline void check_stratified(const Frame& frame, std::span<const Sample> samples, const StratifiedTruth& truth,
                             std::string_view call) {
  check_frame(frame, call);
  check_count(samples.size(), frame, "samples", call);
  check_count(truth.pixels.size(), frame, "truth pixels", call);
  check_count(truth.weight.size(), frame, "truth weights", call);
  check_references(truth.pixels, frame, call);
}
}  // namespace detail

/// measure() on a stratified truth: the classes from every pixel's outcome, the statistics from
/// the traced pixels, each counted as many times as it stands for. Throws as measure() does.
inline Metrics measure_stratified(const Frame& frame, std::span<const Sample> samples, const StratifiedTruth& truth) {
  detail::check_stratified(frame, samples, truth, "accuracy::measure_stratified");
  return detail::accumulate(frame, samples, truth.pixels, [&](std::size_t i) { return truth.weight[i]; });
}

/// The estimates of the frame's false-miss and wrong-surface rates (over the truth's hits, as
/// ClassStats has them) and their upper 95% bounds: the band's counts are exact, the sample's
/// proportion is bounded by Wilson's interval and scaled by the stride.
inline SampleConfidence confidence(const Frame& frame, std::span<const Sample> samples, const StratifiedTruth& truth) {
  detail::check_stratified(frame, samples, truth, "accuracy::confidence");
  // Per part (band, sample): the truth's hits, the misses among them, the hits behind.
  double hits[2] = {0, 0}, misses[2] = {0, 0}, behind[2] = {0, 0};
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Reference& r = truth.pixels[i];
    if (truth.weight[i] == 0 || r.outcome != Outcome::hit) continue;
    const int part = truth.weight[i] == 1 ? 0 : 1;
    const Sample& s = samples[i];
    hits[part] += 1.0;
    if (!s.hit) misses[part] += 1.0;
    else if (std::isfinite(s.t) && (s.t - r.t) / (r.t * frame.angle(i)) > wrong_surface_footprints) behind[part] += 1.0;
  }
  const double k = truth.stride == 1 ? 1.0 : truth.stride;
  const double total = hits[0] + k * hits[1];
  auto rates = [&](const double (&n)[2], double& estimate, double& upper) {
    if (total == 0.0) return;
    estimate = (n[0] + k * n[1]) / total;
    upper = hits[1] == 0.0 ? estimate : (n[0] + k * hits[1] * detail::wilson_upper(n[1], hits[1])) / total;
  };
  SampleConfidence c;
  rates(misses, c.false_miss_rate, c.false_miss_rate_95);
  rates(behind, c.wrong_surface_rate, c.wrong_surface_rate_95);
  return c;
}

}  // namespace proceduray::accuracy
