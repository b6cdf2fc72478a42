// Tests for proceduray/accuracy/{percentiles,metrics,report}.hpp: synthetic grids whose answers are known
// by construction (a square block of hits whose bands are counted by hand, a known t offset, one NaN).
#include "proceduray/accuracy/metrics.hpp"
#include "proceduray/accuracy/percentiles.hpp"
#include "proceduray/accuracy/report.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace proceduray;
using namespace proceduray::accuracy;

namespace {
constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();
constexpr double infinity = std::numeric_limits<double>::infinity();

Frame frame_of(std::uint32_t w, std::uint32_t h, double angle = 1e-3) {
  return Frame{.width = w, .height = h, .pixel_angle = angle, .pixel_angles = {}};
}

/// A w x h grid whose reference hits the square [lo, hi] x [lo, hi] at distance t, facing -z.
std::vector<Reference> block(std::uint32_t w, std::uint32_t h, std::uint32_t lo, std::uint32_t hi, double t = 10.0) {
  std::vector<Reference> refs(std::size_t{w} * h);
  for (std::uint32_t y = lo; y <= hi; ++y) {
    for (std::uint32_t x = lo; x <= hi; ++x) refs[y * w + x] = {Outcome::hit, t, {0.0, 0.0, -1.0}};
  }
  return refs;
}

/// A method that reproduces the reference exactly.
std::vector<Sample> perfect(const std::vector<Reference>& refs) {
  std::vector<Sample> out(refs.size());
  for (std::size_t i = 0; i < refs.size(); ++i) {
    const bool hit = refs[i].outcome == Outcome::hit;
    out[i] = {.hit = hit, .t = hit ? refs[i].t : 0.0, .normal = refs[i].normal, .steps = 1.0, .flags = 0};
  }
  return out;
}

std::size_t count(const std::vector<PixelClass>& classes, PixelClass c) {
  return static_cast<std::size_t>(std::count(classes.begin(), classes.end(), c));
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  for (std::size_t comma; (comma = line.find(',', start)) != std::string::npos; start = comma + 1) {
    fields.push_back(line.substr(start, comma - start));
  }
  fields.push_back(line.substr(start));
  return fields;
}

/// The field of the CSV row `row` under the header name `column`.
std::string csv_cell(const std::string& csv, std::size_t row, const std::string& column) {
  const auto lines = lines_of(csv);
  const auto header = fields_of(lines.at(0));
  const auto at = std::find(header.begin(), header.end(), column);
  REQUIRE(at != header.end());
  return fields_of(lines.at(row + 1)).at(static_cast<std::size_t>(at - header.begin()));
}
}  // namespace

TEST_CASE("nearest-rank percentiles of 1 to 100 are the rank itself") {
  std::vector<double> values(100);
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = static_cast<double>(i + 1);
  std::shuffle(values.begin(), values.end(), std::mt19937(7));  // the order of the input must not matter
  // The k-th smallest of 1..100 is k, so percentile p is ceil(p) (at least 1).
  for (double p : {0.0, 0.5, 1.0, 1.5, 7.0, 14.0, 50.0, 95.0, 99.0, 99.1, 100.0}) {  // 7, 14: p / 100 is inexact
    CHECK(percentile(values, p) == std::max(1.0, std::ceil(p)));
  }
  const Distribution d = summarize(values);
  CHECK(d.count == 100);
  CHECK(d.mean == doctest::Approx(50.5));
  CHECK(d.median == 50.0);
  CHECK(d.p95 == 95.0);
  CHECK(d.p99 == 99.0);
  CHECK(d.max == 100.0);
}

