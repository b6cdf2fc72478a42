// The bodies of proceduray/march/primitives.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/march/primitives.hpp"

#if PROCEDURAY_BODIES
namespace proceduray {

PROCEDURAY_DECL const MarchCapabilities& sdf_capabilities() {
  static const MarchCapabilities caps = [] {
    MarchCapabilities c{"sdf",
                        {MarchMethod::relaxed, MarchMethod::lipschitz, MarchMethod::sphere, MarchMethod::fixed},
                        {MarchNormal::central, MarchNormal::tetrahedral},
                        0,
                        march_base_knobs};
    c.defaults.method = MarchMethod::relaxed;
    c.defaults.relaxation = 1.5f;
    c.defaults.threshold = 0.25f;
    return c;
  }();
  return caps;
}

PROCEDURAY_DECL const MarchCapabilities& metaball_capabilities() {
  static const MarchCapabilities caps = [] {
    MarchCapabilities c{"metaballs",
                        {MarchMethod::segment, MarchMethod::fixed, MarchMethod::lipschitz},
                        {MarchNormal::analytic},
                        0,
                        march_base_knobs};
    c.defaults.method = MarchMethod::segment;
    c.defaults.threshold = 2.0f;
    c.defaults.fixed_steps = 128;
    c.defaults.normal = MarchNormal::analytic;
    return c;
  }();
  return caps;
}

PROCEDURAY_DECL MarchCapabilities fractal_capabilities(std::uint32_t iterations) {
  MarchCapabilities c{"fractal",
                      {MarchMethod::sphere, MarchMethod::relaxed, MarchMethod::fixed},
                      {MarchNormal::central, MarchNormal::tetrahedral},
                      16,
                      march_base_knobs};
  c.defaults.method = MarchMethod::sphere;
  c.defaults.max_steps = 256;
  c.defaults.threshold = 0.25f;
  c.defaults.normal_scale = 0.25f;
  c.defaults.iterations = iterations;
  return c;
}

PROCEDURAY_DECL MarchKnobs preset_base(const MarchCapabilities& caps) {
  MarchKnobs k = caps.defaults;
  k.threshold_mode = MarchThreshold::footprint;
  k.threshold = 0.5f;
  k.refine = 1u;
  k.relaxation = 1.0f;
  k.max_steps = 512u;
  if (caps.kind == "sdf") {
    k.method = MarchMethod::lipschitz;
    k.normal = MarchNormal::central;
  } else if (caps.kind == "metaballs") {
    k.method = MarchMethod::segment;
  } else if (caps.kind == "fractal") {
    k.method = MarchMethod::sphere;
    k.normal = MarchNormal::central;
    k.max_steps = 256u;
  }
  return k;
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
