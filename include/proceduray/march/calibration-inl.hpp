// The bodies of proceduray/march/calibration.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/march/calibration.hpp"

#if PROCEDURAY_BODIES
namespace proceduray {

PROCEDURAY_DECL bool dominates(const CalibrationRow& a, const CalibrationRow& b) {
  // Unmeasured (NaN) is the worst value: a row that measured it can dominate one that did not.
  auto v = [](double x) { return std::isnan(x) ? std::numeric_limits<double>::infinity() : x; };
  const double av[] = {a.evals, a.depth_median, a.depth_p99, a.silhouette_false_hits, a.false_misses, a.normal_p95,
                       v(a.wrong_surface)};
  const double bv[] = {b.evals, b.depth_median, b.depth_p99, b.silhouette_false_hits, b.false_misses, b.normal_p95,
                       v(b.wrong_surface)};
  bool better = false;
  for (std::size_t i = 0; i < 7; ++i) {
    if (av[i] > bv[i]) return false;
    better = better || av[i] < bv[i];
  }
  return better;
}

PROCEDURAY_DECL std::filesystem::path shipped_calibration() {
  std::filesystem::path dir = "shaders";
  if (const char* env = std::getenv("PROCEDURAY_SHADER_DIR"); env != nullptr && *env != '\0') {
    dir = env;
  } else {
#ifdef PROCEDURAY_SHADER_DIR
    dir = PROCEDURAY_SHADER_DIR;
#endif
  }
  return dir / "calibration" / "primitives.csv";
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
