// accuracy::Metrics as an aligned text table for people and as CSV for the charting script: the same
// columns in the same order, under names that stay stable.
//
//   #include <iostream>
//   #include <sstream>
//   namespace acc = proceduray::accuracy;
//   const acc::Metrics m{};                       // from acc::measure(frame, samples, truth)
//   acc::write_table(std::cout, m);               // a line per column, a column per class
//   std::ostringstream csv;
//   const std::vector<acc::Label> run{{"method", "sphere_tracing"}, {"max_steps", "128"}};
//   acc::write_csv(csv, m, run);                  // header "method,max_steps,class,rays,...", 5 rows
//   acc::write_csv_rows(csv, m, run);             // the next run of a sweep: rows only, same header
//
// CSV: a header line, then a row per PixelClass in order (silhouette_1px, silhouette_2px, interior,
// far) and a last row "all". The columns: the labels' names in the order given (the knobs of the
// run), "class", then these, whose names and meanings never change (new ones go at the end):
//   rays undetermined agree false_hits false_misses agree_rate false_hit_rate false_miss_rate
//   both_hit depth_px_median depth_px_p95 depth_px_p99 depth_px_max normal_rays normal_deg_median
//   normal_deg_p95 normal_deg_max steps_mean steps_median steps_p99 steps_max nonfinite exhausted
//   started_inside wrong_surface wrong_surface_rate
// (meanings: columns()[i].meaning, and ClassStats in metrics.hpp). Counts are written as integers,
// other values with 9 significant digits, infinity as "inf", and a value that does not exist (the
// median of no rays, a rate of no rays) as an empty field: "no data" must not read as zero. Fields
// with a comma, quote or line break are quoted as RFC 4180 says. The table writes "-" for no data.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "proceduray/accuracy/metrics.hpp"
#include "proceduray/error.hpp"