TEST_CASE("nearest-rank percentiles of few values take the lower middle and never interpolate") {
  const std::vector<double> four{0.5, 0.1, 2.0, 0.3};  // sorted: 0.1 0.3 0.5 2.0
  CHECK(percentile(four, 50.0) == 0.3);                // rank ceil(2.0) = 2
  CHECK(percentile(four, 50.1) == 0.5);                // rank ceil(2.004) = 3
  CHECK(percentile(four, 95.0) == 2.0);
  CHECK(percentile(four, 0.0) == 0.1);
  CHECK(nearest_rank(25.0, 4) == 1);
  CHECK(nearest_rank(26.0, 4) == 2);
  const std::vector<double> one{3.25};
  const Distribution d = summarize(one);
  CHECK((d.median == 3.25 && d.p95 == 3.25 && d.p99 == 3.25 && d.max == 3.25 && d.mean == 3.25));
}

TEST_CASE("an empty sample summarizes to count 0 and NaN fields") {
  const Distribution d = summarize(std::vector<double>{});
  CHECK(d.count == 0);
  CHECK((std::isnan(d.mean) && std::isnan(d.median) && std::isnan(d.p95) && std::isnan(d.p99) && std::isnan(d.max)));
}

TEST_CASE("percentiles reject an empty sample and NaN values and p outside 0 to 100") {
  const std::vector<double> ok{1.0, 2.0};
  CHECK_THROWS_WITH_AS(percentile(std::vector<double>{}, 50.0), doctest::Contains("accuracy::percentile: no values"),
                       UsageError);
  CHECK_THROWS_WITH_AS(percentile(ok, 101.0), doctest::Contains("accuracy::percentile: percentile 101"), UsageError);
  CHECK_THROWS_WITH_AS(percentile(ok, -1.0), doctest::Contains("outside [0, 100]"), UsageError);
  CHECK_THROWS_AS(percentile(ok, not_a_number), UsageError);
  CHECK_THROWS_WITH_AS(summarize(std::vector<double>{1.0, not_a_number}),
                       doctest::Contains("accuracy::summarize: value #1 of 2 is NaN"), UsageError);
}

TEST_CASE("classify puts a single hit pixel and its Chebyshev rings in the bands") {
  // 9x9, one hit at (4, 4): it and its 8 neighbours (diagonals too: Chebyshev) differ at distance 1,
  // the 16 pixels of the next ring at distance 2, the other 81 - 1 - 8 - 16 = 56 are far.
  std::vector<Reference> refs(81);
  refs[4 * 9 + 4] = {Outcome::hit, 1.0, {0, 0, 1}};
  const std::vector<PixelClass> c = classify(frame_of(9, 9), refs);
  CHECK(c[4 * 9 + 4] == PixelClass::silhouette_1px);
  CHECK(c[3 * 9 + 3] == PixelClass::silhouette_1px);  // diagonal neighbour
  CHECK(c[2 * 9 + 6] == PixelClass::silhouette_2px);
  CHECK(c[1 * 9 + 4] == PixelClass::far);
  CHECK(count(c, PixelClass::silhouette_1px) == 9);
  CHECK(count(c, PixelClass::silhouette_2px) == 16);
  CHECK(count(c, PixelClass::interior) == 0);
  CHECK(count(c, PixelClass::far) == 56);
}

TEST_CASE("classify counts the bands of a square block by hand") {
  // 12x12, hits in the 6x6 block [3, 8]^2. Hits: its border ring (36 - 16 = 20) is 1 px from a miss,
  // the next ring (16 - 4 = 12) 2 px, the centre 2x2 = 4 is interior. Misses: the ring around the block
  // ([2, 9]^2: 64 - 36 = 28) is 1 px away, the next ([1, 10]^2: 100 - 64 = 36) 2 px, the rest 44 far.
  const std::vector<PixelClass> c = classify(frame_of(12, 12), block(12, 12, 3, 8));
  CHECK(count(c, PixelClass::silhouette_1px) == 20 + 28);
  CHECK(count(c, PixelClass::silhouette_2px) == 12 + 36);
  CHECK(count(c, PixelClass::interior) == 4);
  CHECK(count(c, PixelClass::far) == 44);
  CHECK(c[5 * 12 + 5] == PixelClass::interior);
  CHECK(c[0] == PixelClass::far);
}

