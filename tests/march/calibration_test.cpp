// march/calibration.hpp and version.hpp: the table's round trip, the cheapest setting within a
// budget, and the refusals (another version, a foreign file, an unmeetable budget).
#include <proceduray/march/calibration.hpp>
#include <proceduray/march/primitives.hpp>
#include <proceduray/version.hpp>

#include <doctest/doctest.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>

using namespace proceduray;

namespace {

CalibrationRow row(const char* geometry, double evals, double median, double p99, double fat, const char* threshold) {
  CalibrationRow r{geometry, "sdf", sdf_capabilities().defaults, evals, median, p99, fat, 0.0, 0.5};
  set_knob(r.knobs, "threshold", threshold);
  return r;
}

Calibration table() {
  return Calibration("test device", "64x64",
                     {row("cog", 30.0, 0.001, 0.004, 0.0, "0.125"), row("cog", 20.0, 0.005, 0.015, 0.0, "0.5"),
                      row("cog", 15.0, 0.02, 0.06, 0.01, "2"), row("cog", 25.0, 0.02, 0.2, 0.0, "0.25"),
                      row("torus", 40.0, 0.003, 0.01, 0.0, "0.5")});
}

std::string text_of(const Calibration& c) {
  std::ostringstream out;
  c.write(out);
  return out.str();
}

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("calibration - the library version is the build files' version") {
  const std::string root = PROCEDURAY_TEST_SOURCE_DIR "/..";
  std::smatch m;
  const std::string cmake = read(root + "/CMakeLists.txt"), meson = read(root + "/meson.build");
  REQUIRE(std::regex_search(cmake, m, std::regex(R"(project\(proceduray VERSION ([0-9.]+))")));
  CHECK(m[1].str() == std::string(version));
  REQUIRE(std::regex_search(meson, m, std::regex(R"(version: '([0-9.]+)')")));
  CHECK(m[1].str() == std::string(version));
}

TEST_CASE("calibration - a table round-trips through its file") {
  const Calibration a = table();
  std::istringstream in(text_of(a));
  const Calibration b = Calibration::parse(in, "memory");
  CHECK(b.device() == "test device");
  CHECK(b.size() == "64x64");
  REQUIRE(b.rows().size() == a.rows().size());
  for (std::size_t i = 0; i < a.rows().size(); ++i) {
    CHECK(b.rows()[i].geometry == a.rows()[i].geometry);
    CHECK(b.rows()[i].evals == a.rows()[i].evals);
    CHECK(b.rows()[i].depth_p99 == a.rows()[i].depth_p99);
    CHECK(describe(b.rows()[i].knobs) == describe(a.rows()[i].knobs));
  }
  CHECK(b.geometries() == std::vector<std::string>{"cog", "torus"});
}

TEST_CASE("calibration - the cheapest row within the budget, cheaper as it loosens") {
  const Calibration t = table();
  CHECK(t.cheapest("cog", {.depth_median = 0.002}).evals == 30.0);
  CHECK(t.cheapest("cog", {.depth_median = 0.01, .depth_p99 = 0.02}).evals == 20.0);
  CHECK(t.cheapest("cog", {.depth_median = 0.05}).evals == 15.0);
  // The silhouette bound rules out the cheapest: fat silhouettes are an error too.
  CHECK(t.cheapest("cog", {.depth_median = 0.05, .silhouette_false_hits = 0.0}).evals == 20.0);
  CHECK(t.cheapest("cog", {}).evals == 15.0);  // no bound: the cheapest of all
  CHECK(t.cheapest("torus", {}).knobs.threshold == 0.5f);
  // The normal's error is a budget too.
  CalibrationRow sharp = row("cog", 16.0, 0.02, 0.06, 0.0, "2");
  sharp.normal_p95 = 20.0;
  const Calibration with_normals("d", "1x1", {sharp, row("cog", 18.0, 0.02, 0.06, 0.0, "1")});
  CHECK(with_normals.cheapest("cog", {}).evals == 16.0);
  CHECK(with_normals.cheapest("cog", {.normal_p95 = 1.0}).evals == 18.0);
}

TEST_CASE("calibration - a row off the front is dominated in cost and every error") {
  const CalibrationRow a = row("cog", 20.0, 0.005, 0.015, 0.0, "0.5");
  CalibrationRow b = a;
  CHECK_FALSE(dominates(a, b));  // equal: neither
  b.evals = 21.0;
  CHECK(dominates(a, b));
  b.normal_p95 = 0.1;  // b's normals are better: a no longer dominates
  CHECK_FALSE(dominates(a, b));
  CHECK_FALSE(dominates(b, a));
}

TEST_CASE("calibration - an unmeetable budget names the best reachable setting") {
  const Calibration t = table();
  CHECK_THROWS_WITH_AS(t.cheapest("cog", {.depth_median = 1e-5}),
                       doctest::Contains("no calibrated setting of 'cog' meets the budget (depth median <= 1e-05"),
                       UsageError);
  CHECK_THROWS_WITH_AS(t.cheapest("cog", {.depth_median = 1e-5}),
                       doctest::Contains("the best reachable: depth median 0.001, p99 0.004"), UsageError);
  CHECK_THROWS_WITH_AS(t.cheapest("cog", {.depth_median = 1e-5}), doctest::Contains("at 30 evaluations (method=lipschitz"),
                       UsageError);
  CHECK_THROWS_WITH_AS(t.cheapest("teapot", {}), doctest::Contains("no rows for 'teapot'; the table has: cog, torus"),
                       UsageError);
}

TEST_CASE("calibration - another version, a foreign file and damaged rows are refused") {
  std::string text = text_of(table());
  const std::string old = std::regex_replace(text, std::regex("# library [0-9.]+"), "# library 0.0.9");
  std::istringstream in_old(old);
  const std::string refused = "old.csv: measured by library 0.0.9, this is " + std::string(version) +
                              "; its marches may differ";
  CHECK_THROWS_WITH_AS(Calibration::parse(in_old, "old.csv"), doctest::Contains(refused.c_str()), EnvironmentError);
  std::istringstream foreign("scene,device\npaper,x\n");
  CHECK_THROWS_WITH_AS(Calibration::parse(foreign, "sweep.csv"), doctest::Contains("not a calibration table"),
                       EnvironmentError);
  std::string damaged = text;
  damaged.replace(damaged.find(",30,"), 4, ",x30,");
  std::istringstream in_damaged(damaged);
  CHECK_THROWS_WITH_AS(Calibration::parse(in_damaged, "bad.csv"), doctest::Contains("bad.csv: line 5 has a bad value"),
                       EnvironmentError);
  std::string bad_knob = text;
  bad_knob.replace(bad_knob.find("lipschitz"), 9, "wobbly");
  std::istringstream in_knob(bad_knob);
  CHECK_THROWS_WITH_AS(Calibration::parse(in_knob, "knob.csv"), doctest::Contains("unknown method 'wobbly'"),
                       EnvironmentError);
  CHECK_THROWS_WITH_AS(Calibration::load("/nonexistent/table.csv"), doctest::Contains("cannot read '/nonexistent/table.csv'"),
                       EnvironmentError);
}

TEST_CASE("calibration - the shipped table loads and covers every marched primitive") {
  const Calibration t = Calibration::load(shipped_calibration());
  for (const char* g : {"julia", "mandelbulb", "metaballs", "mini_spheres", "round_cube", "square_torus",
                        "twisted_torus", "cog", "cylinder", "fractal_pyramid"}) {
    CAPTURE(g);
    CHECK_NOTHROW(t.cheapest(g, {}));
  }
}
