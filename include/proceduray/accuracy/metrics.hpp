// Accuracy of a render against a double-precision ground truth for the same camera rays: hit/miss
// agreement per pixel class, depth error in pixel footprints, normal angle error, steps per ray,
// NaN/Inf and exhausted-march counts; and PSNR of colour images. Pure C++: no device.
//
//   namespace acc = proceduray::accuracy;
//   const std::uint32_t width = 64, height = 48;
//   acc::Frame frame{.width = width, .height = height, .pixel_angle = 2.0 * std::tan(0.4) / height};
//   std::vector<acc::Sample> samples(width * height);   // the method under test, read back per pixel
//   std::vector<acc::Reference> truth(width * height);  // the ground truth for the same rays
//   const acc::Metrics m = acc::measure(frame, samples, truth);  // UsageError on mismatched sizes
//   m[acc::PixelClass::silhouette_1px].false_hits;      // rays the method hit and the truth missed
//   m.all.depth.p99;                                     // |t - t_ref| / footprint, 99th percentile
//   std::vector<float> image(width * height * 4), expected(width * height * 4);
//   double db = acc::psnr(image, expected);              // +infinity: the images are equal
//
// Pixel classes come from the REFERENCE hit mask (outcome == hit) on the image grid, so the method
// under test cannot move its own pixels between classes. With d the Chebyshev distance from a pixel
// to the nearest pixel whose reference hit state differs (pixels outside the image do not count):
//   d == 1: silhouette_1px;  d == 2: silhouette_2px;  d > 2: interior if the reference hits, far if not.
// An undetermined reference counts as "not hit" in the mask: doubt widens the silhouette band around
// it instead of leaking into interior statistics; its own ray is counted (ClassStats::undetermined)
// and left out of every other statistic.
//
// Depth error is measured in pixel footprints, |t - t_ref| / (t_ref * pixel_angle): the footprint at
// distance t is t * pixel_angle, so an error below one footprint is invisible at this resolution
// whatever the distance, and errors of near and far objects compare on one scale.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "proceduray/accuracy/outcome.hpp"
#include "proceduray/accuracy/percentiles.hpp"
#include "proceduray/error.hpp"
#include "proceduray/scene/outputs.hpp"

namespace proceduray::accuracy {

/// Bits of Sample::flags: the output_flag_* bits shaders write (scene/outputs.hpp).
namespace flags {
inline constexpr std::uint32_t nan_seen = output_flag_nan;                ///< a NaN or Inf appeared while tracing the ray
inline constexpr std::uint32_t exhausted = output_flag_exhausted;         ///< the march ran out of steps
inline constexpr std::uint32_t started_inside = output_flag_started_inside;  ///< the ray started inside the object
}  // namespace flags

/// The method under test at one pixel. t and normal are read only when hit is true.
struct Sample {
  bool hit = false;
  double t = 0.0;            ///< hit distance along the camera ray (unit direction)
  glm::dvec3 normal{0.0};    ///< world normal, any length; zero counts as a 180-degree error
  double steps = 0.0;        ///< evaluations or steps spent on the ray
  std::uint32_t flags = 0;   ///< flags::* bits
};

/// The ground truth at one pixel: a ground-truth Result's outcome, t and normal. Outcome::undetermined
/// rays are counted and left out of every other statistic. On a hit t must be finite and > 0 and the
/// normal finite; a zero normal means the surface has none there (an edge, a fold seam; the searchers
/// leave it zero) and leaves the ray out of the normal errors.
struct Reference {
  Outcome outcome = Outcome::miss;
  double t = 0.0;
  glm::dvec3 normal{0.0};
};

/// The image grid, row-major (pixel = y * width + x), and the angle (radians) one pixel subtends:
/// the footprint at distance t is t * angle. One angle for all pixels (Camera::pixel_angle), or one per pixel.
struct Frame {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  double pixel_angle = 0.0;            ///< used when pixel_angles is empty
  std::vector<double> pixel_angles{};  ///< per pixel, row-major; empty: pixel_angle for every pixel

