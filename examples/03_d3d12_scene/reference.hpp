// The D3D12 sample's ground truth per camera ray: for every pixel of a width x height image
// (row-major, y down, as raygen.rgen), the nearest primary hit over the ground and every
// primitive, in double and independent of the shaders' marching loops. What an accuracy tool
// compares a render's hits (the debug view's object ids and steps) against.
//
//   const d3d12::SceneConstants constants = d3d12::default_constants(d3d12::sample_camera(48, 32), 2.0f);
//   const d3d12::ReferenceImage truth = d3d12::reference_image(constants, 48, 32);   // the sample's scene
//   const d3d12::Primitive cog = d3d12::default_primitive(d3d12::cog);
//   const d3d12::ReferenceImage alone = d3d12::reference_image(constants, std::span(&cog, 1),
//                                                              d3d12::Layout::sample, 48, 32, {.min_step = 1.0e-7});
//   std::vector<proceduray::accuracy::Sample> samples(48 * 32);   // the render, read back per pixel
//   proceduray::accuracy::Metrics m = proceduray::accuracy::measure(truth.frame(), samples, truth.pixels);
//   truth.objects[5 * 48 + 7];                                 // the debug view's id there (sky_id: none)
//   truth.costs[d3d12::object_id(d3d12::metaballs)].evaluations;   // one object's share
//
// Rays: camera.glsl's camera_ray in double, origin camera.eye, unit direction, so t is a distance
// and the footprint at t is camera.pixel_angle * t (measure's Frame). Each object is found by
// reference_objects.hpp (closed forms for the ground, box and spheres; lipschitz_search for the
// metaballs and the SDFs); the pixel's answer is the nearest hit. An object whose search ran out
// of budget (or whose shape the clipped ray starts in) makes the pixel undetermined unless a
// determined hit lies before where that search stopped: nothing in front of the stop was missed,
// so that hit stands. Only primary rays: shadows and reflections start on the method's own hits.
// Cost (tests/accuracy/d3d12_reference_test.cpp, 48x32, time 2, default options): evaluations per
// ray that reaches the object's AABB (per ray that hits it): box 3 (3), spheres 5 (5), metaballs
// 65 (110; the step is |F - threshold| / L with L = 9.4 at R = 0.6), mini spheres 32 (45), round cube 24
// (44), square torus 20 (54), twisted torus 46 (119; L = 5.2), cog 14 (51), cylinder 31 (47),
// fractal pyramid 27 (43); the ground 1 per ray; 13201 for the image, well under a millisecond.
// A finer floor (1e-9 footprints) adds 2% and moves no hit by more than 4e-12 footprints. Plain
// loops, one thread.
#pragma once

#include <proceduray/accuracy/parallel.hpp>

#include "reference_objects.hpp"

#include <proceduray/accuracy/metrics.hpp>
#include <proceduray/accuracy/nearest.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace d3d12 {

/// One object's share of a reference's cost.
struct ObjectCost {
  std::uint64_t rays = 0;             ///< rays that reached the object's bounds (the ground: every ray)
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
  std::uint32_t object = sky_id;
};

/// The ground truth of an image: per pixel the nearest hit, and the cost of finding it.
struct ReferenceImage {
  std::uint32_t width = 0, height = 0;
  double pixel_angle = 0.0;                         ///< camera.pixel_angle: the footprint per unit t
  std::vector<acc::Reference> pixels;               ///< row-major, pixel = y * width + x
  std::vector<std::uint32_t> objects;               ///< the object id each pixel's reference hit (sky_id: none)
  std::array<ObjectCost, object_id_count> costs{};  ///< by object id (sky_id's stays 0)
  std::uint64_t evaluations = 0;                    ///< the sum of costs[].evaluations
  std::uint64_t undetermined = 0;                   ///< pixels whose reference is Outcome::undetermined

  /// The frame measure() takes for these pixels.
  acc::Frame frame() const { return {.width = width, .height = height, .pixel_angle = pixel_angle}; }
};

