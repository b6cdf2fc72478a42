// The setting the accuracy and stability tests' bounds were measured at: half a pixel footprint,
// refined hits (bisection to 1/32 threshold), central normals, Lipschitz-scaled steps on the
// SDFs (512) and sphere steps on the fractals (256): the shipped defaults before they were picked
// from the error budget, and the base of the calibration preset (march/primitives.hpp's preset_base). Those tests pin it, so they keep checking the marches themselves
// whatever the defaults become; the defaults have their own tests (examples/march_defaults_test,
// examples/march_budget_test).
//
//   paper::Frame c = test_knobs::pinned(paper::default_frame(w, h, 0.0f));
#pragma once

#include <02_paper_scene/frame.hpp>
#include <03_d3d12_scene/d3d12_types.hpp>
#include <proceduray/march/primitives.hpp>

namespace test_knobs {

/// The paper scene's constants with both fractals on the half-footprint setting.
inline paper::Frame pinned(paper::Frame c) {
  for (const auto& [id, name] : paper::marched_objects) c.knobs[id] = proceduray::preset_base(paper::capabilities(id));
  return c;
}

/// The D3D12 scene's constants with every marched primitive on the half-footprint setting.
inline d3d12::SceneConstants pinned(d3d12::SceneConstants c) {
  for (std::uint32_t k = d3d12::metaballs; k < d3d12::primitive_count; ++k) {
    const auto kind = static_cast<d3d12::PrimitiveKind>(k);
    d3d12::knobs(c, kind) = proceduray::preset_base(d3d12::capabilities(kind));
  }
  return c;
}

}  // namespace test_knobs
