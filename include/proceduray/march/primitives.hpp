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

// The defaults per kind come from a stated budget: each is the setting that meets ErrorBudget{}
// (a picture that cannot be told from exact) on every shipped primitive of the kind, in both
// shipped calibration tables (shaders/calibration/: H200 at 1920x1080, and lavapipe at 640x360,
// where a threshold in footprints is 3 times wider in the world), at the least total evaluations
// per ray at 1080p. A scene's own primitive may do better with its own pick (the example scenes
// do); tests/examples/march_defaults_test.cpp checks both.

/// SDFs: over-relaxed steps (w 1.5, Lipschitz-scaled) to a quarter footprint, 512 steps, central
/// normals at the threshold: 190 evaluations for the seven D3D12 SDFs, as many as 0.2.0's
/// Lipschitz steps at half a footprint, which missed 0.17% of the fractal pyramid's pixels at
/// 640x360 where this setting meets every bound.
PROCEDURAY_DECL const MarchCapabilities& sdf_capabilities();

/// Metaballs: segment tracing to 2 footprints (22.6 evaluations per ray where the sample's fixed
/// 128 steps take 59), analytic normals. Fixed steps keep 128.
PROCEDURAY_DECL const MarchCapabilities& metaball_capabilities();

/// Escape-time fractals with `iterations` by default (at most 16): sphere tracing of the
/// estimate, 256 steps, a quarter footprint, central normals at a quarter of the threshold. Half
/// a footprint (0.2.0's default) put 0.73% of the Mandelbulb's pixels at 1080p on a surface
/// behind the true one (a step over a thin part); a quarter, 0.48% (52.4 evaluations against 47.9).
PROCEDURAY_DECL MarchCapabilities fractal_capabilities(std::uint32_t iterations);

/// The setting a calibration preset varies from, whatever the defaults are (so a table does not
/// depend on the defaults picked from it): half a footprint, refined hits, the kind's bounded
/// method (Lipschitz steps on SDFs, segment tracing on metaballs, 256 sphere steps on fractals),
/// central normals (analytic on metaballs), no relaxation; iterations kept. These were 0.2.0's
/// defaults, and the setting the accuracy tests' bounds are measured at.
PROCEDURAY_DECL MarchKnobs preset_base(const MarchCapabilities& caps);

}  // namespace proceduray

#include "proceduray/march/primitives-inl.hpp"  // the bodies (config.hpp)
