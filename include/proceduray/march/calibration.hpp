// An error budget, met at the least cost: the measured error and cost of march settings per
// geometry (a calibration table, written by tools/sweep and shipped in
// shaders/calibration/), and the cheapest setting whose error fits what the user allows.
//
//   const proceduray::Calibration table = proceduray::Calibration::load(proceduray::shipped_calibration());
//   const proceduray::ErrorBudget budget{.depth_median = 0.01, .depth_p99 = 0.05, .silhouette_false_hits = 0.01};
//   const proceduray::CalibrationRow& pick = table.cheapest("cog", budget);   // throws: none meets it
//   constants.knobs[cog_id] = pick.knobs;                                      // 12.3 evaluations per ray, say
//
// "Model no more than a scene needs": a scene that tolerates a tenth of a pixel of depth error
// should not pay for a thousandth. Errors are the accuracy metrics of accuracy/metrics.hpp,
// measured against a ground truth in double: depth in pixel footprints (median and p99 of the
// rays where both hit), silhouette false hits (fraction of the 1-pixel silhouette band's rays
// that hit where the truth misses), false misses (fraction of the truth's hits the render
// missed) and the 95th percentile of the normal's error in degrees (the median hides what
// tetrahedral differences cost on the Julia set: 0.95 against 37 degrees). Cost is evaluations
// per ray that sees the geometry, which does not depend on the machine; the table records the
// device, size and library version that measured it.
//
// File: CSV. Line 1 "# proceduray-calibration 4", line 2 "# library <version>", line 3
// "# measured <device> <W>x<H>", then a header and a row per (geometry, setting). A table from
// another library version is refused (its marches may differ), as is a foreign or damaged file.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/error.hpp>
#include <proceduray/march/knobs.hpp>
#include <proceduray/version.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <istream>
#include <limits>
#include <ostream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace proceduray {

/// What a scene may get wrong. Every bound is inclusive. The defaults are a budget a 1920x1080
/// picture cannot tell from exact (half a percent of an object's pixels wrong at most, depth
/// within a tenth of a footprint at the median): a budget that allows more names what it
/// relaxes, e.g. {.depth_median = 0.5} or ErrorBudget::relaxed() for "anything".
struct ErrorBudget {
  double depth_median = 0.1;              ///< pixel footprints, median of the rays both hit
  double depth_p99 = 2.0;                 ///< pixel footprints, 99th percentile
  double silhouette_false_hits = 0.005;   ///< fraction of the 1-pixel band's rays
  double false_misses = 0.005;            ///< fraction of the truth's hits
  double wrong_surface = 0.005;           ///< fraction of the truth's hits landing > 2 footprints behind it
  double normal_p95 = 180.0;              ///< normal error, 95th percentile, degrees (not bounded by default)
  /// Every bound open: the cheapest setting, whatever it gets wrong.
  static ErrorBudget relaxed() {
    constexpr double inf = std::numeric_limits<double>::infinity();
    return {inf, inf, 1.0, 1.0, 1.0, 180.0};
  }
};

/// Throws UsageError, naming `op`, the bound and its value, for a budget bound that is NaN or
/// negative, a fraction over 1 or a normal bound over 180 degrees: such a budget is invalid, not
/// unmeetable. Depth bounds may be infinite (open).
inline void validate(const ErrorBudget& b, std::string_view op) {
  const struct {
    const char* name;
    double value;
    double most;
  } bounds[] = {{"depth_median", b.depth_median, std::numeric_limits<double>::infinity()},
                {"depth_p99", b.depth_p99, std::numeric_limits<double>::infinity()},
                {"silhouette_false_hits", b.silhouette_false_hits, 1.0},
                {"false_misses", b.false_misses, 1.0},
                {"wrong_surface", b.wrong_surface, 1.0},
                {"normal_p95", b.normal_p95, 180.0}};
  for (const auto& bound : bounds) {
    if (bound.value >= 0.0 && bound.value <= bound.most) continue;
    std::ostringstream m;
    m << op << ": the error budget's " << bound.name << " is " << bound.value << "; a bound is a number from 0 to "
      << (bound.most == 1.0 ? "1 (a fraction)" : bound.most == 180.0 ? "180 (degrees)" : "infinity (footprints)")
      << ": give one in range, or ErrorBudget::relaxed() for no bound";
    throw UsageError(m.str());
  }
}

