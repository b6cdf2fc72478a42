// Defaults from a stated budget: every marched primitive's default knobs (the example scenes'
// per-primitive picks) are the cheapest setting of the shipped 1920x1080 calibration table that
// meets ErrorBudget{}, a picture that cannot be told from exact, there and in the 640x360 table;
// each kind's default (march/primitives.hpp) meets it on every shipped primitive of the kind in
// both, at the least total cost.
#include <02_paper_scene/paper_types.hpp>
#include <03_d3d12_scene/d3d12_types.hpp>
#include <proceduray/march/calibration.hpp>
#include <proceduray/march/primitives.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

using namespace proceduray;

namespace {

/// Every marched primitive of the two scenes with its default knobs.
std::vector<std::pair<std::string, MarchKnobs>> scene_defaults() {
  std::vector<std::pair<std::string, MarchKnobs>> out;
  out.emplace_back("julia", paper::julia_knobs);  // the fields' starting knobs (DistanceFieldDesc::knobs)
  out.emplace_back("mandelbulb", paper::mandelbulb_knobs);
  for (std::uint32_t k = d3d12::metaballs; k < d3d12::primitive_count; ++k) {
    const auto kind = static_cast<d3d12::PrimitiveKind>(k);
    out.emplace_back(std::string(d3d12::primitive_names[k]), d3d12::capabilities(kind).defaults);
  }
  return out;
}

/// A setting apart from its iteration count (a kind's fractals differ only there).
std::string setting(MarchKnobs k) {
  k.iterations = 0;
  return describe(k);
}

/// The shipped tables: 1920x1080 (H200), whose costs rank the settings, and 640x360 (lavapipe).
struct Tables {
  Calibration full = Calibration::load(shipped_calibration());
  Calibration small = Calibration::load(shipped_calibration().parent_path() / "primitives_640x360.csv");
  /// small's verdict per geometry and setting, looked up once per row of full.
  std::map<std::string, bool> small_meets = [this] {
    std::map<std::string, bool> out;
    for (const CalibrationRow& s : small.rows()) out[s.geometry + " " + describe(s.knobs)] = s.meets(ErrorBudget{});
    return out;
  }();
  /// Whether `r` (a row of `full`) meets the default budget in both tables.
  bool meets(const CalibrationRow& r) const {
    const auto it = small_meets.find(r.geometry + " " + describe(r.knobs));
    return r.meets(ErrorBudget{}) && it != small_meets.end() && it->second;  // not measured there: no
  }
};

}  // namespace

TEST_CASE("march defaults - the shipped tables are measured at 1080p and 640x360 with every error") {
  const Tables t;
  CHECK(t.full.size() == "1920x1080");
  CHECK(t.small.size() == "640x360");
  for (const Calibration* table : {&t.full, &t.small}) {
    REQUIRE(table->rows().size() > 300);
    for (const CalibrationRow& r : table->rows()) CHECK_FALSE(std::isnan(r.wrong_surface));
  }
}

TEST_CASE("march defaults - each primitive's default is its cheapest setting meeting the default budget") {
  const Tables t;
  for (const auto& entry : scene_defaults()) {  // not a structured binding: clang 14 cannot capture one in CAPTURE
    const std::string& name = entry.first;
    CAPTURE(name);
    CAPTURE(describe(entry.second));
    const CalibrationRow* own = nullptr;
    double cheapest = std::numeric_limits<double>::infinity();
    for (const CalibrationRow& r : t.full.rows()) {
      if (r.geometry != name) continue;
      if (describe(r.knobs) == describe(entry.second)) own = &r;
      if (t.meets(r)) cheapest = std::min(cheapest, r.evals);
    }
    REQUIRE(own != nullptr);  // the sweep measured the default itself
    CHECK(t.meets(*own));
    CHECK(own->evals == doctest::Approx(cheapest).epsilon(1e-9));
  }
}

TEST_CASE("march defaults - each kind's default meets the budget on all its primitives at the least total cost") {
  const Tables t;
  std::map<std::string, std::uint32_t> iterations;  // the geometry's own count: the rows a kind default stands for
  for (const auto& [name, knobs] : scene_defaults()) iterations[name] = knobs.iterations;
  for (const MarchCapabilities& caps : {sdf_capabilities(), metaball_capabilities(), fractal_capabilities(8)}) {
    CAPTURE(caps.kind);
    // Per setting: how many of the kind's primitives it meets the budget on, and their cost.
    std::map<std::string, std::pair<std::size_t, double>> met;
    std::map<std::string, bool> geometries;
    for (const CalibrationRow& r : t.full.rows()) {
      if (r.kind != caps.kind || r.knobs.iterations != iterations.at(r.geometry)) continue;
      geometries[r.geometry] = true;
      if (!t.meets(r)) continue;
      auto& [count, evals] = met[setting(r.knobs)];
      ++count;
      evals += r.evals;
    }
    REQUIRE(geometries.size() >= 1);
    double cheapest = std::numeric_limits<double>::infinity();
    for (const auto& [s, m] : met) {
      if (m.first == geometries.size()) cheapest = std::min(cheapest, m.second);
    }
    const auto own = met.find(setting(caps.defaults));
    REQUIRE(own != met.end());
    CHECK(own->second.first == geometries.size());
    CHECK(own->second.second == doctest::Approx(cheapest).epsilon(1e-9));
  }
}
