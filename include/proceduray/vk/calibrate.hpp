// Calibrating one distance field on the user's machine: measure a preset of its methods and
// knobs (or the settings given) at the size the user renders at, and keep the table, keyed by
// the GLSL's text, the declaration, the library version, the device and the view, so the next
// run reads it instead of measuring again.
//
//   proceduray::vk::FieldMeter meter(ctx, gyroid, {.shader_dirs = {"shaders"}});
//   const proceduray::vk::Calibrated c = proceduray::vk::calibrate(meter, cpu, {.view = view, .cache_dir = ".cache",
//       .progress = [](const std::string& line) { std::puts(line.c_str()); }});
//   const proceduray::CalibrationRow& pick = c.table.cheapest("gyroid", {});   // the default budget
//   scene.set_error_budget({}, c.table, 1920, 1080);   // or let compile() pick for every field
//
// The preset (field_preset): each method the field accepts (plain sphere steps only where
// L <= 1: field_capabilities) at thresholds from a quarter to four footprints, relaxed steps at
// w = 1.5, fixed steps of 32 and 128; a fractal's iteration counts from its default down by
// two; and the classic hit rule at half a footprint (refine = classic), which shows what the
// sign change buys and which a budget on silhouette false hits never picks. Rows are calibration rows (march/calibration.hpp) with every error measured, the
// wrong-surface rate included; cost is evaluations per ray that entered the field's box.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/march/calibration.hpp>
#include <proceduray/vk/measure.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace proceduray::vk {

/// What to calibrate at, and where to keep the table.
struct CalibrateOptions {
  MeasureView view;                    ///< the view and size the field is rendered at
  std::vector<MarchKnobs> settings;    ///< empty: field_preset(the field's capabilities)
  std::filesystem::path cache_dir;     ///< empty: measured every time, kept nowhere
  std::function<void(const std::string&)> progress;  ///< a line per setting measured (none: quiet)
};

/// A calibration and where it came from.
struct Calibrated {
  Calibration table;            ///< one row per setting with hits
  bool cached = false;          ///< read from the cache folder, nothing measured
  std::filesystem::path file;   ///< the cache file (empty without a cache folder)
};

/// The source a meter's calibration records (scene/field.hpp's field_source).
inline std::string field_source(const FieldMeter& meter) { return field_source(meter.field(), meter.glsl_text()); }

/// The settings calibrate() measures by default for a field that accepts `caps`.
PROCEDURAY_DECL std::vector<MarchKnobs> field_preset(const MarchCapabilities& caps);

namespace detail {
/// The cache file of a calibration: the folder, the field's id and a key of everything it depends on.
PROCEDURAY_DECL std::filesystem::path calibration_file(const FieldMeter& meter, const CalibrateOptions& o,
                                                       const std::vector<MarchKnobs>& settings);
/// The row of one measurement, or false when the setting hit nothing (no depth error to record).
PROCEDURAY_DECL bool calibration_row(const FieldMeter& meter, const MarchKnobs& k, const Measurement& m,
                                     CalibrationRow& row);
/// The size text of a view, "WxH", as calibration tables record it.
PROCEDURAY_DECL std::string view_size(const MeasureView& view);
}  // namespace detail

/// Measures every setting (checked against the field's capabilities first: a bad one throws
/// UsageError before anything renders) and returns the table; with a cache folder, reuses a
/// table measured for the same GLSL, declaration, version, device, view and settings.
template <class Distance>
Calibrated calibrate(FieldMeter& meter, const Distance& distance, const CalibrateOptions& o) {
  detail::check_view(o.view, "calibrate");
  const std::vector<MarchKnobs> settings = o.settings.empty() ? field_preset(meter.capabilities()) : o.settings;
  for (const MarchKnobs& k : settings) validate(k, meter.capabilities(), "calibrate: field \"" + meter.field().id + "\"");
  Calibrated out;
  if (!o.cache_dir.empty()) {
    out.file = detail::calibration_file(meter, o, settings);
    std::error_code ec;
    if (std::filesystem::exists(out.file, ec)) {
      try {
        out.table = Calibration::load(out.file);
        out.cached = out.table.device() == meter.device() && out.table.size() == detail::view_size(o.view);
      } catch (const Error&) {
        out.cached = false;  // another version, damaged: measured again and replaced
      }
      if (out.cached) return out;
    }
  }
  std::vector<CalibrationRow> rows;
  for (std::size_t i = 0; i < settings.size(); ++i) {
    const Measurement m = meter.measure(distance, settings[i], o.view);
    CalibrationRow row;
    if (detail::calibration_row(meter, settings[i], m, row)) rows.push_back(row);
    if (o.progress) {
      char line[160];
      std::snprintf(line, sizeof line, "calibrate %s: %zu/%zu  %.1f evals  depth median %.3g  p99 %.3g  misses %.3g%%",
                    meter.field().id.c_str(), i + 1, settings.size(), m.evaluations_per_box_ray,
                    m.metrics.all.depth.median, m.metrics.all.depth.p99, 100.0 * m.confidence.false_miss_rate);
      o.progress(std::string(line) + "  " + describe(settings[i]));
    }
  }
  out.table = Calibration(meter.device(), detail::view_size(o.view), std::move(rows), field_source(meter));
  if (!out.file.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(out.file.parent_path(), ec);
    std::ofstream file(out.file, std::ios::trunc);
    out.table.write(file);  // best effort: a cache that cannot be written is measured again
  }
  return out;
}

}  // namespace proceduray::vk

#include "proceduray/vk/calibrate-inl.hpp"  // the bodies (config.hpp)