  std::size_t pixels() const { return static_cast<std::size_t>(width) * height; }
  double angle(std::size_t pixel) const { return pixel_angles.empty() ? pixel_angle : pixel_angles[pixel]; }
};

/// Where a pixel lies relative to the reference silhouette (rule in the header comment).
enum class PixelClass : std::uint8_t { silhouette_1px, silhouette_2px, interior, far };
/// Every class, in report order.
inline constexpr std::array<PixelClass, 4> pixel_classes{PixelClass::silhouette_1px, PixelClass::silhouette_2px,
                                                         PixelClass::interior, PixelClass::far};
/// The class's name as reports and CSV files spell it.
constexpr std::string_view name(PixelClass c) {
  constexpr std::array<std::string_view, 4> names{"silhouette_1px", "silhouette_2px", "interior", "far"};
  return names[static_cast<std::size_t>(c)];
}

/// How far behind the reference's hit (pixel footprints) a hit counts as on a wrong surface.
inline constexpr double wrong_surface_footprints = 2.0;

/// Statistics of one pixel class (or of all). Rays with an undetermined reference are only counted.
struct ClassStats {
  std::size_t rays = 0;            ///< rays with a determined reference
  std::size_t undetermined = 0;    ///< rays whose reference is undetermined (in no other field)
  std::size_t agree = 0;           ///< method and reference agree on hit/miss
  std::size_t false_hits = 0;      ///< method hit, reference missed
  std::size_t false_misses = 0;    ///< method missed, reference hit
  std::size_t both_hit = 0;        ///< both hit: the rays with depth and normal errors
  /// Both hit, and the method's t lies more than wrong_surface_footprints behind the reference's:
  /// a surface behind the true one (a march that stepped over a thin part), not a depth error.
  std::size_t wrong_surface = 0;
  Distribution depth;              ///< |t - t_ref| / (t_ref * pixel angle), both hit and t finite
  Distribution normal_degrees;     ///< angle between normals, both hit, both normals finite, reference non-zero
  Distribution steps;              ///< Sample::steps over all rays, finite values
  std::size_t nonfinite = 0;       ///< rays with flags::nan_seen, non-finite steps, or a hit with a non-finite t/normal
  std::size_t exhausted = 0;       ///< rays with flags::exhausted
  std::size_t started_inside = 0;  ///< rays with flags::started_inside

  double agree_rate() const { return rate(agree); }              ///< agree / rays; NaN without rays
  double false_hit_rate() const { return rate(false_hits); }     ///< false_hits / rays; NaN without rays
  double false_miss_rate() const { return rate(false_misses); }  ///< false_misses / rays; NaN without rays
  /// false_misses / the reference's hits (both_hit + false_misses): the fraction of an object's
  /// pixels the method misses, where false_miss_rate divides by every ray; NaN without any.
  double missed_hits_rate() const {
    const std::size_t hits = both_hit + false_misses;
    return hits == 0 ? std::numeric_limits<double>::quiet_NaN()
                     : static_cast<double>(false_misses) / static_cast<double>(hits);
  }
  /// wrong_surface / the reference's hits (both_hit + false_misses); NaN without any.
  double wrong_surface_rate() const {
    const std::size_t hits = both_hit + false_misses;
    return hits == 0 ? std::numeric_limits<double>::quiet_NaN()
                     : static_cast<double>(wrong_surface) / static_cast<double>(hits);
  }

 private:
  double rate(std::size_t n) const {
    return rays == 0 ? std::numeric_limits<double>::quiet_NaN() : static_cast<double>(n) / static_cast<double>(rays);
  }
};

/// The result of measure(): one ClassStats per pixel class and one over all pixels.
struct Metrics {
  std::array<ClassStats, 4> classes;  ///< indexed by PixelClass
  ClassStats all;                     ///< every pixel: the classes combined

