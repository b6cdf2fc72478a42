// The paper scene's ground truth per camera ray: for every pixel of a width x height image
// (row-major, y down, as raygen.rgen), the nearest primary hit over all objects, in double and
// independent of the sphere tracer. What an accuracy tool compares a render's hits against.
//
//   const paper::Frame constants = paper::default_frame(48, 32, 0.0f);
//   const paper::ReferenceImage truth = paper::reference_image(constants, 48, 32);   // ~1e-3 footprints
//   const paper::ReferenceImage coarse = paper::reference_image(constants, 48, 32, {.spacing = 1.0e-2});
//   const paper::ReferenceImage longer = paper::reference_image(constants, 48, 32, {.iteration_factor = 2});
//   std::vector<proceduray::accuracy::Sample> samples(48 * 32);   // the render, read back per pixel
//   proceduray::accuracy::Metrics m = proceduray::accuracy::measure(truth.frame(), samples, truth.pixels);
//   truth.objects[5 * 48 + 7];        // which object pixel (7, 5) sees (sky_id on a miss)
//   truth.evaluations;                // the reference's whole cost
//   truth.costs[paper::mandelbulb_id].evaluations;   // one object's share
//
// Rays: camera.glsl's camera_ray in double, origin camera.eye, unit direction, so t is a
// distance and the footprint at t is camera.pixel_angle * t (measure's Frame). Each object is
// found by reference_objects.hpp (closed form for the plane, lipschitz_search for the Pac-men,
// escape-test predicate_search for the fractals); the pixel's answer is the nearest hit. An
// object whose search ran out of budget (or whose bounds the ray starts in) makes the pixel
// undetermined unless a determined hit lies before where that search stopped: nothing in front
// of the stop was missed, so that hit stands. Only primary rays: shadows and reflections depend
// on the method's own hit points, and are not what this reference measures.
// Cost: the fractal searches dominate, ~ (chord through the AABB) / (options.spacing footprints),
// so per ray it grows with 1 / spacing and with the image height. Seen at 48x32, default spacing:
// per hit ray Mandelbulb 3.6e3 escape tests, Julia 6.3e3 (misses through the box 6.7e3, 7.8e3),
// Pac-man 47, 2e6 in all, 0.15 s in a Release build; 1024x768 needs ~24 times as many per ray.
// Plain loops, one thread.
#pragma once

#include <proceduray/accuracy/parallel.hpp>

#include "reference_objects.hpp"

#include <proceduray/accuracy/metrics.hpp>
#include <proceduray/accuracy/nearest.hpp>
#include <proceduray/accuracy/stratified.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace paper {

/// One object's share of a reference's cost.
struct ObjectCost {
  std::uint64_t rays = 0;             ///< rays that reached the object's bounds (the plane: every ray)
  std::uint64_t hits = 0;             ///< of those, rays that hit it (nearest or not)
  std::uint64_t evaluations = 0;      ///< evaluations on all those rays
  std::uint64_t hit_evaluations = 0;  ///< evaluations on the rays that hit it

  ObjectCost& operator+=(const ObjectCost& o) {
    rays += o.rays;
    hits += o.hits;
    evaluations += o.evaluations;
    hit_evaluations += o.hit_evaluations;
    return *this;
  }
};

/// The nearest hit along one ray, and the object it belongs to (sky_id on a miss or undetermined).
struct RayReference {
  acc::Reference reference{};
  ObjectId object = sky_id;
};

/// The ground truth of an image: per pixel the nearest hit, and the cost of finding it.
struct ReferenceImage {
  std::uint32_t width = 0, height = 0;
  double pixel_angle = 0.0;                 ///< camera.pixel_angle: the footprint per unit t
  std::vector<acc::Reference> pixels;       ///< row-major, pixel = y * width + x
  std::vector<ObjectId> objects;            ///< the object each pixel's reference hit (sky_id: none)
  std::array<ObjectCost, 6> costs{};        ///< by ObjectId (sky_id's stays 0)
  std::uint64_t evaluations = 0;            ///< the sum of costs[].evaluations: every search's Result::evaluations
  std::uint64_t undetermined = 0;           ///< pixels whose reference is Outcome::undetermined
  /// A stratified reference (stratified_reference_image): how many pixels each pixel stands for
  /// (0: not traced; its object the last traced one's to its left); empty: every pixel traced.
  std::vector<std::uint32_t> weights;
  std::uint32_t stride = 1;                 ///< one pixel in this many traced outside the band
  std::size_t traced = 0;                   ///< pixels traced

  /// The frame measure() takes for these pixels.
  acc::Frame frame() const { return {.width = width, .height = height, .pixel_angle = pixel_angle}; }
};

/// Every object with geometry, in the order they are searched.
inline constexpr std::array<ObjectId, 5> reference_objects{plane_id, pacman0_id, pacman1_id, julia_id, mandelbulb_id};

/// Unit direction of pixel (x, y) of a width x height image: camera.glsl's camera_ray in double.
inline glm::dvec3 camera_direction(const ReferenceScene& s, std::uint32_t x, std::uint32_t y, std::uint32_t width,
                                   std::uint32_t height) {
  const double u = (static_cast<double>(x) + 0.5) / static_cast<double>(width) * 2.0 - 1.0;
  const double v = (static_cast<double>(y) + 0.5) / static_cast<double>(height) * 2.0 - 1.0;
  return glm::normalize(s.forward + u * s.right - v * s.up);
}