TEST_CASE("classify ignores pixels outside the image and treats undetermined as not hit") {
  std::vector<Reference> all_hit(7 * 7, Reference{Outcome::hit, 1.0, {0, 0, 1}});
  const std::vector<PixelClass> full = classify(frame_of(7, 7), all_hit);
  CHECK(count(full, PixelClass::interior) == 49);  // the image border is no silhouette
  CHECK(count(classify(frame_of(7, 7), std::vector<Reference>(49)), PixelClass::far) == 49);
  all_hit[3 * 7 + 3].outcome = Outcome::undetermined;  // a hole of doubt in the middle widens the band
  const std::vector<PixelClass> holed = classify(frame_of(7, 7), all_hit);
  CHECK(count(holed, PixelClass::silhouette_1px) == 9);
  CHECK(count(holed, PixelClass::silhouette_2px) == 16);
  CHECK(count(holed, PixelClass::interior) == 49 - 9 - 16);
}

TEST_CASE("a perfect method agrees everywhere with zero errors") {
  const std::vector<Reference> refs = block(12, 12, 3, 8);
  const Metrics m = measure(frame_of(12, 12), perfect(refs), refs);
  CHECK(m.all.rays == 144);
  CHECK(m.all.agree == 144);
  CHECK((m.all.false_hits == 0 && m.all.false_misses == 0));
  CHECK(m.all.agree_rate() == 1.0);
  CHECK(m.all.both_hit == 36);
  CHECK(m.all.depth.count == 36);
  CHECK(m.all.depth.max == 0.0);
  CHECK(m.all.normal_degrees.max == 0.0);
  CHECK(m[PixelClass::interior].rays == 4);
  CHECK(m[PixelClass::far].rays == 44);
  CHECK(m[PixelClass::far].both_hit == 0);
  CHECK(std::isnan(m[PixelClass::far].depth.median));  // no data, not zero
  std::size_t sum = 0;
  for (PixelClass c : pixel_classes) sum += m[c].rays;
  CHECK(sum == m.all.rays);
}

TEST_CASE("a known t offset gives a known error in pixel footprints") {
  // Footprint at t = 10 with 1e-3 rad per pixel: 0.01. An offset of 0.025 is 2.5 footprints.
  const std::vector<Reference> refs = block(12, 12, 3, 8, 10.0);
  std::vector<Sample> samples = perfect(refs);
  for (Sample& s : samples) s.t += s.hit ? -0.025 : 0.0;  // |t - t_ref|: the sign does not matter
  Frame frame = frame_of(12, 12, 1e-3);
  Metrics m = measure(frame, samples, refs);
  CHECK(m.all.depth.median == doctest::Approx(2.5));
  CHECK(m.all.depth.p99 == doctest::Approx(2.5));
  CHECK(m[PixelClass::interior].depth.max == doctest::Approx(2.5));
  // Per-pixel angles: twice the angle on the row y = 3 (6 hits, all on the block's border) halves their
  // error to 1.25; the other 30 hits stay at 2.5.
  frame.pixel_angles.assign(144, 1e-3);
  for (std::uint32_t x = 0; x < 12; ++x) frame.pixel_angles[3 * 12 + x] = 2e-3;
  m = measure(frame, samples, refs);
  CHECK(m.all.depth.max == doctest::Approx(2.5));
  CHECK(m.all.depth.mean == doctest::Approx((30 * 2.5 + 6 * 1.25) / 36));
  CHECK(m[PixelClass::silhouette_1px].depth.mean == doctest::Approx((14 * 2.5 + 6 * 1.25) / 20));
  CHECK(m[PixelClass::interior].depth.mean == doctest::Approx(2.5));
}