  const ClassStats& operator[](PixelClass c) const { return classes[static_cast<std::size_t>(c)]; }
};

namespace detail {
inline std::string pixel_name(const Frame& frame, std::size_t pixel) {
  return "pixel #" + std::to_string(pixel) + " (x " + std::to_string(pixel % frame.width) + ", y " +
         std::to_string(pixel / frame.width) + ")";
}

/// Throws unless the frame has pixels.
inline void check_grid(const Frame& frame, std::string_view call) {
  if (frame.width == 0 || frame.height == 0) {
    throw UsageError(std::string(call) + ": frame is " + std::to_string(frame.width) + "x" +
                     std::to_string(frame.height) + "; width and height must be positive");
  }
}

/// Throws unless the frame has pixels and every pixel angle is finite and positive.
inline void check_frame(const Frame& frame, std::string_view call) {
  check_grid(frame, call);
  const std::string where(call);
  const auto bad = [](double a) { return !(std::isfinite(a) && a > 0.0); };
  if (frame.pixel_angles.empty()) {
    if (bad(frame.pixel_angle)) {
      throw UsageError(where + ": pixel_angle " + number(frame.pixel_angle) + " is not a positive finite "
                       "angle; pass the radians one pixel subtends (Camera::pixel_angle)");
    }
    return;
  }
  if (frame.pixel_angles.size() != frame.pixels()) {
    throw UsageError(where + ": pixel_angles has " + std::to_string(frame.pixel_angles.size()) + " values for " +
                     std::to_string(frame.pixels()) + " pixels; pass one per pixel, or none to use pixel_angle");
  }
  for (std::size_t i = 0; i < frame.pixel_angles.size(); ++i) {
    if (bad(frame.pixel_angles[i])) {
      throw UsageError(where + ": pixel_angles[" + std::to_string(i) + "] = " + number(frame.pixel_angles[i]) +
                       " is not a positive finite angle; pass the radians the pixel subtends");
    }
  }
}

/// Throws unless a per-pixel array has exactly width * height elements.
inline void check_count(std::size_t count, const Frame& frame, std::string_view what, std::string_view call) {
  if (count != frame.pixels()) {
    throw UsageError(std::string(call) + ": " + std::string(what) + " has " + std::to_string(count) +
                     " elements for a " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                     " frame; pass one per pixel (" + std::to_string(frame.pixels()) + "), row-major");
  }
}

inline bool all_finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

/// Throws on a reference that would make the statistics meaningless: a bad outcome, or a hit without
/// a positive finite t (the footprint divides by it) or with a non-finite normal.
inline void check_references(std::span<const Reference> refs, const Frame& frame, std::string_view call) {
  for (std::size_t i = 0; i < refs.size(); ++i) {
    const Reference& r = refs[i];
    if (r.outcome != Outcome::miss && r.outcome != Outcome::hit && r.outcome != Outcome::undetermined) {
      throw UsageError(std::string(call) + ": reference " + pixel_name(frame, i) + " has outcome " +
                       std::to_string(static_cast<int>(r.outcome)) + "; use Outcome::hit, miss or undetermined");
    }
    if (r.outcome == Outcome::hit && (!(std::isfinite(r.t) && r.t > 0.0) || !all_finite(r.normal))) {
      throw UsageError(std::string(call) + ": reference " + pixel_name(frame, i) + " is a hit at t " +
                       number(r.t) + " with normal (" + number(r.normal.x) + ", " + number(r.normal.y) +
                       ", " + number(r.normal.z) + "); a hit needs a finite "
                       "t > 0 and a finite normal: fix the ground truth, or mark the ray Outcome::undetermined");
    }
  }
}

/// Angle between two normals in degrees. atan2(|a x b|, a . b) keeps precision at small angles, where
/// acos(a . b) loses half the digits. A zero method normal points nowhere: the worst case, 180.
inline double angle_degrees(glm::dvec3 method, glm::dvec3 reference) {
  const double lm = glm::length(method);
  if (lm == 0.0) return 180.0;
  const glm::dvec3 a = method / lm, b = glm::normalize(reference);
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * (180.0 / std::numbers::pi);
}

/// Counts of one class and the values its distributions are made from.
struct Accumulator {
  ClassStats stats;
  std::vector<double> depth, normal, steps;

  void add(const Sample& s, const Reference& r, double pixel_angle) {
    if (r.outcome == Outcome::undetermined) {
      ++stats.undetermined;
      return;
    }
    ++stats.rays;
    const bool ref_hit = r.outcome == Outcome::hit;
    if (s.hit == ref_hit) ++stats.agree;
    else if (s.hit) ++stats.false_hits;
    else ++stats.false_misses;
    const bool t_ok = std::isfinite(s.t), n_ok = all_finite(s.normal);
    if ((s.flags & flags::nan_seen) != 0 || !std::isfinite(s.steps) || (s.hit && !(t_ok && n_ok))) ++stats.nonfinite;
    if ((s.flags & flags::exhausted) != 0) ++stats.exhausted;
    if ((s.flags & flags::started_inside) != 0) ++stats.started_inside;
    if (std::isfinite(s.steps)) steps.push_back(s.steps);
    if (!(s.hit && ref_hit)) return;
    ++stats.both_hit;
    if (t_ok) depth.push_back(std::abs(s.t - r.t) / (r.t * pixel_angle));
    if (t_ok && (s.t - r.t) / (r.t * pixel_angle) > wrong_surface_footprints) ++stats.wrong_surface;
    if (n_ok && r.normal != glm::dvec3(0.0)) normal.push_back(angle_degrees(s.normal, r.normal));
  }

