// The bodies of proceduray/march/knobs.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/march/knobs.hpp"

#if PROCEDURAY_BODIES
namespace proceduray::detail {

PROCEDURAY_DECL std::string number(float v) {
  char text[32];
  const auto r = std::to_chars(text, text + sizeof text, v);
  return std::string(text, r.ptr);
}

}  // namespace proceduray::detail

namespace proceduray {

PROCEDURAY_DECL void set_knob(MarchKnobs& k, std::string_view name, std::string_view value) {
  using detail::parse_number;
  if (name == "method") k.method = detail::parse_name<MarchMethod>(value, march_method_names, name);
  else if (name == "max_steps") k.max_steps = parse_number<std::uint32_t>(name, value);
  else if (name == "threshold_mode") k.threshold_mode = detail::parse_name<MarchThreshold>(value, march_threshold_names, name);
  else if (name == "threshold") k.threshold = parse_number<float>(name, value);
  else if (name == "epsilon") k.epsilon = parse_number<float>(name, value);
  else if (name == "step_scale") k.step_scale = parse_number<float>(name, value);
  else if (name == "relaxation") k.relaxation = parse_number<float>(name, value);
  else if (name == "fixed_steps") k.fixed_steps = parse_number<std::uint32_t>(name, value);
  else if (name == "refine") {
    if (value == "on" || value == "1") k.refine = 1;
    else if (value == "off" || value == "0") k.refine = 0;
    else if (value == "classic" || value == "2") k.refine = 2;
    else throw UsageError("march knobs: refine '" + std::string(value) + "' is not on/off/classic; valid: on, off, classic, 1, 0, 2");
  } else if (name == "normal") k.normal = detail::parse_name<MarchNormal>(value, march_normal_names, name);
  else if (name == "normal_scale") k.normal_scale = parse_number<float>(name, value);
  else if (name == "iterations") k.iterations = parse_number<std::uint32_t>(name, value);
  else if (name == "iteration_mode") k.iteration_mode = detail::parse_name<MarchIterations>(value, march_iterations_names, name);
  else if (name == "iteration_detail") k.iteration_detail = parse_number<float>(name, value);
  else if (name == "probe") k.probe = parse_number<float>(name, value);
  else throw UsageError("march knobs: unknown knob '" + std::string(name) + "'; valid: " + detail::joined(march_knob_names));
}

PROCEDURAY_DECL std::vector<std::pair<std::string, std::string>> knob_values(const MarchKnobs& k) {
  auto name_of = [](const auto& names, auto e) {
    const auto v = static_cast<std::uint32_t>(e);
    return v < names.size() ? std::string(names[v]) : "invalid(" + std::to_string(v) + ")";
  };
  return {{"method", name_of(march_method_names, k.method)},
          {"max_steps", std::to_string(k.max_steps)},
          {"threshold_mode", name_of(march_threshold_names, k.threshold_mode)},
          {"threshold", detail::number(k.threshold)},
          {"epsilon", detail::number(k.epsilon)},
          {"step_scale", detail::number(k.step_scale)},
          {"relaxation", detail::number(k.relaxation)},
          {"fixed_steps", std::to_string(k.fixed_steps)},
          {"refine", k.refine == 2 ? "classic" : (k.refine != 0 ? "on" : "off")},
          {"normal", name_of(march_normal_names, k.normal)},
          {"normal_scale", detail::number(k.normal_scale)},
          {"iterations", std::to_string(k.iterations)},
          {"iteration_mode", name_of(march_iterations_names, k.iteration_mode)},
          {"iteration_detail", detail::number(k.iteration_detail)},
          {"probe", detail::number(k.probe)}};
}

PROCEDURAY_DECL std::string describe(const MarchKnobs& k) {
  std::string out;
  for (const auto& [name, value] : knob_values(k)) out += (out.empty() ? "" : " ") + name + "=" + value;
  return out;
}

PROCEDURAY_DECL void proceduray_validate(const MarchKnobs& k, std::string_view where) {
  auto fail = [&](const std::string& what) { throw UsageError(std::string(where) + ": " + what); };
  auto finite = [](float v) { return std::isfinite(v); };
  auto code = [](auto e) { return static_cast<std::uint32_t>(e); };
  if (code(k.method) >= march_method_names.size()) {
    fail("method " + std::to_string(code(k.method)) + " is unknown; valid: " + detail::joined(march_method_names));
  }
  if (k.max_steps == 0 || k.max_steps > march_max_steps_limit) {
    fail("max_steps " + std::to_string(k.max_steps) + " is out of range; give 1 to " +
         std::to_string(march_max_steps_limit) + " (0 steps never hit; more would hold the device for minutes)");
  }
  if (code(k.threshold_mode) >= march_threshold_names.size()) {
    fail("threshold_mode " + std::to_string(code(k.threshold_mode)) + " is unknown; valid: " +
         detail::joined(march_threshold_names));
  }
  if (!(finite(k.threshold) && k.threshold > 0.0f)) {
    fail("threshold " + detail::number(k.threshold) + " must be a positive number (" +
         (k.threshold_mode == MarchThreshold::footprint ? "pixel footprints, e.g. 0.5" : "world units, e.g. 1e-3") + ")");
  }
  if (!(finite(k.epsilon) && k.epsilon >= 0.0f)) fail("epsilon " + detail::number(k.epsilon) + " must be >= 0 world units");
  if (!(finite(k.step_scale) && k.step_scale >= march_min_step_scale && k.step_scale <= 1.0f)) {
    fail("step_scale " + detail::number(k.step_scale) + " must be in [1/1024, 1]: larger steps than the bound allows "
         "skip surfaces, and a bound needing smaller ones is no bound to march (rescale the distance)");
  }
  if (!(finite(k.relaxation) && k.relaxation >= 1.0f && k.relaxation < 2.0f)) {
    fail("relaxation " + detail::number(k.relaxation) + " must be in [1, 2): at 2 and above relaxed steps "
         "never keep their spheres overlapping (Keinert et al. 2014)");
  }
  if (k.method == MarchMethod::fixed && (k.fixed_steps == 0 || k.fixed_steps >= k.max_steps)) {
    fail("fixed_steps " + std::to_string(k.fixed_steps) + " must be in [1, max_steps) = [1, " +
         std::to_string(k.max_steps) + "): the crossing's refinement needs steps left");
  }
  if (k.refine > 2) fail("refine " + std::to_string(k.refine) + " must be 0 (off), 1 (on) or 2 (classic)");
  if (code(k.normal) >= march_normal_names.size()) {
    fail("normal " + std::to_string(code(k.normal)) + " is unknown; valid: " + detail::joined(march_normal_names));
  }
  if (!(finite(k.normal_scale) && k.normal_scale > 0.0f && k.normal_scale <= 64.0f)) {
    fail("normal_scale " + detail::number(k.normal_scale) + " must be in (0, 64] thresholds");
  }
  if (k.iterations > march_max_iterations_limit) {
    fail("iterations " + std::to_string(k.iterations) + " is past " + std::to_string(march_max_iterations_limit) +
         ": an estimate's points inside never bail out, and each would run them all");
  }
  if (code(k.iteration_mode) >= march_iterations_names.size()) {
    fail("iteration_mode " + std::to_string(code(k.iteration_mode)) + " is unknown; valid: " +
         detail::joined(march_iterations_names));
  }
  if (!(finite(k.iteration_detail) && k.iteration_detail >= 0.0f)) {
    fail("iteration_detail " + detail::number(k.iteration_detail) + " must be a world size >= 0");
  }
  if (!(finite(k.probe) && k.probe >= 1.0f && k.probe <= march_max_probe)) {
    fail("probe " + detail::number(k.probe) + " must be in [1, 8] distances: under 1 a probe never reaches "
         "the surface the bound promises, past 8 it steps over parts the estimate saw (2 for an exact SDF)");
  }
}

PROCEDURAY_DECL void validate(const MarchKnobs& k, const MarchCapabilities& caps, std::string_view geometry) {
  const std::string where = "march knobs of '" + std::string(geometry) + "' (" + std::string(caps.kind) + ")";
  auto fail = [&](const std::string& what) { throw UsageError(where + ": " + what); };
  if (caps.methods.empty()) fail("this geometry is not marched (analytic): it takes no march knobs");
  proceduray_validate(k, where);
  bool method_ok = false;
  for (MarchMethod m : caps.methods) method_ok = method_ok || m == k.method;
  if (!method_ok) {
    fail("method " + std::string(march_method_names[static_cast<std::uint32_t>(k.method)]) +
         " does not apply; valid: " + detail::joined_of(caps.methods, march_method_names));
  }
  bool normal_ok = false;
  for (MarchNormal n : caps.normals) normal_ok = normal_ok || n == k.normal;
  if (!normal_ok) {
    fail("normal " + std::string(march_normal_names[static_cast<std::uint32_t>(k.normal)]) +
         " does not apply; valid: " + detail::joined_of(caps.normals, march_normal_names));
  }
  if (caps.max_iterations == 0) {
    if (k.iteration_mode != MarchIterations::fixed) {
      fail("iteration_mode by_distance needs a fractal; this geometry has no iterations");
    }
  } else {
    if (k.iterations == 0 || k.iterations > caps.max_iterations) {
      fail("iterations " + std::to_string(k.iterations) + " must be in [1, " + std::to_string(caps.max_iterations) + "]");
    }
    if (k.iteration_mode == MarchIterations::by_distance && !(k.iteration_detail > 0.0f)) {
      fail("iteration_detail " + detail::number(k.iteration_detail) + " must be a positive world size");
    }
  }
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
