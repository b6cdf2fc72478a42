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

/// Splits the samples' evaluations by their truth's class (classify's bands for the near
/// misses). Throws UsageError for counts other than frame's pixels, or weights of another count.
inline EvaluationSplit split_evaluations(const Frame& frame, std::span<const Reference> truth,
                                         std::span<const Sample> samples,
                                         std::span<const std::uint32_t> weights = {}) {
  constexpr std::string_view call = "accuracy::split_evaluations";
  const std::vector<PixelClass> classes = classify(frame, truth);  // checks the grid and the truth's count
  detail::check_count(samples.size(), frame, "samples", call);
  if (!weights.empty()) detail::check_count(weights.size(), frame, "weights", call);
  EvaluationSplit out;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double w = weights.empty() ? 1.0 : static_cast<double>(weights[i]);
    if (w == 0.0 || truth[i].outcome == Outcome::undetermined) continue;
    const bool near = classes[i] == PixelClass::silhouette_1px || classes[i] == PixelClass::silhouette_2px;
    EvaluationClass& c = truth[i].outcome == Outcome::hit ? out.hit : (near ? out.near_miss : out.far_miss);
    c.rays += w;
    c.evaluations += w * samples[i].steps;
  }
  return out;
}

}  // namespace proceduray::accuracy