  ClassStats finish() const {
    ClassStats out = stats;
    out.depth = summarize(depth);
    out.normal_degrees = summarize(normal);
    out.steps = summarize(steps);
    return out;
  }
};
}  // namespace detail

/// Each pixel's class from the reference hit mask (rule in the header comment), row-major.
/// Throws UsageError for a frame without pixels or a reference count other than width * height.
inline std::vector<PixelClass> classify(const Frame& frame, std::span<const Reference> references) {
  constexpr std::string_view call = "accuracy::classify";
  detail::check_grid(frame, call);  // the angles are not needed to classify
  detail::check_count(references.size(), frame, "references", call);
  const auto w = static_cast<std::ptrdiff_t>(frame.width), h = static_cast<std::ptrdiff_t>(frame.height);
  const auto hit = [&](std::ptrdiff_t x, std::ptrdiff_t y) {
    return references[static_cast<std::size_t>(y * w + x)].outcome == Outcome::hit;
  };
  std::vector<PixelClass> classes(frame.pixels());
  for (std::ptrdiff_t y = 0; y < h; ++y) {
    for (std::ptrdiff_t x = 0; x < w; ++x) {
      const bool own = hit(x, y);
      std::ptrdiff_t nearest = 3;  // Chebyshev distance to the other state, 3 meaning "beyond the band"
      for (std::ptrdiff_t dy = -2; dy <= 2; ++dy) {
        for (std::ptrdiff_t dx = -2; dx <= 2; ++dx) {
          const std::ptrdiff_t nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= w || ny >= h || hit(nx, ny) == own) continue;
          nearest = std::min(nearest, std::max(std::abs(dx), std::abs(dy)));
        }
      }
      classes[static_cast<std::size_t>(y * w + x)] = nearest == 1   ? PixelClass::silhouette_1px
                                                     : nearest == 2 ? PixelClass::silhouette_2px
                                                     : own          ? PixelClass::interior
                                                                    : PixelClass::far;
    }
  }
  return classes;
}

namespace detail {
/// measure()'s core, on checked inputs: pixel i counted weight(i) times (0: left out of every
/// statistic, its reference still classing its neighbours; a sample standing for that many
/// pixels: accuracy/stratified.hpp).
template <class Weight>
Metrics accumulate(const Frame& frame, std::span<const Sample> samples, std::span<const Reference> references,
                   const Weight& weight) {
  const std::vector<PixelClass> classes = classify(frame, references);
  std::array<Accumulator, 4> per_class;
  Accumulator all;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    for (std::uint32_t k = weight(i); k > 0; --k) {
      per_class[static_cast<std::size_t>(classes[i])].add(samples[i], references[i], frame.angle(i));
      all.add(samples[i], references[i], frame.angle(i));
    }
  }
  Metrics m;
  for (std::size_t c = 0; c < per_class.size(); ++c) m.classes[c] = per_class[c].finish();
  m.all = all.finish();
  return m;
}
}  // namespace detail

/// Compares the method's samples with the reference, pixel by pixel, per class and overall. Throws
/// UsageError for a bad frame (no pixels, a non-positive or non-finite pixel angle), sizes other than
/// width * height, or an invalid reference (see Reference). The method's outputs are data, never an
/// error: NaN, Inf and negative values are counted or measured, not rejected.
inline Metrics measure(const Frame& frame, std::span<const Sample> samples, std::span<const Reference> references) {
  constexpr std::string_view call = "accuracy::measure";
  detail::check_frame(frame, call);
  detail::check_count(samples.size(), frame, "samples", call);
  detail::check_count(references.size(), frame, "references", call);
  detail::check_references(references, frame, call);
  return detail::accumulate(frame, samples, references, [](std::size_t) { return 1u; });
}

/// Peak signal-to-noise ratio in dB of two images of the same layout (any channels, any order):
/// 10 log10(peak^2 / MSE) over every value. Returns +infinity for equal images, NaN if either holds a
/// NaN. Throws UsageError for empty or differently sized images, or a peak that is not positive and finite.
inline double psnr(std::span<const float> a, std::span<const float> b, double peak = 1.0) {
  if (a.size() != b.size() || a.empty()) {
    throw UsageError("accuracy::psnr: images of " + std::to_string(a.size()) + " and " + std::to_string(b.size()) +
                     " values; pass two non-empty images of the same size and channel layout");
  }
  if (!(std::isfinite(peak) && peak > 0.0)) {
    throw UsageError("accuracy::psnr: peak " + detail::number(peak) + " is not positive and finite; "
                     "pass the largest value a channel can hold (1 for float, 255 for 8 bit)");
  }
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double d = static_cast<double>(a[i]) - static_cast<double>(b[i]);
    sum += d * d;
  }
  const double mse = sum / static_cast<double>(a.size());
  if (mse == 0.0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(peak * peak / mse);
}

}  // namespace proceduray::accuracy