/// The nearest hit over every object along eye + t dir (dir unit length); adds each search's cost
/// to `costs` (by ObjectId) when given.
inline RayReference reference_ray(const ReferenceScene& s, glm::dvec3 dir, std::array<ObjectCost, 6>* costs = nullptr) {
  acc::NearestHit nearest;
  for (ObjectId id : reference_objects) {
    const ObjectTrace traced = trace_object(s, id, s.eye, dir);
    const acc::Result& r = traced.result;
    if (costs != nullptr && traced.entered) {
      ObjectCost& c = (*costs)[id];
      ++c.rays;
      c.evaluations += r.evaluations;
      if (r.outcome == acc::Outcome::hit) {
        ++c.hits;
        c.hit_evaluations += r.evaluations;
      }
    }
    nearest.add(r, id);
  }
  RayReference best;
  best.reference = nearest.reference();
  best.object = static_cast<ObjectId>(nearest.object(sky_id));
  return best;
}

/// What one worker of reference_image adds up over its rows.
struct RowTally {
  std::array<ObjectCost, 6> costs{};
  std::uint64_t undetermined = 0;
};

/// Row y of the image into out (width entries from out.pixels[y * width], written by this call
/// only); costs and undetermined pixels into `tally`.
inline void reference_row(const ReferenceScene& s, std::uint32_t y, ReferenceImage& out, RowTally& tally) {
  for (std::uint32_t x = 0; x < out.width; ++x) {
    const glm::dvec3 dir = camera_direction(s, x, y, out.width, out.height);
    if (!acc::detail::finite(dir)) {
      throw proceduray::UsageError("paper::reference_image: pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                   ") has direction " + acc::detail::show(dir) + "; pass a camera whose forward, right "
                                   "and up span a view (proceduray::look_at)");
    }
    const RayReference r = reference_ray(s, dir, &tally.costs);
    const std::size_t pixel = static_cast<std::size_t>(y) * out.width + x;
    out.pixels[pixel] = r.reference;
    out.objects[pixel] = r.object;
    tally.undetermined += r.reference.outcome == acc::Outcome::undetermined;
  }
}

/// The reference of every pixel of a width x height image of `constants` (camera, time, iteration
/// counts). Throws UsageError for a zero size, a non-finite or degenerate camera, or a bad option,
/// naming the call, the value and the fix.
inline ReferenceImage reference_image(const Frame& constants, std::uint32_t width, std::uint32_t height,
                                      const ReferenceOptions& options = {}) {
  if (width == 0 || height == 0) {
    throw proceduray::UsageError("paper::reference_image: image size " + std::to_string(width) + "x" +
                                 std::to_string(height) + " has no pixels; pass width and height >= 1 (the render's size)");
  }
  const ReferenceScene s = reference_scene(constants, options);
  ReferenceImage out;
  out.width = width;
  out.height = height;
  out.pixel_angle = s.pixel_angle;
  out.pixels.resize(static_cast<std::size_t>(width) * height);
  out.objects.resize(out.pixels.size(), sky_id);
  // Every core (accuracy/parallel.hpp): each ray's truth depends on that ray alone.
  std::vector<RowTally> tally(acc::worker_count());
  acc::parallel_rows(
      height, [&](std::uint32_t y, std::uint32_t worker) { reference_row(s, y, out, tally[worker]); },
      static_cast<std::uint32_t>(tally.size()));
  for (const RowTally& t : tally) {
    for (std::size_t i = 0; i < out.costs.size(); ++i) out.costs[i] += t.costs[i];
    out.undetermined += t.undetermined;
  }
  for (const ObjectCost& c : out.costs) out.evaluations += c.evaluations;
  return out;
}

/// The reference on a stratified sample (accuracy/stratified.hpp): every pixel near a silhouette
/// or a depth jump, and one in `stride` elsewhere, standing for `stride` pixels (weights), on
/// every core. Costs are not counted (costs, evaluations stay 0). stride 1: reference_image's
/// pixels and objects, every weight 1. Throws what reference_image throws, and UsageError for a
/// stride of 0.
inline ReferenceImage stratified_reference_image(const Frame& constants, std::uint32_t width,
                                                 std::uint32_t height, std::uint32_t stride,
                                                 const ReferenceOptions& options = {}) {
  if (width == 0 || height == 0) return reference_image(constants, width, height, options);  // its error
  const ReferenceScene s = reference_scene(constants, options);
  ReferenceImage out;
  out.width = width;
  out.height = height;
  out.pixel_angle = s.pixel_angle;
  out.objects.assign(static_cast<std::size_t>(width) * height, sky_id);
  std::vector<std::uint8_t> known(out.objects.size(), 0);
  acc::StratifiedTruth truth = acc::stratified_truth(out.frame(), stride, 1, [&](std::uint32_t x, std::uint32_t y) {
    const glm::dvec3 dir = camera_direction(s, x, y, width, height);
    const RayReference r = reference_ray(s, dir);
    const std::size_t pixel = static_cast<std::size_t>(y) * width + x;
    out.objects[pixel] = r.object;  // this pixel's only: no other trace writes it
    known[pixel] = 1;
    return r.reference;
  });
  // A pixel not traced takes its block's outcome (stratified.hpp) and, for one object's view of
  // the classes, the object of the last traced pixel to its left (blocks off the band hold one).
  for (std::uint32_t y = 0; y < height; ++y) {
    const std::size_t row = static_cast<std::size_t>(y) * width;
    ObjectId last = sky_id;
    for (std::uint32_t x = 0; x < width; ++x) {
      if (known[row + x]) last = out.objects[row + x];
      else out.objects[row + x] = last;
    }
  }
  out.pixels = std::move(truth.pixels);
  out.weights = std::move(truth.weight);
  out.stride = truth.stride;
  out.traced = truth.traced;
  for (std::size_t i = 0; i < out.pixels.size(); ++i) {
    out.undetermined += out.weights[i] > 0 && out.pixels[i].outcome == acc::Outcome::undetermined;
  }
  return out;
}

}  // namespace paper