TEST_CASE("hits more than 2 footprints behind the truth count as wrong-surface, in front never") {
  // Footprint at t = 10: 0.01. Behind by 0.025 (2.5 footprints): wrong surface; by 0.015 (1.5)
  // and in front by 0.05 (5): depth errors only.
  const std::vector<Reference> refs = block(12, 12, 3, 8, 10.0);  // 36 hits
  std::vector<Sample> samples = perfect(refs);
  samples[3 * 12 + 3].t += 0.025;
  samples[3 * 12 + 4].t += 0.025;
  samples[5 * 12 + 5].t += 0.025;
  samples[5 * 12 + 6].t += 0.015;
  samples[6 * 12 + 6].t -= 0.05;
  samples[7 * 12 + 7].hit = false;  // a false miss: a truth hit the rate counts over
  const Metrics m = measure(frame_of(12, 12), samples, refs);
  CHECK(m.all.wrong_surface == 3);
  CHECK(m[PixelClass::silhouette_1px].wrong_surface == 2);
  CHECK(m[PixelClass::interior].wrong_surface == 1);
  CHECK(m.all.wrong_surface_rate() == doctest::Approx(3.0 / 36.0));
  CHECK(std::isnan(m[PixelClass::far].wrong_surface_rate()));  // no truth hits there
  std::ostringstream out;
  write_csv(out, m);
  CHECK(csv_cell(out.str(), 4, "wrong_surface") == "3");
}

TEST_CASE("false hits and false misses are counted in their classes") {
  // The method grows the block by one pixel (false hits on the 28-pixel ring, all in silhouette_1px)
  // and misses the 4 interior pixels (false misses, all interior).
  const std::vector<Reference> refs = block(12, 12, 3, 8);
  std::vector<Sample> samples = perfect(block(12, 12, 2, 9));
  for (std::uint32_t y = 5; y <= 6; ++y) {
    for (std::uint32_t x = 5; x <= 6; ++x) samples[y * 12 + x].hit = false;
  }
  const Metrics m = measure(frame_of(12, 12), samples, refs);
  const ClassStats& s1 = m[PixelClass::silhouette_1px];
  CHECK(s1.false_hits == 28);
  CHECK(s1.false_misses == 0);
  CHECK(s1.false_hit_rate() == doctest::Approx(28.0 / 48.0));
  CHECK(m[PixelClass::interior].false_misses == 4);
  CHECK(m[PixelClass::interior].false_miss_rate() == 1.0);
  CHECK(m[PixelClass::interior].both_hit == 0);
  CHECK(m[PixelClass::far].agree == 44);
  CHECK(m.all.agree == 144 - 28 - 4);
  CHECK(m.all.both_hit == 32);
}

TEST_CASE("one injected NaN is counted once and kept out of the distributions") {
  const std::vector<Reference> refs = block(12, 12, 3, 8);
  std::vector<Sample> samples = perfect(refs);
  samples[5 * 12 + 5].t = not_a_number;                        // interior hit with a NaN t
  const Metrics m = measure(frame_of(12, 12), samples, refs);
  CHECK(m.all.nonfinite == 1);
  CHECK(m[PixelClass::interior].nonfinite == 1);
  CHECK(m.all.depth.count == 35);                     // 36 both hit, one without a t
  CHECK(m.all.normal_degrees.count == 36);            // its normal is still fine
  CHECK(m.all.both_hit == 36);
  // Each other source of non-finite output, on a different ray: 4 rays in all.
  samples[3 * 12 + 3].normal.y = infinity;
  samples[0].flags = flags::nan_seen;                // a miss that saw a NaN
  samples[1].steps = not_a_number;
  samples[2].t = not_a_number;                                 // a miss's t is never read
  const Metrics more = measure(frame_of(12, 12), samples, refs);
  CHECK(more.all.nonfinite == 4);
  CHECK(more[PixelClass::far].nonfinite == 2);
  CHECK(more.all.normal_degrees.count == 35);
  CHECK(more.all.steps.count == 143);
}

