// The bodies of proceduray/march/metaballs.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/march/metaballs.hpp"

#if PROCEDURAY_BODIES
namespace proceduray {

PROCEDURAY_DECL Metaball metaball(glm::vec3 centre, float radius, glm::vec3 amplitude,
                                  glm::vec3 frequency, glm::vec3 phase) {
  return {centre, radius, amplitude, 0.0f, frequency, 0.0f, phase, 0.0f};
}

PROCEDURAY_DECL glm::vec3 metaball_centre_at(const Metaball& b, float time) {
  return b.centre + b.amplitude * glm::sin(b.frequency * time + b.phase);
}

PROCEDURAY_DECL Metaballs make_metaballs(std::span<const Metaball> balls, float threshold) {
  if (balls.empty()) {
    throw UsageError("make_metaballs: 0 metaballs; give at least one source (proceduray::metaball(centre, radius))");
  }
  if (balls.size() > max_metaballs) {
    throw UsageError("make_metaballs: " + std::to_string(balls.size()) + " metaballs, over the limit of " +
                     std::to_string(max_metaballs) + " (proceduray::max_metaballs, the shaders' array); split the "
                     "blob into several objects");
  }
  if (!(threshold > 0.0f && threshold < 1.0f)) {
    throw UsageError("make_metaballs: threshold " + std::to_string(threshold) + " is outside (0, 1): the field "
                     "peaks at 1 at a centre, so there would be no surface; use e.g. 0.25");
  }
  const auto finite = [](glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
  Metaballs out;
  out.count = static_cast<std::uint32_t>(balls.size());
  out.threshold = threshold;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const Metaball& b = balls[i];
    const std::string which = "make_metaballs: metaball " + std::to_string(i);
    if (!finite(b.centre) || !finite(b.amplitude) || !finite(b.frequency) || !finite(b.phase) || !std::isfinite(b.radius)) {
      throw UsageError(which + " has a non-finite centre, radius or motion (NaN or infinity); check the values "
                       "it is computed from");
    }
    if (!(b.radius > 0.0f)) {
      throw UsageError(which + " has radius " + std::to_string(b.radius) + "; a source needs a positive radius");
    }
    out.ball[i] = b;
  }
  return out;
}

PROCEDURAY_DECL Metaballs make_metaballs(std::initializer_list<Metaball> balls, float threshold) {
  return make_metaballs(std::span<const Metaball>(balls.begin(), balls.size()), threshold);
}

PROCEDURAY_DECL Aabb metaballs_bounds(const Metaballs& blob) {
  if (blob.count == 0 || blob.count > max_metaballs) {
    throw UsageError("metaballs_bounds: the block has " + std::to_string(blob.count) + " sources; build it with "
                     "make_metaballs (1 to " + std::to_string(max_metaballs) + " sources)");
  }
  Aabb box{glm::vec3(INFINITY), glm::vec3(-INFINITY)};
  for (std::uint32_t i = 0; i < blob.count; ++i) {
    const Metaball& b = blob.ball[i];
    const glm::vec3 reach = glm::abs(b.amplitude) + glm::vec3(b.radius);
    box.min = glm::min(box.min, b.centre - reach);
    box.max = glm::max(box.max, b.centre + reach);
  }
  return box;
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
