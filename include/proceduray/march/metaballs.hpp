// Metaballs as data: up to max_metaballs sources, each with a centre, a radius and a motion,
// carried to the shaders in a uniform or a hit record (registered structs), and the box that
// holds them at every time, for the procedural geometry.
//
//   proceduray::Metaballs blob = proceduray::make_metaballs(
//       {proceduray::metaball({-0.3f, 0.0f, 0.0f}, 0.6f, {0.2f, 0.0f, 0.0f}, glm::vec3(1.1f)),   // centre, radius, amplitude, frequency
//        proceduray::metaball({0.3f, 0.1f, 0.0f}, 0.5f)},                                        // still
//       0.25f);                                                                                  // the threshold
//   scene.add_geometry("blob", proceduray::GeometryDesc::procedural({proceduray::metaballs_bounds(blob)}));
//   // GLSL: #include "primitives/metaball_motion.glsl"
//   //       MetaballList balls = metaballs_at(constants.blob, constants.time);
//   //       metaballs_march(o, u, s_lo, s_hi, balls, constants.blob.threshold, method, 64u, m, s, n, steps);
//
// Source i at time t sits at centre + amplitude * sin(frequency * t + phase), per axis. The
// field is zero beyond each radius, so the surface (threshold > 0) stays inside the union of
// the balls' spheres: metaballs_bounds is that union's box over every time (|sin| <= 1).
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/error.hpp>
#include <proceduray/aabb.hpp>
#include <proceduray/shader/field_list.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>

namespace proceduray {

/// Sources one Metaballs block holds: metaballs.glsl's metaball_max.
inline constexpr std::uint32_t max_metaballs = 8;

/// One source and its motion.
struct Metaball {
  glm::vec3 centre;
  float radius = 0.0f;          ///< influence radius: the field is 0 beyond it
  glm::vec3 amplitude{0.0f};    ///< per-axis swing of the centre
  float pad0 = 0.0f;
  glm::vec3 frequency{0.0f};    ///< radians per second, per axis
  float pad1 = 0.0f;
  glm::vec3 phase{0.0f};        ///< radians, per axis
  float pad2 = 0.0f;
};
PROCEDURAY_STRUCT(Metaball, scalar, centre, radius, amplitude, pad0, frequency, pad1, phase, pad2);

/// The sources and the threshold of the surface F = threshold.
struct Metaballs {
  Metaball ball[max_metaballs];
  std::uint32_t count = 0;
  float threshold = 0.0f;
  float pad0 = 0.0f, pad1 = 0.0f;
};
PROCEDURAY_STRUCT(Metaballs, scalar, ball, count, threshold, pad0, pad1);

/// A source at `centre` of radius `radius`, swinging by `amplitude` at `frequency` (radians per second).
PROCEDURAY_DECL Metaball metaball(glm::vec3 centre, float radius, glm::vec3 amplitude = glm::vec3(0.0f),
                                  glm::vec3 frequency = glm::vec3(0.0f), glm::vec3 phase = glm::vec3(0.0f));

/// Where source b is at `time` (metaball_motion.glsl's formula, on the host).
PROCEDURAY_DECL glm::vec3 metaball_centre_at(const Metaball& b, float time);

/// The block for the shaders; throws UsageError naming the source and the fix for no source,
/// more than max_metaballs, a radius <= 0, a non-finite number, or a threshold outside (0, 1)
/// (the falloff peaks at 1: a threshold of 1 or more has no surface away from a centre, 0 or
/// less fills all space).
PROCEDURAY_DECL Metaballs make_metaballs(std::span<const Metaball> balls, float threshold);
PROCEDURAY_DECL Metaballs make_metaballs(std::initializer_list<Metaball> balls, float threshold);

/// The box holding the surface at every time: each source's centre +- (|amplitude| + radius).
/// Throws UsageError for a block with no source.
PROCEDURAY_DECL Aabb metaballs_bounds(const Metaballs& blob);

}  // namespace proceduray

#include "proceduray/march/metaballs-inl.hpp"  // the bodies (config.hpp)