TEST_CASE("normal errors are angles in degrees whatever the normals length") {
  std::vector<Reference> refs(4, Reference{Outcome::hit, 2.0, {1.0, 0.0, 0.0}});
  std::vector<Sample> samples(4, Sample{.hit = true, .t = 2.0, .normal = {}, .steps = 1.0, .flags = 0});
  const double a = 30.0 * std::numbers::pi / 180.0;
  samples[0].normal = 5.0 * glm::dvec3(std::cos(a), std::sin(a), 0.0);  // 30 degrees, not unit length
  const double tiny = 1e-7;                                              // radians: acos would lose it
  samples[1].normal = {std::cos(tiny), std::sin(tiny), 0.0};
  samples[2].normal = {0.0, 0.0, 0.0};                                   // points nowhere: 180
  samples[3].normal = {1.0, 0.0, 0.0};
  refs[3].normal = {0.0, 0.0, 0.0};                                      // no reference normal: left out
  const Metrics m = measure(frame_of(2, 2), samples, refs);
  CHECK(m.all.normal_degrees.count == 3);
  CHECK(m.all.normal_degrees.max == doctest::Approx(180.0));
  CHECK(m.all.normal_degrees.median == doctest::Approx(30.0));
  std::vector<Sample> one{samples[1]};
  std::vector<Reference> one_ref{refs[0]};
  CHECK(measure(frame_of(1, 1), one, one_ref).all.normal_degrees.max ==
        doctest::Approx(tiny * 180.0 / std::numbers::pi).epsilon(1e-6).scale(0.0));  // relative
}

TEST_CASE("steps exhausted marches and undetermined rays are counted") {
  // 10x10, every reference a miss (all far), steps 1..100 in pixel order.
  std::vector<Reference> refs(100);
  std::vector<Sample> samples(100);
  for (std::size_t i = 0; i < samples.size(); ++i) samples[i].steps = static_cast<double>(i + 1);
  for (std::size_t i : {7u, 8u, 9u}) samples[i].flags = flags::exhausted;
  samples[20].flags = flags::started_inside | flags::exhausted;
  Metrics m = measure(frame_of(10, 10), samples, refs);
  CHECK(m.all.steps.mean == doctest::Approx(50.5));
  CHECK(m.all.steps.median == 50.0);
  CHECK(m.all.steps.p99 == 99.0);
  CHECK(m.all.steps.max == 100.0);
  CHECK(m.all.exhausted == 4);
  CHECK(m.all.started_inside == 1);
  // Undetermined references: counted, and in no other statistic even when the method hits there.
  for (std::size_t i : {0u, 1u, 2u}) {
    refs[i].outcome = Outcome::undetermined;
    samples[i].hit = true;
  }
  refs[9].outcome = Outcome::undetermined;  // an exhausted ray: no longer counted as exhausted
  m = measure(frame_of(10, 10), samples, refs);
  CHECK(m.all.undetermined == 4);
  CHECK(m.all.rays == 96);
  CHECK(m.all.false_hits == 0);
  CHECK(m.all.exhausted == 3);
  CHECK(m.all.steps.count == 96);
}