/// One measured setting of one geometry.
struct CalibrationRow {
  std::string geometry;  ///< the object's name in its scene ("cog", "mandelbulb")
  std::string kind;      ///< its MarchCapabilities::kind
  MarchKnobs knobs{};
  double evals = 0.0;                  ///< evaluations per ray that sees the geometry
  double depth_median = 0.0;           ///< pixel footprints
  double depth_p99 = 0.0;              ///< pixel footprints
  double silhouette_false_hits = 0.0;  ///< fraction
  /// Fraction of the truth's hits the render missed (ClassStats::missed_hits_rate); NaN: not
  /// measured so (a table of format 1 or 2 counted them per ray of the frame), which meets no bound below 1.
  double false_misses = 0.0;
  double normal_p95 = 0.0;             ///< normal error against the truth's, 95th percentile, degrees
  /// Fraction of the truth's hits landing more than 2 footprints behind it; NaN: not measured
  /// (a format-1 table), which meets no bound below 1.
  double wrong_surface = std::numeric_limits<double>::quiet_NaN();

  /// How far over `b` this row is: the largest ratio measured / allowed (<= 1 meets it; an
  /// unmeasured error is infinitely over any bound but an open one).
  double excess(const ErrorBudget& b) const {
    auto ratio = [](double measured, double allowed) {
      if (measured <= allowed) return 0.0;
      return allowed > 0.0 && !std::isnan(measured) ? measured / allowed : std::numeric_limits<double>::infinity();
    };
    return std::max({ratio(depth_median, b.depth_median), ratio(depth_p99, b.depth_p99),
                     ratio(silhouette_false_hits, b.silhouette_false_hits),
                     b.false_misses >= 1.0 ? 0.0 : ratio(false_misses, b.false_misses),
                     ratio(normal_p95, b.normal_p95), b.wrong_surface >= 1.0 ? 0.0 : ratio(wrong_surface, b.wrong_surface)});
  }
  bool meets(const ErrorBudget& b) const { return excess(b) == 0.0; }
};

/// The format line a calibration file starts with. Format 4 added the `probe` knob (older
/// tables read with its default, 2, the only probe there was); format 3 counts false misses per
/// truth hit; format 2 added wrong_surface but counted false misses per ray of the frame, format
/// 1 had neither: their unmeasured errors read as NaN.
inline constexpr std::string_view calibration_format = "# proceduray-calibration 4";
inline constexpr int calibration_format_number = 4;

/// Whether `a` is at least as good as `b` in cost and every error, and better in one: then `b`
/// is off the front (no one would choose it).
PROCEDURAY_DECL bool dominates(const CalibrationRow& a, const CalibrationRow& b);

/// The table shipped with the library: $PROCEDURAY_SHADER_DIR/calibration/primitives.csv, else
/// the shader directory the build or install defines (PROCEDURAY_SHADER_DIR), else ./shaders.
PROCEDURAY_DECL std::filesystem::path shipped_calibration();

/// Measured settings per geometry, and the cheapest that meets a budget.
class Calibration {
 public:
  Calibration() = default;
  /// `source`: what was measured, when one file was (vk::calibrate: "<id> glsl <hash>"); kept as
  /// a line "# source <text>" so a table is not reused for another version of that file.
  Calibration(std::string device, std::string size, std::vector<CalibrationRow> rows, std::string source = {})
      : m_device(std::move(device)), m_size(std::move(size)), m_rows(std::move(rows)), m_source(std::move(source)) {}

