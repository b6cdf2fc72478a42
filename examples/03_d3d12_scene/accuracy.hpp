// The D3D12 sample's scene measured against its ground truth, per object: which object a
// device hit belongs to (from the ids output) and one object's view of the metrics.
//
//   const d3d12::D3d12Scene scene(d3d12::accuracy_outputs);
//   // ... render with secondary rays off (constants.flags = 0), read back frame.outputs ...
//   std::vector<std::uint32_t> seen = d3d12::device_objects(renderer.plan(), frame.outputs.ids);
//   proceduray::accuracy::Metrics cog = d3d12::measure_object(truth, samples, seen, d3d12::object_id(d3d12::cog));
//
// Object ids are the reference's (sky_id, plane_id, object_id(kind)); a view is as in
// examples/common/object_metrics.hpp.
#pragma once

#include "d3d12_scene.hpp"
#include "reference.hpp"
#include "../common/object_metrics.hpp"

#include <proceduray/accuracy/metrics.hpp>

#include <span>
#include <string>
#include <vector>

namespace d3d12 {

/// What the accuracy tool and tests ask the scene for.
inline constexpr pr::OutputSet accuracy_outputs{pr::Output::t, pr::Output::normal, pr::Output::ids, pr::Output::steps,
                                               pr::Output::flags};

/// The object id of a device hit, from its TLAS instance (ids output): the instance's BLAS
/// names the geometry ("ground" or a primitive's name).
inline std::uint32_t object_of(const pr::Plan& plan, std::uint32_t instance) {
  if (instance >= plan.instances().size()) return sky_id;
  const pr::TlasInstance& in = plan.instances()[instance];
  for (const pr::PlannedGeometry& g : plan.geometries()) {
    if (g.blas != in.blas) continue;
    if (g.name == "ground") return plane_id;
    for (std::uint32_t k = 0; k < primitive_count; ++k) {
      if (g.name == primitive_names[k]) return object_id(static_cast<PrimitiveKind>(k));
    }
  }
  return sky_id;
}

/// Every pixel's object id from a frame's ids output (four uints per pixel).
inline std::vector<std::uint32_t> device_objects(const pr::Plan& plan, std::span<const std::uint32_t> ids) {
  std::vector<std::uint32_t> out(ids.size() / 4);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = object_of(plan, ids[4 * i]);
  return out;
}

/// The name of an object id: "plane", a primitive's name, or "sky".
inline std::string object_name(std::uint32_t id) {
  if (id == plane_id) return "plane";
  if (id >= 2u && id < object_id_count) return std::string(primitive_names[id - 2u]);
  return "sky";
}

/// The metrics of one object's view (see the top of this header).
inline pr::accuracy::Metrics measure_object(const ReferenceImage& truth, std::span<const pr::accuracy::Sample> samples,
                                            std::span<const std::uint32_t> seen, std::uint32_t object) {
  return examples::measure_object(truth.frame(), std::span<const pr::accuracy::Reference>(truth.pixels),
                                  std::span<const std::uint32_t>(truth.objects), samples, seen, object);
}

}  // namespace d3d12
