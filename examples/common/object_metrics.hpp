// One object's view of a scene's accuracy: the metrics where the reference sees that object
// or the render's hit is on it, and the evaluations its rays took. Shared by the example
// scenes' accuracy headers and tools/accuracy.
//
//   // truth: a reference image (frame(), pixels); truth_ids, seen: each pixel's object id in
//   // the reference and in the render; samples: the render's per-pixel outputs
//   proceduray::accuracy::Metrics m = examples::measure_object(truth.frame(),
//       std::span<const proceduray::accuracy::Reference>(truth.pixels),
//       std::span<const std::uint32_t>(truth_ids), samples, std::span<const std::uint32_t>(seen), 3u);
//   double steps = examples::mean_steps(std::span<const std::uint32_t>(truth_ids),
//       std::span<const proceduray::accuracy::Sample>(samples), std::span<const std::uint32_t>(seen), 3u);
//   proceduray::accuracy::Metrics all = examples::measure_frame(truth.frame(), samples, truth.pixels);  // every object
//
// A reference on a stratified sample (accuracy/stratified.hpp) passes its weights (how many pixels
// each traced pixel stands for; 0: not traced) and stride: both then estimate the full frame's.
//
// The reference keeps its hits only where it sees the object and the render only where its
// hit is on the object, so silhouettes are that object's against everything else, and a false
// hit of one object in front of another counts against the one in front.
#pragma once

#include <proceduray/accuracy/evaluation_split.hpp>
#include <proceduray/accuracy/metrics.hpp>
#include <proceduray/accuracy/stratified.hpp>
#include <proceduray/error.hpp>

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace examples {

/// The metrics of a whole frame: measure(), or on a stratified reference (weights given)
/// measure_stratified(), which estimates them.
inline proceduray::accuracy::Metrics measure_frame(const proceduray::accuracy::Frame& frame,
                                                   std::span<const proceduray::accuracy::Sample> samples,
                                                   std::vector<proceduray::accuracy::Reference> reference,
                                                   std::span<const std::uint32_t> weights = {}, std::uint32_t stride = 1) {
  namespace acc = proceduray::accuracy;
  if (weights.empty()) return acc::measure(frame, samples, reference);  // throws for sizes that differ
  acc::StratifiedTruth truth;
  truth.pixels = std::move(reference);
  truth.weight.assign(weights.begin(), weights.end());
  truth.stride = stride;
  return acc::measure_stratified(frame, samples, truth);  // throws for sizes that differ
}

/// The reference seen by one object: its hits where it sees `object`, misses elsewhere.
template <class Id>
std::vector<proceduray::accuracy::Reference> object_reference(std::span<const proceduray::accuracy::Reference> reference,
                                                              std::span<const Id> reference_objects, Id object) {
  namespace acc = proceduray::accuracy;
  std::vector<acc::Reference> refs(reference.begin(), reference.end());
  for (std::size_t i = 0; i < refs.size() && i < reference_objects.size(); ++i) {
    if (refs[i].outcome == acc::Outcome::hit && reference_objects[i] != object) refs[i] = {.outcome = acc::Outcome::miss};
  }
  return refs;
}

/// Where the frame's evaluations go, by the object's view of the reference: the rays that hit it,
/// those that miss it within 2 pixels of its silhouette, the rest (accuracy/evaluation_split.hpp).
/// A pixel's evaluations are all its ray's, so a near miss in front of another object counts that one's too.
template <class Id>
proceduray::accuracy::EvaluationSplit split_object(const proceduray::accuracy::Frame& frame,
                                                   std::span<const proceduray::accuracy::Reference> reference,
                                                   std::span<const Id> reference_objects,
                                                   std::span<const proceduray::accuracy::Sample> samples, Id object,
                                                   std::span<const std::uint32_t> weights = {}) {
  if (reference_objects.size() != reference.size()) {
    throw proceduray::UsageError("examples::split_object: " + std::to_string(reference_objects.size()) +
                                 " reference object ids for " + std::to_string(reference.size()) +
                                 " pixels; pass one id per pixel of the same frame");
  }
  const std::vector<proceduray::accuracy::Reference> refs = object_reference(reference, reference_objects, object);
  return proceduray::accuracy::split_evaluations(frame, refs, samples, weights);
}

template <class Id>
proceduray::accuracy::Metrics measure_object(const proceduray::accuracy::Frame& frame,
                                             std::span<const proceduray::accuracy::Reference> reference,
                                             std::span<const Id> reference_objects,
                                             std::span<const proceduray::accuracy::Sample> samples,
                                             std::span<const Id> seen, Id object,
                                             std::span<const std::uint32_t> weights = {}, std::uint32_t stride = 1) {
  namespace acc = proceduray::accuracy;
  if (reference_objects.size() != reference.size() || seen.size() != samples.size()) {
    throw proceduray::UsageError("examples::measure_object: " + std::to_string(reference_objects.size()) +
                                 " reference object ids for " + std::to_string(reference.size()) + " pixels and " +
                                 std::to_string(seen.size()) + " rendered ids for " + std::to_string(samples.size()) +
                                 " samples; pass one id per pixel of the same frame");
  }
  std::vector<acc::Reference> refs = object_reference(reference, reference_objects, object);
  std::vector<acc::Sample> mine(samples.begin(), samples.end());
  for (std::size_t i = 0; i < mine.size(); ++i) {
    if (mine[i].hit && seen[i] != object) mine[i].hit = false;
  }
  return measure_frame(frame, mine, std::move(refs), weights, stride);
}

/// Mean evaluations over the rays that see the object in the reference or in the render.
template <class Id>
double mean_steps(std::span<const Id> reference_objects, std::span<const proceduray::accuracy::Sample> samples,
                  std::span<const Id> seen, Id object, std::span<const std::uint32_t> weights = {}) {
  if (reference_objects.size() != samples.size() || seen.size() != samples.size()) {
    throw proceduray::UsageError("examples::mean_steps: " + std::to_string(reference_objects.size()) + " reference ids, " +
                                 std::to_string(seen.size()) + " rendered ids and " + std::to_string(samples.size()) +
                                 " samples; pass one of each per pixel of the same frame");
  }
  // On a stratified sample, the traced pixels each count as many as they stand for.
  double steps = 0.0, rays = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double w = weights.empty() ? 1.0 : double(weights[i]);
    if (w == 0.0 || (reference_objects[i] != object && seen[i] != object)) continue;
    steps += w * samples[i].steps;
    rays += w;
  }
  return rays > 0.0 ? steps / rays : 0.0;
}

}  // namespace examples