  /// Reads a table; `source` names it in errors. Throws EnvironmentError for a foreign or
  /// damaged file, or one written by another library version (with both versions).
  static Calibration parse(std::istream& in, const std::string& source) {
    auto fail = [&](const std::string& what) -> EnvironmentError {
      return EnvironmentError("Calibration::load: " + source + ": " + what);
    };
    std::string line;
    auto next = [&](std::string& l) -> bool {  // a line without its CR (a table saved on Windows)
      if (!std::getline(in, l)) return false;
      if (!l.empty() && l.back() == '\r') l.pop_back();
      return true;
    };
    if (!next(line)) line.clear();
    int format = 0;
    for (int f = 1; f <= calibration_format_number; ++f) {
      if (line == "# proceduray-calibration " + std::to_string(f)) format = f;
    }
    if (format == 0) {
      throw fail("not a calibration table (line 1 is not '" + std::string(calibration_format) +
                 "'); write one with proceduray_sweep --calibration");
    }
    const bool per_ray_misses = format <= 2;
    if (!next(line) || line.rfind("# library ", 0) != 0) throw fail("line 2 does not name the library version");
    const std::string measured_by = line.substr(10);
    if (measured_by != version) {
      throw fail("measured by library " + measured_by + ", this is " + std::string(version) +
                 "; its marches may differ: re-run proceduray_sweep --calibration with this version");
    }
    if (!next(line) || line.rfind("# measured ", 0) != 0) throw fail("line 3 does not name the device and size");
    Calibration out;
    const std::string measured = line.substr(11);
    const auto space = measured.rfind(' ');
    out.m_device = space == std::string::npos ? measured : measured.substr(0, space);
    out.m_size = space == std::string::npos ? "" : measured.substr(space + 1);
    if (!next(line)) line.clear();
    if (line.rfind("# source ", 0) == 0) {
      out.m_source = line.substr(9);
      if (!next(line)) line.clear();
    }
    if (line != header(format)) throw fail("the column header is not this version's");
    const std::size_t errors = format == 1 ? 6 : 7;  // evals and the errors, before the knobs
    const std::size_t knobs = knob_columns(format);
    std::size_t number = 4;
    while (next(line)) {
      ++number;
      if (line.empty()) continue;
      std::vector<std::string> f;
      std::stringstream cells(line);
      for (std::string cell; std::getline(cells, cell, ',');) f.push_back(cell);
      if (f.size() != 2 + errors + knobs) {
        throw fail("line " + std::to_string(number) + " has " + std::to_string(f.size()) + " fields, not " +
                   std::to_string(2 + errors + knobs));
      }
      CalibrationRow r;
      r.geometry = f[0];
      r.kind = f[1];
      try {
        double* numbers[] = {&r.evals, &r.depth_median, &r.depth_p99, &r.silhouette_false_hits, &r.false_misses,
                             &r.normal_p95, &r.wrong_surface};
        for (std::size_t i = 0; i < errors; ++i) {
          std::size_t used = 0;
          *numbers[i] = std::stod(f[2 + i], &used);
          const bool unmeasured = i == 6 && std::isnan(*numbers[i]);  // wrong_surface of a sweep without it
          if (used != f[2 + i].size() || (!(*numbers[i] >= 0.0) && !unmeasured)) throw UsageError(f[2 + i]);
        }
        if (per_ray_misses) r.false_misses = std::numeric_limits<double>::quiet_NaN();  // another unit
        r.knobs = march_base_knobs;
        for (std::size_t k = 0; k < knobs; ++k) {
          set_knob(r.knobs, march_knob_names[k], f[2 + errors + k]);
        }
      } catch (const std::exception& e) {
        throw fail("line " + std::to_string(number) + " has a bad value (" + e.what() + ")");
      }
      out.m_rows.push_back(std::move(r));
    }
    return out;
  }

