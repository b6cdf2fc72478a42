// march/calibration.hpp and version.hpp: the table's round trip, the cheapest setting within a
// budget, and the refusals (another version, a foreign file, an unmeetable budget).
#include <proceduray/march/calibration.hpp>
#include <proceduray/march/primitives.hpp>
#include <proceduray/version.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <string>

using namespace proceduray;

namespace {

CalibrationRow row(const char* geometry, double evals, double median, double p99, double fat, const char* threshold) {
  CalibrationRow r{geometry, "sdf", march_base_knobs, evals, median, p99, fat, 0.0, 0.5, 0.0};  // Lipschitz steps
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

/// The test table's text as a table of an older format (1 to 3) would write it: its format line,
/// and no probe column (the knob came with format 4).
std::string in_format(const char* number) {
  std::string text = std::regex_replace(text_of(table()), std::regex("# proceduray-calibration 4"),
                                        std::string("# proceduray-calibration ") + number);
  return std::regex_replace(text, std::regex(",(probe|2)\n"), "\n");
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
  CHECK(b.source().empty());
  // A table that says what it measured keeps it.
  const Calibration c("d", "8x8", a.rows(), "gyroid glsl 0123456789abcdef");
  std::istringstream in_c(text_of(c));
  CHECK(Calibration::parse(in_c, "memory").source() == "gyroid glsl 0123456789abcdef");
}

TEST_CASE("calibration - the cheapest row within the budget, cheaper as it loosens") {
  const Calibration t = table();
  CHECK(t.cheapest("cog", {.depth_median = 0.002}).evals == 30.0);
  CHECK(t.cheapest("cog", {.depth_median = 0.01, .depth_p99 = 0.02}).evals == 20.0);
  CHECK(t.cheapest("cog", {.depth_median = 0.05, .silhouette_false_hits = 0.01}).evals == 15.0);
  // The silhouette bound rules out the cheapest: fat silhouettes are an error too.
  CHECK(t.cheapest("cog", {.depth_median = 0.05, .silhouette_false_hits = 0.0}).evals == 20.0);
  CHECK(t.cheapest("cog", ErrorBudget::relaxed()).evals == 15.0);  // no bound: the cheapest of all
  CHECK(t.cheapest("cog", {}).evals == 20.0);  // the default budget: its 1% fat silhouette is too much
  CHECK(t.cheapest("torus", {}).knobs.threshold == 0.5f);
  // The normal's error is a budget too.
  CalibrationRow sharp = row("cog", 16.0, 0.02, 0.06, 0.0, "2");
  sharp.normal_p95 = 20.0;
  const Calibration with_normals("d", "1x1", {sharp, row("cog", 18.0, 0.02, 0.06, 0.0, "1")});
  CHECK(with_normals.cheapest("cog", {}).evals == 16.0);
  CHECK(with_normals.cheapest("cog", {.normal_p95 = 1.0}).evals == 18.0);
}

TEST_CASE("calibration - the default budget is what a 1080p picture cannot tell; relaxing names the bound") {
  const ErrorBudget b{};
  CHECK(b.depth_median == 0.1);
  CHECK(b.depth_p99 == 2.0);
  CHECK(b.silhouette_false_hits == 0.005);
  CHECK(b.false_misses == 0.005);
  CHECK(b.wrong_surface == 0.005);
  CalibrationRow r = row("cog", 10.0, 0.05, 1.0, 0.0, "1");
  CHECK(r.meets(b));
  r.wrong_surface = 0.01;  // 1% of the hits on a surface behind the true one
  CHECK_FALSE(r.meets(b));
  CHECK(r.excess(b) == doctest::Approx(2.0));
  CHECK(r.meets({.wrong_surface = 0.02}));
  r.wrong_surface = std::numeric_limits<double>::quiet_NaN();  // not measured: meets no bound but an open one
  CHECK_FALSE(r.meets(b));
  CHECK(r.meets({.wrong_surface = 1.0}));
  CHECK(r.meets(ErrorBudget::relaxed()));
}

TEST_CASE("calibration - a format-3 table reads with the probe it was measured with, 2; format 4 keeps it") {
  std::istringstream in(in_format("3"));
  const Calibration three = Calibration::parse(in, "three.csv");
  REQUIRE(three.rows().size() == 5);
  CHECK(three.rows()[0].knobs.probe == 2.0f);
  CHECK(three.rows()[0].false_misses == 0.0);
  CHECK(three.cheapest("cog", {}).evals == 20.0);
  // Format 4 writes the knob and reads it back; a row of format 4 without it is refused by count.
  Calibration deep = table();
  CalibrationRow r = deep.rows()[0];
  r.knobs.probe = 4.0f;
  const Calibration four("d", "8x8", {r});
  std::istringstream in4(text_of(four));
  CHECK(Calibration::parse(in4, "four.csv").rows()[0].knobs.probe == 4.0f);
  std::istringstream short_row(std::regex_replace(text_of(four), std::regex(",4\n"), "\n"));
  CHECK_THROWS_WITH_AS(Calibration::parse(short_row, "short.csv"), doctest::Contains("has 23 fields, not 24"),
                       EnvironmentError);
}

TEST_CASE("calibration - a format-2 table reads with false misses unmeasured (they were per ray)") {
  std::istringstream in(in_format("2"));
  const Calibration two = Calibration::parse(in, "two.csv");
  REQUIRE(two.rows().size() == 5);
  CHECK(std::isnan(two.rows()[0].false_misses));
  CHECK(two.rows()[0].wrong_surface == 0.0);
  CHECK_THROWS_WITH_AS(two.cheapest("cog", {}), doctest::Contains("false misses not measured per hit (a format-1 or -2 table)"),
                       UsageError);
  CHECK(two.cheapest("cog", {.silhouette_false_hits = 0.01, .false_misses = 1.0}).evals == 15.0);
}

TEST_CASE("calibration - a format-1 table reads with wrong-surface unmeasured, CRLF lines too") {
  std::string text = in_format("1");
  text = std::regex_replace(text, std::regex("normal_p95_degrees,wrong_surface,"), "normal_p95_degrees,");
  text = std::regex_replace(text, std::regex(",0\\.5,0,lipschitz"), ",0.5,lipschitz");  // drop the column's values
  text = std::regex_replace(text, std::regex("\n"), "\r\n");
  std::istringstream in(text);
  const Calibration old = Calibration::parse(in, "old.csv");
  REQUIRE(old.rows().size() == 5);
  CHECK(std::isnan(old.rows()[0].wrong_surface));
  CHECK(old.rows()[0].evals == 30.0);
  CHECK(old.rows()[4].knobs.threshold == 0.5f);
  CHECK_THROWS_WITH_AS(old.cheapest("cog", {}), doctest::Contains("wrong surface not measured (a format-1 table)"),
                       UsageError);
  CHECK(old.cheapest("cog", {.silhouette_false_hits = 0.01, .false_misses = 1.0, .wrong_surface = 1.0}).evals == 15.0);
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
    CHECK_NOTHROW(t.cheapest(g, ErrorBudget{}));  // every default bound, wrong-surface included
  }
}

TEST_CASE("bad input: a NaN or negative budget bound is invalid, not unmeetable") {
  const Calibration t = table();
  ErrorBudget nan_median;
  nan_median.depth_median = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH_AS(t.cheapest("cog", nan_median),
                       doctest::Contains("Calibration::cheapest: the error budget's depth_median is nan; a bound is a "
                                         "number from 0 to infinity"),
                       UsageError);
  ErrorBudget negative;
  negative.silhouette_false_hits = -0.01;
  CHECK_THROWS_WITH_AS(t.cheapest("cog", negative),
                       doctest::Contains("silhouette_false_hits is -0.01; a bound is a number from 0 to 1 (a fraction)"),
                       UsageError);
  ErrorBudget degrees;
  degrees.normal_p95 = 360.0;
  CHECK_THROWS_WITH_AS(t.cheapest("cog", degrees), doctest::Contains("normal_p95 is 360; a bound is a number from 0 to 180"),
                       UsageError);
  CHECK_NOTHROW(t.cheapest("cog", ErrorBudget::relaxed()));  // infinite depth bounds are open, not invalid
}

TEST_CASE("bad input: an empty calibration table says it is empty") {
  const Calibration empty("test device", "64x64", {});
  CHECK_THROWS_WITH_AS(empty.cheapest("cog", {}),
                       doctest::Contains("no rows for 'cog': the table is empty; calibrate it"), UsageError);
}