/// Unit direction of pixel (x, y) of a width x height image: camera.glsl's camera_ray in double.
inline glm::dvec3 camera_direction(const ReferenceScene& s, std::uint32_t x, std::uint32_t y, std::uint32_t width,
                                   std::uint32_t height) {
  const double u = (static_cast<double>(x) + 0.5) / static_cast<double>(width) * 2.0 - 1.0;
  const double v = (static_cast<double>(y) + 0.5) / static_cast<double>(height) * 2.0 - 1.0;
  return glm::normalize(s.forward + u * s.right - v * s.up);
}

namespace detail {
/// Throws UsageError unless the image has pixels.
inline void check_size(std::uint32_t width, std::uint32_t height) {
  if (width == 0 || height == 0) {
    throw proceduray::UsageError("d3d12::reference_image: image size " + std::to_string(width) + "x" +
                                 std::to_string(height) +
                                 " has no pixels; pass width and height >= 1 (the render's size)");
  }
}

/// Adds one object's search to its cost.
inline void count(ObjectCost& c, const acc::Result& r) {
  ++c.rays;
  c.evaluations += r.evaluations;
  if (r.outcome != acc::Outcome::hit) return;
  ++c.hits;
  c.hit_evaluations += r.evaluations;
}
}  // namespace detail

/// The nearest hit over the ground and every primitive along eye + t dir (dir unit length); adds
/// each search's cost to `costs` (by object id) when given.
inline RayReference reference_ray(const ReferenceScene& s, glm::dvec3 dir,
                                  std::array<ObjectCost, object_id_count>* costs = nullptr) {
  std::vector<std::uint32_t> ids;
  if (s.ground) ids.push_back(plane_id);
  for (const PlacedPrimitive& p : s.primitives) ids.push_back(object_id(p.kind));
  acc::NearestHit nearest;
  for (std::uint32_t id : ids) {
    const ObjectTrace traced = trace_object(s, id, s.eye, dir);
    const acc::Result& r = traced.result;
    if (costs != nullptr && traced.entered) detail::count((*costs)[id], r);
    nearest.add(r, id);
  }
  RayReference best;
  best.reference = nearest.reference();
  best.object = static_cast<std::uint32_t>(nearest.object(sky_id));
  return best;
}

/// What one worker of reference_image adds up over its rows.
struct RowTally {
  std::array<ObjectCost, object_id_count> costs{};
  std::uint64_t undetermined = 0;
};

/// Row y of the image into out (width entries from out.pixels[y * width], written by this call
/// only); costs and undetermined pixels into `tally`.
inline void reference_row(const ReferenceScene& s, std::uint32_t y, ReferenceImage& out, RowTally& tally) {
  for (std::uint32_t x = 0; x < out.width; ++x) {
    const glm::dvec3 dir = camera_direction(s, x, y, out.width, out.height);
    if (!acc::detail::finite(dir)) {
      throw proceduray::UsageError("d3d12::reference_image: pixel (" + std::to_string(x) + ", " + std::to_string(y) +
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

/// The reference of every pixel of a width x height image of a prepared scene. Throws UsageError
/// for a zero size or a degenerate camera.
inline ReferenceImage reference_image(const ReferenceScene& s, std::uint32_t width, std::uint32_t height) {
  detail::check_size(width, height);
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

/// The reference of `primitives` placed by `layout` (the scene D3d12Scene(primitives, layout)
/// builds) under `constants` (camera, time). Throws UsageError as reference_scene and
/// reference_image do, naming the call, the value and the fix.
inline ReferenceImage reference_image(const SceneConstants& constants, std::span<const Primitive> primitives,
                                      Layout layout, std::uint32_t width, std::uint32_t height,
                                      const ReferenceOptions& options = {}) {
  detail::check_size(width, height);
  return reference_image(reference_scene(constants, primitives, layout, options), width, height);
}

/// The reference of the sample's scene (default_primitives() on the ground) under `constants`.
inline ReferenceImage reference_image(const SceneConstants& constants, std::uint32_t width, std::uint32_t height,
                                      const ReferenceOptions& options = {}) {
  detail::check_size(width, height);
  return reference_image(reference_scene(constants, options), width, height);
}

}  // namespace d3d12
