// Nearest-rank percentiles, and the summary of a distribution that the accuracy metrics report.
//
//   const std::vector<double> errors{0.5, 0.1, 2.0, 0.3};
//   double p95 = proceduray::accuracy::percentile(errors, 95.0);  // 2.0: rank ceil(0.95 * 4) = 4
//   proceduray::accuracy::Distribution d = proceduray::accuracy::summarize(errors);
//   d.median;  // 0.3: rank ceil(0.50 * 4) = 2 of the sorted values 0.1 0.3 0.5 2.0
//   d.max;     // 2.0, the same as percentile(errors, 100.0)
//
// The nearest-rank method: the p-th percentile (0 <= p <= 100) of n values is the value of
// 1-based rank max(1, ceil(p * n / 100)) in ascending order. It never interpolates, so every
// percentile is a value that occurred (a p99 of steps per ray is a step count some ray took),
// it needs no convention for small n, and p100 is the maximum, p0 the minimum. The median is
// p50, the lower middle value for even n. NaN has no rank: it is a UsageError here, and the
// metrics count NaN outputs apart (metrics.hpp) instead of sorting them.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "proceduray/error.hpp"

namespace proceduray::accuracy {

namespace detail {
/// A number for a message: up to 9 significant digits, so 1e-9 does not print as 0.000000.
inline std::string number(double v) {
  std::array<char, 32> text{};
  std::snprintf(text.data(), text.size(), "%.9g", v);
  return text.data();
}
}  // namespace detail

/// Count, mean and nearest-rank percentiles of a sample; every field but count is NaN when count is 0.
struct Distribution {
  std::size_t count = 0;                                    ///< how many values
  double mean = std::numeric_limits<double>::quiet_NaN();   ///< arithmetic mean
  double median = std::numeric_limits<double>::quiet_NaN(); ///< p50 (nearest rank)
  double p95 = std::numeric_limits<double>::quiet_NaN();    ///< 95th percentile (nearest rank)
  double p99 = std::numeric_limits<double>::quiet_NaN();    ///< 99th percentile (nearest rank)
  double max = std::numeric_limits<double>::quiet_NaN();    ///< largest value (p100)
};

/// The 1-based nearest rank of percentile p among n values: max(1, ceil(p * n / 100)); throws UsageError
/// unless 0 <= p <= 100 and n > 0.
inline std::size_t nearest_rank(double p, std::size_t n, std::string_view call = "accuracy::nearest_rank") {
  if (!(p >= 0.0 && p <= 100.0)) {
    throw UsageError(std::string(call) + ": percentile " + detail::number(p) +
                     " is outside [0, 100]; pass 50 for the median, 100 for the maximum");
  }
  if (n == 0) {
    throw UsageError(std::string(call) + ": no values; a percentile needs at least one value "
                     "(summarize() reports an empty sample as count 0 with NaN fields)");
  }
  // p * n first, then / 100: for whole p and n the product is exact, so p7 of 100 values is rank 7,
  // not 8 as ceil(0.07 * 100) would give (0.07 is a little above 7/100 in binary: 7.000000000000001).
  const double rank = std::ceil(p * static_cast<double>(n) / 100.0);
  return std::clamp<std::size_t>(static_cast<std::size_t>(rank), 1, n);
}

namespace detail {
/// Throws UsageError naming `call` and the index of the first NaN in `values`.
inline void check_no_nan(std::span<const double> values, std::string_view call) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (std::isnan(values[i])) {
      throw UsageError(std::string(call) + ": value #" + std::to_string(i) + " of " +
                       std::to_string(values.size()) + " is NaN; NaN has no rank: drop NaN values and count them "
                       "apart (accuracy::measure does)");
    }
  }
}
/// The nearest-rank percentile of values sorted ascending.
inline double sorted_percentile(std::span<const double> sorted, double p, std::string_view call) {
  return sorted[nearest_rank(p, sorted.size(), call) - 1];
}
}  // namespace detail

/// The nearest-rank p-th percentile (0 <= p <= 100) of values in any order; throws UsageError for an
/// empty span, a NaN value or p outside [0, 100].
inline double percentile(std::span<const double> values, double p) {
  constexpr std::string_view call = "accuracy::percentile";
  detail::check_no_nan(values, call);
  const std::size_t rank = nearest_rank(p, values.size(), call);
  std::vector<double> copy(values.begin(), values.end());
  // Selection, not a full sort: one percentile of a frame's worth of rays is O(n).
  std::nth_element(copy.begin(), copy.begin() + static_cast<std::ptrdiff_t>(rank - 1), copy.end());
  return copy[rank - 1];
}

/// Count, mean, median, p95, p99 and max of values in any order (one sort); throws UsageError for a NaN
/// value. Infinities are ranked like any value and make the mean infinite.
inline Distribution summarize(std::span<const double> values) {
  constexpr std::string_view call = "accuracy::summarize";
  detail::check_no_nan(values, call);
  Distribution d;
  d.count = values.size();
  if (values.empty()) return d;
  std::vector<double> sorted(values.begin(), values.end());
  std::sort(sorted.begin(), sorted.end());
  double sum = 0.0;
  for (double v : sorted) sum += v;
  d.mean = sum / static_cast<double>(sorted.size());
  d.median = detail::sorted_percentile(sorted, 50.0, call);
  d.p95 = detail::sorted_percentile(sorted, 95.0, call);
  d.p99 = detail::sorted_percentile(sorted, 99.0, call);
  d.max = sorted.back();
  return d;
}

}  // namespace proceduray::accuracy