  /// Reads the file at `path` (see parse); a missing file is an EnvironmentError naming it.
  static Calibration load(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) {
      throw EnvironmentError("Calibration::load: cannot read '" + path.string() +
                             "'; pass a table written by proceduray_sweep --calibration (the shipped one is "
                             "shaders/calibration/primitives.csv: set PROCEDURAY_SHADER_DIR)");
    }
    return parse(in, path.string());
  }

  /// The column header of the rows of a table of `format` (1: without wrong_surface; before 4:
  /// without probe).
  static std::string header(int format = calibration_format_number) {
    std::string h = "geometry,kind,evals,depth_median,depth_p99,silhouette_false_hits,false_misses,normal_p95_degrees,";
    if (format != 1) h += "wrong_surface,";
    for (std::size_t i = 0; i < knob_columns(format); ++i) h += std::string(i ? "," : "") + std::string(march_knob_names[i]);
    return h;
  }
  /// The knobs a table of `format` has columns for: the first n of march_knob_names.
  static std::size_t knob_columns(int format) { return format < 4 ? 14 : march_knob_names.size(); }

  /// Writes the table in the format parse reads.
  void write(std::ostream& out) const {
    out << calibration_format << "\n# library " << version << "\n# measured " << m_device << " " << m_size << "\n";
    if (!m_source.empty()) out << "# source " << m_source << "\n";
    out << header() << "\n";
    out.precision(9);
    for (const CalibrationRow& r : m_rows) {
      out << r.geometry << "," << r.kind << "," << r.evals << "," << r.depth_median << "," << r.depth_p99 << ","
          << r.silhouette_false_hits << "," << r.false_misses << "," << r.normal_p95 << "," << r.wrong_surface;
      for (const auto& kv : knob_values(r.knobs)) out << "," << kv.second;
      out << "\n";
    }
  }

  /// The cheapest row of `geometry` (fewest evaluations) that meets `budget`. Throws UsageError
  /// for a geometry the table lacks (listing those it has) or a budget no row meets (naming the
  /// best reachable: the row least over it, and its errors).
  const CalibrationRow& cheapest(std::string_view geometry, const ErrorBudget& budget) const {
    validate(budget, "Calibration::cheapest");
    const CalibrationRow* best = nullptr;
    const CalibrationRow* closest = nullptr;
    for (const CalibrationRow& r : m_rows) {
      if (r.geometry != geometry) continue;
      if (r.meets(budget) && (best == nullptr || r.evals < best->evals)) best = &r;
      if (closest == nullptr || r.excess(budget) < closest->excess(budget)) closest = &r;
    }
    if (best != nullptr) return *best;
    if (closest == nullptr) {
      std::string names;
      for (const std::string& g : geometries()) names += (names.empty() ? "" : ", ") + g;
      if (names.empty()) {
        throw UsageError("Calibration::cheapest: no rows for '" + std::string(geometry) +
                         "': the table is empty; calibrate it (proceduray_sweep --calibration, or vk::calibrate)");
      }
      throw UsageError("Calibration::cheapest: no rows for '" + std::string(geometry) + "'; the table has: " + names);
    }
    std::ostringstream m;
    m << "Calibration::cheapest: no calibrated setting of '" << geometry << "' meets the budget (depth median <= "
      << budget.depth_median << ", p99 <= " << budget.depth_p99 << " footprints, silhouette false hits <= "
      << budget.silhouette_false_hits << ", false misses <= " << budget.false_misses << ", wrong surface <= "
      << budget.wrong_surface << ", normal p95 <= " << budget.normal_p95
      << " degrees); the best reachable: depth median " << closest->depth_median << ", p99 " << closest->depth_p99
      << ", silhouette false hits " << closest->silhouette_false_hits << ", false misses "
      << (std::isnan(closest->false_misses) ? std::string("not measured per hit (a format-1 or -2 table)")
                                            : std::to_string(closest->false_misses))
      << ", wrong surface "
      << (std::isnan(closest->wrong_surface) ? std::string("not measured (a format-1 table)")
                                             : std::to_string(closest->wrong_surface))
      << ", normal p95 " << closest->normal_p95
      << " at " << closest->evals << " evaluations (" << describe(closest->knobs)
      << "); loosen the budget or calibrate finer settings (proceduray_sweep --calibration)";
    throw UsageError(m.str());
  }

  /// The geometries the table covers, in first-seen order.
  std::vector<std::string> geometries() const {
    std::vector<std::string> out;
    for (const CalibrationRow& r : m_rows) {
      bool seen = false;
      for (const std::string& g : out) seen = seen || g == r.geometry;
      if (!seen) out.push_back(r.geometry);
    }
    return out;
  }

  const std::vector<CalibrationRow>& rows() const noexcept { return m_rows; }
  const std::string& device() const noexcept { return m_device; }
  const std::string& size() const noexcept { return m_size; }
  /// What was measured ("" when not recorded): see the constructor.
  const std::string& source() const noexcept { return m_source; }

 private:
  std::string m_device, m_size;
  std::vector<CalibrationRow> m_rows;
  std::string m_source;
};

}  // namespace proceduray

#include "proceduray/march/calibration-inl.hpp"  // the bodies (config.hpp)