TEST_CASE("measure rejects mismatched sizes and bad frames naming the call") {
  const std::vector<Reference> refs = block(4, 4, 1, 2);
  const std::vector<Sample> samples = perfect(refs);
  CHECK_THROWS_WITH_AS(measure(frame_of(4, 4), std::vector<Sample>(15), refs),
                       doctest::Contains("accuracy::measure: samples has 15 elements for a 4x4 frame"), UsageError);
  CHECK_THROWS_WITH_AS(measure(frame_of(4, 5), samples, refs), doctest::Contains("one per pixel (20)"), UsageError);
  CHECK_THROWS_WITH_AS(measure(frame_of(0, 4), samples, refs), doctest::Contains("frame is 0x4"), UsageError);
  CHECK_THROWS_WITH_AS(measure(frame_of(4, 4, 0.0), samples, refs),
                       doctest::Contains("accuracy::measure: pixel_angle 0 is not a positive finite angle"),
                       UsageError);
  CHECK_THROWS_AS(measure(frame_of(4, 4, -1e-3), samples, refs), UsageError);
  CHECK_THROWS_AS(measure(frame_of(4, 4, not_a_number), samples, refs), UsageError);
  CHECK_THROWS_AS(measure(frame_of(4, 4, infinity), samples, refs), UsageError);
  Frame per_pixel = frame_of(4, 4);
  per_pixel.pixel_angles.assign(15, 1e-3);
  CHECK_THROWS_WITH_AS(measure(per_pixel, samples, refs), doctest::Contains("pixel_angles has 15 values for 16 pixels"),
                       UsageError);
  per_pixel.pixel_angles.assign(16, 1e-3);
  per_pixel.pixel_angles[6] = not_a_number;
  CHECK_THROWS_WITH_AS(measure(per_pixel, samples, refs), doctest::Contains("pixel_angles[6]"), UsageError);
  CHECK_THROWS_WITH_AS(classify(frame_of(4, 4), std::vector<Reference>(3)),
                       doctest::Contains("accuracy::classify: references has 3 elements"), UsageError);
}

TEST_CASE("measure rejects a reference hit without a positive finite t or normal") {
  const std::vector<Sample> samples(16);
  for (double t : {-0.5, 0.0, infinity, not_a_number}) {
    std::vector<Reference> refs = block(4, 4, 1, 2);
    refs[2 * 4 + 1].t = t;
    CHECK_THROWS_WITH_AS(measure(frame_of(4, 4), samples, refs),
                         doctest::Contains("accuracy::measure: reference pixel #9 (x 1, y 2) is a hit at t"),
                         UsageError);
  }
  std::vector<Reference> refs = block(4, 4, 1, 2);
  refs[5].normal.x = not_a_number;
  CHECK_THROWS_WITH_AS(measure(frame_of(4, 4), samples, refs), doctest::Contains("fix the ground truth"), UsageError);
  refs[5] = {Outcome::miss, not_a_number, glm::dvec3(not_a_number)};  // a miss's t and normal are not read
  CHECK_NOTHROW(measure(frame_of(4, 4), samples, refs));
}

TEST_CASE("psnr of equal images is infinite and of a known difference is known") {
  const std::vector<float> a(12, 0.5f), b(12, 0.75f);  // every value off by 0.25: MSE 1/16, PSNR 10 log10(16)
  CHECK(psnr(a, a) == std::numeric_limits<double>::infinity());
  CHECK(psnr(a, b) == doctest::Approx(10.0 * std::log10(16.0)));
  CHECK(psnr(a, b, 2.0) == doctest::Approx(psnr(a, b) + 20.0 * std::log10(2.0)));
  std::vector<float> half = a;
  for (std::size_t i = 0; i < 6; ++i) half[i] = 0.75f;   // half the values off: MSE 1/32
  CHECK(psnr(a, half) == doctest::Approx(10.0 * std::log10(32.0)));
  std::vector<float> bad = a;
  bad[3] = std::numeric_limits<float>::quiet_NaN();
  CHECK(std::isnan(psnr(a, bad)));
}

TEST_CASE("psnr rejects images of other sizes and a bad peak") {
  const std::vector<float> a(12, 0.5f), b(11, 0.5f);
  CHECK_THROWS_WITH_AS(psnr(a, b), doctest::Contains("accuracy::psnr: images of 12 and 11 values"), UsageError);
  CHECK_THROWS_AS(psnr(std::vector<float>{}, std::vector<float>{}), UsageError);
  CHECK_THROWS_WITH_AS(psnr(a, a, 0.0), doctest::Contains("accuracy::psnr: peak 0"), UsageError);
  CHECK_THROWS_AS(psnr(a, a, infinity), UsageError);
}

