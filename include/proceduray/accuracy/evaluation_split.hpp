// Where a frame's evaluations go, by what the ground truth says of each ray: rays that hit,
// rays that pass near a surface and miss (within 2 pixels of a silhouette: a march slows down
// beside a surface it never crosses), and rays that miss far. The answer to "what does the
// accuracy cost": a method that meets the budget with fewer evaluations per near miss is the
// cheaper exact hit.
//
//   namespace acc = proceduray::accuracy;
//   const acc::Frame frame{.width = 320, .height = 240, .pixel_angle = 1.0e-3};
//   std::vector<acc::Reference> truth(frame.pixels());    // the ground truth per pixel
//   std::vector<acc::Sample> samples(frame.pixels());     // the render: samples[i].steps its evaluations
//   const acc::EvaluationSplit s = acc::split_evaluations(frame, truth, samples);  // + weights: stratified
//   const double near = s.near_miss.per_ray();            // mean evaluations of a near miss
//   const double share = s.share(s.near_miss);            // its fraction of all the frame's evaluations
//   const std::vector<acc::RayClass> c = acc::ray_classes(frame, truth);   // per pixel, for a heat map
//
// Samples' `steps` are the evaluations (the steps output). Undetermined truths are left out; a
// weight of 0 leaves a pixel out, k counts it k times (accuracy/stratified.hpp's samples).
#pragma once

#include <proceduray/accuracy/metrics.hpp>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string_view>
#include <vector>

namespace proceduray::accuracy {

/// Evaluations of one class of rays.
struct EvaluationClass {
  double rays = 0.0;         ///< rays of the class (weighted)
  double evaluations = 0.0;  ///< their evaluations (weighted)
  /// Mean evaluations per ray of the class; NaN without rays.
  double per_ray() const {
    return rays > 0.0 ? evaluations / rays : std::numeric_limits<double>::quiet_NaN();
  }
};

/// A frame's evaluations split by ray class.
struct EvaluationSplit {
  EvaluationClass hit;        ///< the truth hits
  EvaluationClass near_miss;  ///< the truth misses within 2 pixels of a silhouette
  EvaluationClass far_miss;   ///< the truth misses farther out
  /// Every class's evaluations together.
  double evaluations() const { return hit.evaluations + near_miss.evaluations + far_miss.evaluations; }
  /// A class's fraction of all the evaluations; NaN when there are none.
  double share(const EvaluationClass& c) const {
    const double all = evaluations();
    return all > 0.0 ? c.evaluations / all : std::numeric_limits<double>::quiet_NaN();
  }
};

/// A ray's class by its truth. The values are what proceduray_accuracy --classes-csv writes.
enum class RayClass : std::uint8_t {
  unknown = 0,    ///< undetermined truth, or a pixel a stratified truth left out (weight 0)
  hit = 1,        ///< the truth hits
  near_miss = 2,  ///< the truth misses within 2 pixels of a silhouette
  far_miss = 3,   ///< the truth misses farther out
};

/// Each pixel's RayClass (classify's bands for the near misses). Throws UsageError for a truth
/// of another count than frame's pixels, or weights of another count.
inline std::vector<RayClass> ray_classes(const Frame& frame, std::span<const Reference> truth,
                                         std::span<const std::uint32_t> weights = {}) {
  const std::vector<PixelClass> bands = classify(frame, truth);  // checks the grid and the truth's count
  if (!weights.empty()) detail::check_count(weights.size(), frame, "weights", "accuracy::ray_classes");
  std::vector<RayClass> out(truth.size(), RayClass::unknown);
  for (std::size_t i = 0; i < truth.size(); ++i) {
    if ((!weights.empty() && weights[i] == 0) || truth[i].outcome == Outcome::undetermined) continue;
    const bool near = bands[i] == PixelClass::silhouette_1px || bands[i] == PixelClass::silhouette_2px;
    out[i] = truth[i].outcome == Outcome::hit ? RayClass::hit : (near ? RayClass::near_miss : RayClass::far_miss);
  }
  return out;
}

/// Splits the samples' evaluations by their truth's class (ray_classes). Throws UsageError for
/// counts other than frame's pixels, or weights of another count.
inline EvaluationSplit split_evaluations(const Frame& frame, std::span<const Reference> truth,
                                         std::span<const Sample> samples,
                                         std::span<const std::uint32_t> weights = {}) {
  detail::check_count(samples.size(), frame, "samples", "accuracy::split_evaluations");
  const std::vector<RayClass> classes = ray_classes(frame, truth, weights);
  EvaluationSplit out;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (classes[i] == RayClass::unknown) continue;
    const double w = weights.empty() ? 1.0 : static_cast<double>(weights[i]);
    EvaluationClass& c = classes[i] == RayClass::hit ? out.hit
                                                     : (classes[i] == RayClass::near_miss ? out.near_miss : out.far_miss);
    c.rays += w;
    c.evaluations += w * samples[i].steps;
  }
  return out;
}

}  // namespace proceduray::accuracy
