// The bodies of proceduray/vk/calibrate.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/calibrate.hpp"

#include <cmath>

#include "proceduray/vk/spirv_cache.hpp"

#if PROCEDURAY_BODIES
namespace proceduray::vk {

PROCEDURAY_DECL std::vector<MarchKnobs> field_preset(const MarchCapabilities& caps) {
  std::vector<MarchKnobs> out;
  const float thresholds[] = {0.25f, 0.5f, 1.0f, 2.0f, 4.0f};
  std::vector<std::uint32_t> iterations{caps.defaults.iterations};
  if (caps.max_iterations > 0) {
    for (std::uint32_t n = caps.defaults.iterations; n + 2 >= caps.defaults.iterations && n >= 1; --n) {
      if (n != caps.defaults.iterations) iterations.push_back(n);
    }
  }
  for (MarchMethod method : caps.methods) {
    for (std::uint32_t n : iterations) {
      MarchKnobs k = caps.defaults;
      k.method = method;
      k.iterations = n;
      if (method == MarchMethod::fixed) {
        for (std::uint32_t steps : {32u, 128u}) {
          k.fixed_steps = steps;
          k.threshold = 0.5f;
          out.push_back(k);
        }
        continue;
      }
      if (method == MarchMethod::segment) continue;  // needs a bound per segment: metaballs only
      k.relaxation = method == MarchMethod::relaxed ? 1.5f : 1.0f;
      for (float t : thresholds) {
        k.threshold = t;
        out.push_back(k);
      }
    }
  }
  // The classic rule at half a footprint (a hit below the threshold, no crossing): on the chart
  // it shows what the sign change buys; a budget that bounds silhouette false hits never picks it.
  MarchKnobs classic = caps.defaults;
  classic.method = caps.methods.front();
  classic.relaxation = classic.method == MarchMethod::relaxed ? 1.5f : 1.0f;
  classic.threshold = 0.5f;
  classic.refine = 2;
  out.push_back(classic);
  return out;
}

namespace detail {

PROCEDURAY_DECL std::string view_size(const MeasureView& view) {
  return std::to_string(view.width) + "x" + std::to_string(view.height);
}

PROCEDURAY_DECL std::filesystem::path calibration_file(const FieldMeter& meter, const CalibrateOptions& o,
                                                       const std::vector<MarchKnobs>& settings) {
  // GLSL, declaration, parameter values, view, sample, version; the table's format (a unit changed in format 3).
  std::uint64_t h = truth_key(meter.field(), meter.glsl_text(), o.view, meter.options(), meter.parameter_values());
  h = fnv1a(calibration_format, h);
  h = fnv1a(meter.device(), h);
  for (const MarchKnobs& k : settings) h = fnv1a(describe(k), h);
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return o.cache_dir / "calibration" / (meter.field().id + "-" + hex + ".csv");
}

PROCEDURAY_DECL bool calibration_row(const FieldMeter& meter, const MarchKnobs& k, const Measurement& m,
                                     CalibrationRow& row) {
  const accuracy::ClassStats& a = m.metrics.all;
  if (a.both_hit == 0 || !std::isfinite(a.depth.median)) return false;
  auto rate = [](double v) { return std::isfinite(v) ? v : 0.0; };  // a rate of no rays is no error
  // The rates' upper 95% bounds: equal to the rates with every pixel's truth, and a budget met by
  // the bound is met on a stratified truth too.
  row = {meter.field().id, std::string(meter.capabilities().kind), k, m.evaluations_per_box_ray, a.depth.median,
         a.depth.p99, rate(m.metrics[accuracy::PixelClass::silhouette_1px].false_hit_rate()),
         m.confidence.false_miss_rate_95, rate(a.normal_degrees.p95), m.confidence.wrong_surface_rate_95};
  return true;
}

}  // namespace detail
}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
