// What the library's marched primitives (shaders/primitives) accept as knobs, and their
// defaults: signed distance functions (sdf.glsl), metaballs (metaballs.glsl) and the escape-time
// fractals (mandelbulb.glsl, julia.glsl).
//
//   proceduray::MarchKnobs k = proceduray::sdf_capabilities().defaults;
//   proceduray::validate(k, proceduray::sdf_capabilities(), "cog");
//   const proceduray::MarchCapabilities bulb = proceduray::fractal_capabilities(8);   // 8 iterations by default
//
// Why these methods per kind: an SDF has a Lipschitz bound (sdf_lipschitz), so every method
// applies, sphere tracing without the bound included (it overshoots where the bound exceeds 1,
// a failure mode the sweep charts). A metaball field is no distance: only marches that bound it
// (the global or per-segment Lipschitz bound) or ignore it (fixed steps), and its gradient is
// analytic. A fractal's estimate has no usable Lipschitz bound beyond 1 (lipschitz would be
// sphere again), and its normal is a difference at a scale.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/march/knobs.hpp>

#include <cstdint>

namespace proceduray {

/// SDFs: Lipschitz-scaled sphere tracing by default (the D3D12 sample's 512 steps), half a
/// footprint, central normals at the threshold.
PROCEDURAY_DECL const MarchCapabilities& sdf_capabilities();

/// Metaballs: segment tracing by default (on the measured front: at half a footprint 22.5
/// evaluations per ray where the sample's fixed 128 steps take 59, with a third of their depth
/// error; docs/accuracy.md, "Defaults from the front"), analytic normals. Fixed steps keep 128.
PROCEDURAY_DECL const MarchCapabilities& metaball_capabilities();

/// Escape-time fractals with `iterations` by default (at most 16): sphere tracing of the
/// estimate, 256 steps, half a footprint, central normals at a quarter of the threshold (near
/// the reference's own 0.1-footprint scale: 12 degrees median error where 1 threshold gave 34).
PROCEDURAY_DECL MarchCapabilities fractal_capabilities(std::uint32_t iterations);

}  // namespace proceduray

#include "proceduray/march/primitives-inl.hpp"  // the bodies (config.hpp)
