// How a marched geometry is intersected, chosen at run time per geometry: the method, its
// knobs, and what each geometry accepts. The struct crosses to the GLSL (a storage buffer of
// them, one per geometry), where shaders/marching/knobs.glsl turns one into MarchSettings.
//
//   const proceduray::MarchCapabilities caps{"sdf", {proceduray::MarchMethod::lipschitz, proceduray::MarchMethod::relaxed},
//                                            {proceduray::MarchNormal::central}, 0, proceduray::march_base_knobs};
//   proceduray::MarchKnobs k = caps.defaults;              // march/primitives.hpp has the shipped geometries'
//   proceduray::set_knob(k, "method", "relaxed");          // names as the sweep tool takes them
//   proceduray::set_knob(k, "relaxation", "1.6");
//   proceduray::validate(k, caps, "cog");                  // throws UsageError on bad input
//   std::string line = proceduray::describe(k);            // "method=relaxed max_steps=512 ..."
//   // GLSL: MarchSettings m = march_settings(knobs.data[id], world_per_object, pixel_angle, lipschitz);
//
// Why one struct for every method: a sweep, a calibration table and an error budget all speak
// of "the knobs of a geometry"; a knob a method does not read is ignored by the shader but
// still validated, so a table row always describes one valid setting. Enums are uint32 in the
// struct (GLSL has no enums); their values equal the march_* consts of knobs.glsl (a test
// compiles that file as C++ and compares).
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/error.hpp>
#include <proceduray/shader/field_list.hpp>

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace proceduray {

/// How the ray finds the surface.
enum class MarchMethod : std::uint32_t {
  sphere,     ///< steps of the distance (Hart 1996); assumes a 1-Lipschitz distance
  relaxed,    ///< over-relaxed steps w * distance / L with Keinert et al.'s (2014) fallback
  lipschitz,  ///< steps of distance / L, L the geometry's Lipschitz bound
  segment,    ///< segment tracing (Galin et al. 2020): a Lipschitz bound per segment (metaballs)
  fixed,      ///< equal steps across the box, then the crossing (the D3D12 sample's metaballs)
};
/// How the hit threshold is given.
enum class MarchThreshold : std::uint32_t {
  footprint,  ///< `threshold` pixel footprints at the hit's distance, at least `epsilon` world units
  absolute,   ///< `threshold` world units everywhere
};
/// How the normal at a hit is found.
enum class MarchNormal : std::uint32_t {
  analytic,     ///< the geometry's own gradient (where it has one)
  central,      ///< central differences: 6 evaluations, error O(h^2)
  tetrahedral,  ///< four samples on a tetrahedron: 4 evaluations, error O(h)
};
/// How many iterations a fractal's estimate runs.
enum class MarchIterations : std::uint32_t {
  fixed,        ///< always `iterations`
  by_distance,  ///< `iterations` while a pixel footprint is below `iteration_detail`, one fewer per doubling beyond
};

inline constexpr std::array<std::string_view, 5> march_method_names{"sphere", "relaxed", "lipschitz", "segment", "fixed"};
inline constexpr std::array<std::string_view, 2> march_threshold_names{"footprint", "absolute"};
inline constexpr std::array<std::string_view, 3> march_normal_names{"analytic", "central", "tetrahedral"};
inline constexpr std::array<std::string_view, 2> march_iterations_names{"fixed", "by_distance"};

/// The most distance evaluations a march may take, and the most iterations a fractal's estimate
/// may run: past them one frame would hold the device for minutes (a hang, then a device lost).
inline constexpr std::uint32_t march_max_steps_limit = 65536;
inline constexpr std::uint32_t march_max_iterations_limit = 64;
/// The smallest step_scale: a bound that needs steps under 1/1024 of the distance is no bound a
/// march can use (each ray would take thousands of steps); rescale the distance instead.
inline constexpr float march_min_step_scale = 1.0f / 1024.0f;
/// The longest probe below the threshold, in distances: an estimate that underestimates more than
/// 4-fold near its surface is one to rescale, not to probe past.
inline constexpr float march_max_probe = 8.0f;

/// One geometry's knobs (GLSL: MarchKnobs, scalar layout; the enums are uints there, whose
/// march_* consts in marching/knobs.glsl name the same values). Checked wherever it goes to a
/// shader (proceduray_validate below, shader/value_check.hpp).
struct MarchKnobs {
  MarchMethod method;            ///< how the ray finds the surface
  std::uint32_t max_steps;       ///< evaluations at most, refinement included; then a miss
  MarchThreshold threshold_mode; ///< how `threshold` is given
  float threshold;               ///< pixel footprints (footprint mode) or world units (absolute)
  float epsilon;                 ///< footprint mode: the threshold's floor in world units
  float step_scale;              ///< factor on every step, (0, 1]: a fudge for estimates that overshoot
  float relaxation;              ///< relaxed: w in [1, 2)
  std::uint32_t fixed_steps;     ///< fixed: equal steps across the box, < max_steps
  std::uint32_t refine;          ///< 1: bisect the crossing to 1/32 threshold; 0: report the last outside point;
                                 ///< 2 (classic): stop at the first point below the threshold, no crossing
                                 ///< needed (Hart's rule: cheap, but it fattens silhouettes by the threshold)
  MarchNormal normal;            ///< how the normal at a hit is found
  float normal_scale;            ///< differences' offset h as a fraction of the threshold at the hit
  std::uint32_t iterations;      ///< fractals: iterations (the most, by distance)
  MarchIterations iteration_mode;  ///< fixed or by distance
  float iteration_detail;        ///< by_distance: world size of a footprint up to which all iterations run
  float probe;                   ///< below the threshold, probes of `probe` distances (in [1, 8]; 2: an
                                 ///< exact SDF's; an estimate that underestimates k-fold takes up to 2k)
};
/// Throws UsageError, naming `where`, the knob, its value and the valid range, for knobs no
/// geometry can take: an unknown enum value, steps or iterations past the limits above, a
/// non-finite or non-positive threshold, a step_scale outside [march_min_step_scale, 1], ...
/// What one geometry accepts is validate(k, caps, geometry)'s business.
PROCEDURAY_DECL void proceduray_validate(const MarchKnobs& k, std::string_view where);
PROCEDURAY_STRUCT(MarchKnobs, scalar, method, max_steps, threshold_mode, threshold, epsilon, step_scale, relaxation,
                  fixed_steps, refine, normal, normal_scale, iterations, iteration_mode, iteration_detail, probe);

/// What a geometry accepts, and its defaults.
struct MarchCapabilities {
  std::string_view kind;                 ///< "sdf", "fractal", "metaballs": for messages
  std::vector<MarchMethod> methods;      ///< accepted methods, the default first
  std::vector<MarchNormal> normals;      ///< accepted normal methods, the default first
  std::uint32_t max_iterations = 0;      ///< > 0: a fractal whose iterations are knobs, up to this
  MarchKnobs defaults{};                 ///< the default knobs (from the measured front)
};

/// Defaults for a distance bound: Lipschitz-scaled sphere tracing, 512 steps, half a footprint
/// (at least 1e-4), refined hits, central normals at the threshold.
inline constexpr MarchKnobs march_base_knobs{MarchMethod::lipschitz, 512u, MarchThreshold::footprint, 0.5f, 1.0e-4f,
                                             1.0f, 1.0f, 64u, 1u, MarchNormal::central, 1.0f, 0u,
                                             MarchIterations::fixed, 0.01f, 2.0f};

namespace detail {

template <std::size_t N>
std::string joined(const std::array<std::string_view, N>& names) {
  std::string out;
  for (std::string_view n : names) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

template <class Enum, std::size_t N>
std::string joined_of(const std::vector<Enum>& values, const std::array<std::string_view, N>& names) {
  std::string out;
  for (Enum v : values) out += (out.empty() ? "" : ", ") + std::string(names[static_cast<std::uint32_t>(v)]);
  return out;
}

PROCEDURAY_DECL std::string number(float v);

template <class Enum, std::size_t N>
Enum parse_name(std::string_view value, const std::array<std::string_view, N>& names, std::string_view knob) {
  for (std::size_t i = 0; i < N; ++i) {
    if (names[i] == value) return static_cast<Enum>(i);
  }
  throw UsageError("march knobs: unknown " + std::string(knob) + " '" + std::string(value) + "'; valid: " +
                   joined(names));
}

template <class T>
T parse_number(std::string_view knob, std::string_view value) {
  T out{};
  const char* end = value.data() + value.size();
  const auto r = std::from_chars(value.data(), end, out);
  if (r.ec != std::errc{} || r.ptr != end) {
    throw UsageError("march knobs: " + std::string(knob) + " '" + std::string(value) + "' is not a" +
                     (std::is_floating_point_v<T> ? " number" : " whole number") + "; give e.g. " +
                     (std::is_floating_point_v<T> ? "0.5" : "256"));
  }
  return out;
}

}  // namespace detail

/// The knob names set_knob takes, in the struct's order.
inline constexpr std::array<std::string_view, 15> march_knob_names{
    "method", "max_steps", "threshold_mode", "threshold", "epsilon", "step_scale", "relaxation",
    "fixed_steps", "refine", "normal", "normal_scale", "iterations", "iteration_mode", "iteration_detail", "probe"};

/// Sets one knob from text (enum names, numbers; refine takes on/off too). Throws UsageError for
/// an unknown knob or value, listing the valid ones; ranges are validate()'s business.
PROCEDURAY_DECL void set_knob(MarchKnobs& k, std::string_view name, std::string_view value);

/// Each knob as (name, text): the columns of a sweep's CSV and a calibration table.
PROCEDURAY_DECL std::vector<std::pair<std::string, std::string>> knob_values(const MarchKnobs& k);

/// "name=value ..." of every knob.
PROCEDURAY_DECL std::string describe(const MarchKnobs& k);

/// Throws UsageError unless `k` is a setting `caps` accepts: names the geometry, the knob, its
/// value, and the valid range or names.
PROCEDURAY_DECL void validate(const MarchKnobs& k, const MarchCapabilities& caps, std::string_view geometry);

}  // namespace proceduray

#include "proceduray/march/knobs-inl.hpp"  // the bodies (config.hpp)
