// Per-pixel outputs (AOVs): images a scene asks for besides colour, written by its shaders
// through generated helpers and read back with each frame, so a picture can be measured.
//
//   scene.set_outputs({proceduray::Output::t, proceduray::Output::normal, proceduray::Output::steps});
//   proceduray::Plan plan = proceduray::compile(scene);   // plan.outputs(): each output's binding in set 0
//   // GLSL, generated for every stage:   output_t(float)   output_normal(vec3)   output_ids(uvec3)
//   //                                    output_steps(uint) (adds)   output_flags(uint) (ors)
//   // and for closest-hit / any-hit:     output_hit(vec3 world_normal)  (t, normal and ids of this hit)
//   // #ifdef PROCEDURAY_OUTPUTS ... #endif guards code that only feeds outputs (e.g. a camera-ray test).
//   // vk::Renderer::render(w, h).outputs.t: w * h floats, -1 where nothing hit (vk/output_images.hpp)
//
// Each output is one storage image of the pixel grid (gl_LaunchIDEXT), cleared before every trace:
//   t       r32f     hit distance along the camera ray's direction (unit in the examples); -1: none
//   normal  rgba32f  world normal (xyz); 0 when none
//   ids     rgba32ui instance custom index, geometry index, primitive id; 0xffffffff when none
//   steps   r32ui    distance or field evaluations, summed over every call for the pixel
//   flags   r32ui    output_flag_* bits, or-ed over every call for the pixel
// t, normal and ids are the last value written: write them for the camera ray only (a closest-hit
// shader that also shades reflections tests its depth first). steps and flags are atomics that
// intersection shaders may call for any ray: they add up over the pixel's rays, which are the
// camera ray's when secondary rays are off (as the accuracy tool runs the scenes).
//
// A helper of an output the scene did not ask for is an empty macro: its arguments are not
// evaluated and the SPIR-V is the one the shader gives without the call, so a scene that asks
// for nothing pays nothing (same payloads, same SPIR-V; tested).
#pragma once

#include <array>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>

namespace proceduray {

/// One per-pixel output.
enum class Output : std::uint32_t { t, normal, ids, steps, flags };
inline constexpr std::uint32_t output_count = 5;

/// Bits of Output::flags, written by shaders with output_flags(); the same values in GLSL.
inline constexpr std::uint32_t output_flag_nan = 1u << 0;             ///< a NaN or Inf appeared on the way
inline constexpr std::uint32_t output_flag_exhausted = 1u << 1;       ///< a march ran out of steps
inline constexpr std::uint32_t output_flag_started_inside = 1u << 2;  ///< a march started inside its surface
/// a trace_<ray> call past the scene's declared recursion depth was refused (glsl_for.hpp)
inline constexpr std::uint32_t output_flag_depth = 1u << 3;

/// The GLSL name of an output ("t", "normal", ...).
inline constexpr std::string_view name(Output o) {
  constexpr std::array<std::string_view, output_count> names{"t", "normal", "ids", "steps", "flags"};
  return names[static_cast<std::uint32_t>(o)];
}

/// What an output's image holds.
struct OutputFormat {
  std::string_view glsl;       ///< the image format qualifier (r32f, rgba32f, rgba32ui, r32ui)
  std::uint32_t channels = 1;  ///< 32-bit channels per pixel
  bool unsigned_int = false;   ///< uimage2D of uints, else image2D of floats
};

inline constexpr OutputFormat format_of(Output o) {
  switch (o) {
    case Output::t: return {"r32f", 1, false};
    case Output::normal: return {"rgba32f", 4, false};
    case Output::ids: return {"rgba32ui", 4, true};
    case Output::steps:
    case Output::flags: return {"r32ui", 1, true};
  }
  return {};
}

/// A set of outputs (a bit per Output).
class OutputSet {
 public:
  constexpr OutputSet() = default;
  constexpr OutputSet(std::initializer_list<Output> outputs) {
    for (Output o : outputs) m_bits |= bit(o);
  }
  constexpr bool has(Output o) const { return (m_bits & bit(o)) != 0; }
  constexpr bool empty() const { return m_bits == 0; }
  constexpr std::uint32_t bits() const { return m_bits; }
  /// The outputs in Output order, for iteration.
  template <class F>
  constexpr void each(F f) const {
    for (std::uint32_t i = 0; i < output_count; ++i) {
      if (has(static_cast<Output>(i))) f(static_cast<Output>(i));
    }
  }
  friend constexpr bool operator==(OutputSet, OutputSet) = default;

 private:
  static constexpr std::uint32_t bit(Output o) { return 1u << static_cast<std::uint32_t>(o); }
  std::uint32_t m_bits = 0;
};

/// Where compile() put an output: its binding in descriptor set 0.
struct PlannedOutput {
  Output output = Output::t;
  std::uint32_t binding = 0;
  friend bool operator==(const PlannedOutput&, const PlannedOutput&) = default;
};

}  // namespace proceduray
