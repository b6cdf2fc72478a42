// The defaults from the front: every marched primitive's default knobs (march/primitives.hpp,
// and the scenes' per-primitive choices) are a row of the shipped calibration table that no
// other row beats in cost and every error at once (depth median and p99, silhouette false
// hits, false misses, normal error).
#include <02_paper_scene/paper_types.hpp>
#include <03_d3d12_scene/d3d12_types.hpp>
#include <proceduray/march/calibration.hpp>

#include <doctest/doctest.h>

#include <string>
#include <utility>
#include <vector>

using namespace proceduray;

TEST_CASE("march defaults - each primitive's default is measured and on its front") {
  const Calibration table = Calibration::load(shipped_calibration());
  std::vector<std::pair<std::string, MarchKnobs>> defaults;
  for (const auto& [id, name] : paper::marched_objects) defaults.emplace_back(name, paper::capabilities(id).defaults);
  for (std::uint32_t k = d3d12::metaballs; k < d3d12::primitive_count; ++k) {
    const auto kind = static_cast<d3d12::PrimitiveKind>(k);
    defaults.emplace_back(std::string(d3d12::primitive_names[k]), d3d12::capabilities(kind).defaults);
  }
  for (const auto& entry : defaults) {  // not a structured binding: clang 14 cannot capture one in CAPTURE
    const std::string& name = entry.first;
    const MarchKnobs& knobs = entry.second;
    CAPTURE(name);
    CAPTURE(describe(knobs));
    const CalibrationRow* own = nullptr;
    for (const CalibrationRow& r : table.rows()) {
      if (r.geometry == name && describe(r.knobs) == describe(knobs)) own = &r;
    }
    REQUIRE(own != nullptr);  // the sweep measured the default itself
    for (const CalibrationRow& r : table.rows()) {
      if (r.geometry != name) continue;
      CAPTURE(describe(r.knobs));
      CHECK_FALSE(dominates(r, *own));
    }
  }
}