TEST_CASE("csv has the stable header and one row per class then all") {
  const std::vector<Reference> refs = block(12, 12, 3, 8);
  const Metrics m = measure(frame_of(12, 12), perfect(refs), refs);
  std::ostringstream out;
  write_csv(out, m);
  const std::vector<std::string> lines = lines_of(out.str());
  // The header is a contract with the charting script: these names never change.
  CHECK(lines.at(0) == "class,rays,undetermined,agree,false_hits,false_misses,agree_rate,false_hit_rate,"
                       "false_miss_rate,both_hit,depth_px_median,depth_px_p95,depth_px_p99,depth_px_max,normal_rays,"
                       "normal_deg_median,normal_deg_p95,normal_deg_max,steps_mean,steps_median,steps_p99,steps_max,"
                       "nonfinite,exhausted,started_inside,wrong_surface,wrong_surface_rate");
  REQUIRE(lines.size() == 6);
  const std::size_t columns_count = fields_of(lines[0]).size();
  for (std::size_t r = 0; r < 4; ++r) {
    CHECK(fields_of(lines[r + 1]).size() == columns_count);
    CHECK(fields_of(lines[r + 1])[0] == name(pixel_classes[r]));
    CHECK(csv_cell(out.str(), r, "rays") == std::to_string(m[pixel_classes[r]].rays));
  }
  CHECK(fields_of(lines[5])[0] == "all");
  CHECK(csv_cell(out.str(), 4, "rays") == "144");
  CHECK(csv_cell(out.str(), 2, "agree_rate") == "1");
  CHECK(csv_cell(out.str(), 3, "depth_px_median").empty());  // far: no ray hit, no data
}

TEST_CASE("csv labels come first and are quoted and a clashing label name throws") {
  const Metrics m{};
  std::ostringstream out;
  write_csv(out, m, {{"method", "sphere, relaxed"}, {"max_steps", "128"}});
  write_csv_rows(out, m, {{"method", "say \"hi\""}, {"max_steps", "64"}});
  const std::vector<std::string> lines = lines_of(out.str());
  REQUIRE(lines.size() == 11);
  CHECK(lines[0].rfind("method,max_steps,class,rays,", 0) == 0);
  CHECK(lines[1].rfind("\"sphere, relaxed\",128,silhouette_1px,0,", 0) == 0);
  CHECK(lines[6].rfind("\"say \"\"hi\"\"\",64,silhouette_1px,", 0) == 0);
  CHECK_THROWS_WITH_AS(write_csv(out, m, {{"rays", "1"}}),
                       doctest::Contains("accuracy::write_csv_header: label #0 is named \"rays\""), UsageError);
  CHECK_THROWS_AS(write_csv_rows(out, m, {{"a", "1"}, {"a", "2"}}), UsageError);
  CHECK_THROWS_AS(write_csv_header(out, {{"class", "x"}}), UsageError);
  CHECK_THROWS_AS(write_csv_header(out, {{"", "x"}}), UsageError);
}

TEST_CASE("the text table is aligned and names every column and class") {
  const std::vector<Reference> refs = block(12, 12, 3, 8);
  const Metrics m = measure(frame_of(12, 12), perfect(refs), refs);
  std::ostringstream out;
  write_table(out, m);
  const std::vector<std::string> lines = lines_of(out.str());
  REQUIRE(lines.size() == columns().size() + 2);  // header, rule, a line per column
  for (const std::string& line : lines) CHECK(line.size() == lines[0].size());
  for (PixelClass c : pixel_classes) CHECK(lines[0].find(name(c)) != std::string::npos);
  CHECK(lines[0].find("all") != std::string::npos);
  for (std::size_t i = 0; i < columns().size(); ++i) {
    CHECK(lines[i + 2].rfind(std::string(columns()[i].name), 0) == 0);
  }
  CHECK(lines[2].find(" 144") != std::string::npos);  // rays, all
  const auto depth = std::find_if(lines.begin(), lines.end(), [](const std::string& l) {
    return l.rfind("depth_px_median", 0) == 0;
  });
  REQUIRE(depth != lines.end());
  CHECK(depth->find(" -") != std::string::npos);  // far has no depth data
}