namespace proceduray::accuracy {

/// One column of the table and the CSV.
struct Column {
  std::string_view name;                         ///< stable CSV name
  std::string_view meaning;                      ///< one line, with the unit
  bool count = false;                            ///< an integer count (written without decimals)
  double (*value)(const ClassStats&) = nullptr;  ///< the value in one class's statistics
};

/// The metric columns, in CSV order (after the labels and "class").
inline std::span<const Column> columns() {
  using S = const ClassStats&;
  static constexpr std::array<Column, 26> all{{
      {"rays", "rays with a determined reference", true, [](S s) { return double(s.rays); }},
      {"undetermined", "rays with an undetermined reference (in no other column)", true,
       [](S s) { return double(s.undetermined); }},
      {"agree", "rays where method and reference agree on hit or miss", true, [](S s) { return double(s.agree); }},
      {"false_hits", "method hit, reference missed", true, [](S s) { return double(s.false_hits); }},
      {"false_misses", "method missed, reference hit", true, [](S s) { return double(s.false_misses); }},
      {"agree_rate", "agree / rays", false, [](S s) { return s.agree_rate(); }},
      {"false_hit_rate", "false_hits / rays", false, [](S s) { return s.false_hit_rate(); }},
      {"false_miss_rate", "false_misses / rays", false, [](S s) { return s.false_miss_rate(); }},
      {"both_hit", "rays both hit", true, [](S s) { return double(s.both_hit); }},
      {"depth_px_median", "|t - t_ref| in pixel footprints, median", false, [](S s) { return s.depth.median; }},
      {"depth_px_p95", "|t - t_ref| in pixel footprints, p95", false, [](S s) { return s.depth.p95; }},
      {"depth_px_p99", "|t - t_ref| in pixel footprints, p99", false, [](S s) { return s.depth.p99; }},
      {"depth_px_max", "|t - t_ref| in pixel footprints, max", false, [](S s) { return s.depth.max; }},
      {"normal_rays", "rays with a normal error (both hit, normals finite)", true,
       [](S s) { return double(s.normal_degrees.count); }},
      {"normal_deg_median", "normal angle error in degrees, median", false,
       [](S s) { return s.normal_degrees.median; }},
      {"normal_deg_p95", "normal angle error in degrees, p95", false, [](S s) { return s.normal_degrees.p95; }},
      {"normal_deg_max", "normal angle error in degrees, max", false, [](S s) { return s.normal_degrees.max; }},
      {"steps_mean", "steps per ray, mean", false, [](S s) { return s.steps.mean; }},
      {"steps_median", "steps per ray, median", false, [](S s) { return s.steps.median; }},
      {"steps_p99", "steps per ray, p99", false, [](S s) { return s.steps.p99; }},
      {"steps_max", "steps per ray, max", false, [](S s) { return s.steps.max; }},
      {"nonfinite", "rays with a NaN or Inf output or flags::nan_seen", true, [](S s) { return double(s.nonfinite); }},
      {"exhausted", "rays whose march ran out of steps", true, [](S s) { return double(s.exhausted); }},
      {"started_inside", "rays that started inside the object", true, [](S s) { return double(s.started_inside); }},
      {"wrong_surface", "both hit, the method more than 2 footprints behind the truth", true,
       [](S s) { return double(s.wrong_surface); }},
      {"wrong_surface_rate", "wrong_surface / the truth's hits", false, [](S s) { return s.wrong_surface_rate(); }},
  }};
  return all;
}

/// A column the caller adds to every CSV row: a knob of the run (method, max steps, epsilon, ...).
struct Label {
  std::string name;
  std::string value;
};

namespace detail {
/// A value as text: counts as integers, others with `digits` significant digits; NaN as `none`.
inline std::string format_value(double v, bool count, int digits, std::string_view none) {
  if (std::isnan(v)) return std::string(none);
  if (count) return std::to_string(static_cast<std::uint64_t>(v));
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  std::array<char, 32> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%.*g", digits, v);
  return buffer.data();
}

/// A CSV field, quoted (quotes doubled) when it holds a comma, quote or line break.
inline std::string csv_field(std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

/// Throws unless the label names are non-empty, distinct, and not "class" or a metric column.
inline void check_labels(const std::vector<Label>& labels, std::string_view call) {
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const std::string& n = labels[i].name;
    const bool metric = std::any_of(columns().begin(), columns().end(), [&](const Column& c) { return c.name == n; });
    const bool repeated = std::any_of(labels.begin(), labels.begin() + static_cast<std::ptrdiff_t>(i),
                                      [&](const Label& l) { return l.name == n; });
    if (n.empty() || n == "class" || metric || repeated) {
      throw UsageError(std::string(call) + ": label #" + std::to_string(i) + " is named \"" + n + "\", which is " +
                       (n.empty() ? "empty" : repeated ? "a repeated label" : "a column of the report") +
                       "; give each label its own name, other than \"class\" and the names of columns()");
    }
  }
}

/// Every report row: the classes in order, then "all".
inline std::array<std::pair<std::string_view, const ClassStats*>, 5> rows(const Metrics& m) {
  return {{{name(pixel_classes[0]), &m[pixel_classes[0]]},
           {name(pixel_classes[1]), &m[pixel_classes[1]]},
           {name(pixel_classes[2]), &m[pixel_classes[2]]},
           {name(pixel_classes[3]), &m[pixel_classes[3]]},
           {"all", &m.all}}};
}
}  // namespace detail

/// Writes the CSV header line: the label names, "class", then columns(). Throws UsageError for a bad label name.
inline void write_csv_header(std::ostream& out, const std::vector<Label>& labels = {}) {
  detail::check_labels(labels, "accuracy::write_csv_header");
  std::string line;
  for (const Label& l : labels) line += detail::csv_field(l.name) + ",";
  line += "class";
  for (const Column& c : columns()) line += "," + std::string(c.name);
  out << line << '\n';
}

/// Writes one CSV row per class and a last row "all", each starting with the label values.
inline void write_csv_rows(std::ostream& out, const Metrics& metrics, const std::vector<Label>& labels = {}) {
  detail::check_labels(labels, "accuracy::write_csv_rows");
  for (const auto& [row_name, stats] : detail::rows(metrics)) {
    std::string line;
    for (const Label& l : labels) line += detail::csv_field(l.value) + ",";
    line += row_name;
    for (const Column& c : columns()) line += "," + detail::format_value(c.value(*stats), c.count, 9, "");
    out << line << '\n';
  }
}

/// The header line, then the rows: a whole CSV file for one run.
inline void write_csv(std::ostream& out, const Metrics& metrics, const std::vector<Label>& labels = {}) {
  write_csv_header(out, labels);
  write_csv_rows(out, metrics, labels);
}

/// Writes the metrics as an aligned text table: a line per column, a column per class and "all";
/// values with 4 significant digits, "-" for no data.
inline void write_table(std::ostream& out, const Metrics& metrics) {
  const auto rows = detail::rows(metrics);
  std::vector<std::vector<std::string>> cells{{"metric"}};
  for (const auto& row : rows) cells[0].emplace_back(row.first);
  for (const Column& c : columns()) {
    cells.push_back({std::string(c.name)});
    for (const auto& row : rows) cells.back().push_back(detail::format_value(c.value(*row.second), c.count, 4, "-"));
  }
  std::vector<std::size_t> width(cells[0].size(), 0);
  for (const auto& line : cells) {
    for (std::size_t i = 0; i < line.size(); ++i) width[i] = std::max(width[i], line[i].size());
  }
  for (std::size_t r = 0; r < cells.size(); ++r) {
    std::string line = cells[r][0] + std::string(width[0] - cells[r][0].size(), ' ');
    // Names left-aligned, values right-aligned so that digits line up.
    for (std::size_t i = 1; i < cells[r].size(); ++i) {
      line += "  " + std::string(width[i] - cells[r][i].size(), ' ') + cells[r][i];
    }
    out << line << '\n';
    if (r == 0) {
      std::string rule;
      for (std::size_t i = 0; i < width.size(); ++i) rule += (i == 0 ? "" : "  ") + std::string(width[i], '-');
      out << rule << '\n';
    }
  }
}

}  // namespace proceduray::accuracy
