// The paper scene measured against its ground truth, per object: which object a device hit
// belongs to (from the ids output) and one object's view of the metrics.
//
//   const paper::PaperScene scene(paper::accuracy_outputs);
//   // ... render with secondary rays off, read back frame.outputs ...
//   std::vector<paper::ObjectId> seen = paper::device_objects(renderer.plan(), frame.outputs.ids);
//   proceduray::accuracy::Metrics bulb = paper::measure_object(truth, samples, seen, paper::mandelbulb_id);
//
// One object's view: the reference hits only where it sees that object and the render only where
// its hit is on that object, so silhouettes are that object's against everything else, and a
// false hit of one object in front of another counts against the one in front.
#pragma once

#include "paper_scene.hpp"
#include "reference.hpp"
#include "../common/object_metrics.hpp"

#include <proceduray/accuracy/metrics.hpp>

#include <array>
#include <span>
#include <utility>
#include <vector>

namespace paper {

/// What the accuracy tool and tests ask the scene for.
inline constexpr pr::OutputSet accuracy_outputs{pr::Output::t, pr::Output::normal, pr::Output::ids, pr::Output::steps,
                                               pr::Output::flags};

/// The objects with their names, in ObjectId order.
inline constexpr std::array<std::pair<ObjectId, const char*>, 5> named_objects{
    {{plane_id, "plane"}, {pacman0_id, "pacman0"}, {pacman1_id, "pacman1"}, {julia_id, "julia"}, {mandelbulb_id, "mandelbulb"}}};

/// The object a device hit belongs to, from its TLAS instance (ids output, as compile() numbered
/// the instances): the instance's BLAS names the geometry, its index among them the Pac-man.
inline ObjectId object_of(const pr::Plan& plan, std::uint32_t instance) {
  if (instance >= plan.instances().size()) return sky_id;
  const pr::TlasInstance& in = plan.instances()[instance];
  for (const pr::PlannedGeometry& g : plan.geometries()) {
    if (g.blas != in.blas) continue;
    if (g.name == "plane") return plane_id;
    if (g.name == "pacman") return in.instance == 0 ? pacman0_id : pacman1_id;
    if (g.name == "julia") return julia_id;
    if (g.name == "mandelbulb") return mandelbulb_id;
  }
  return sky_id;
}

/// Every pixel's object from a frame's ids output (four uints per pixel).
inline std::vector<ObjectId> device_objects(const pr::Plan& plan, std::span<const std::uint32_t> ids) {
  std::vector<ObjectId> out(ids.size() / 4);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = object_of(plan, ids[4 * i]);
  return out;
}

/// The metrics of one object's view (see the top of this header).
inline pr::accuracy::Metrics measure_object(const ReferenceImage& truth, std::span<const pr::accuracy::Sample> samples,
                                            std::span<const ObjectId> seen, ObjectId object) {
  return examples::measure_object(truth.frame(), std::span<const pr::accuracy::Reference>(truth.pixels),
                                  std::span<const ObjectId>(truth.objects), samples, seen, object,
                                  std::span<const std::uint32_t>(truth.weights), truth.stride);
}

}  // namespace paper
