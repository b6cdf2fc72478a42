// Tests for proceduray/accuracy/stratified.hpp: at stride 1 the stratified measurement is measure()
// itself; at stride 8 it traces a fraction of the pixels, the silhouette classes stay exact, the
// rates are estimated within their reported bounds, each pixel is traced once, and a stride of 0
// is refused.
#include <proceduray/accuracy/stratified.hpp>

#include <doctest/doctest.h>

#include <atomic>
#include <cstdint>
#include <vector>

namespace acc = proceduray::accuracy;

namespace {

constexpr std::uint32_t W = 320, H = 240;
const acc::Frame frame{.width = W, .height = H, .pixel_angle = 1.0e-3};

/// A disc of radius 90 px at (150, 120) at depth 10 + x / 100, and a background miss.
acc::Reference disc(std::uint32_t x, std::uint32_t y) {
  const double dx = x - 150.0, dy = y - 120.0;
  if (dx * dx + dy * dy > 90.0 * 90.0) return {.outcome = acc::Outcome::miss};
  return {.outcome = acc::Outcome::hit, .t = 10.0 + x / 100.0, .normal = {0.0, 0.0, 1.0}};
}

/// A method with known faults: it misses one interior pixel in 50 (a hash), lands 4 footprints
/// behind on one in 200 (a wrong surface), is 0.1 footprints off elsewhere, and hits a 1-pixel
/// ring outside the disc (silhouette false hits).
std::vector<acc::Sample> method() {
  std::vector<acc::Sample> s(std::size_t{W} * H);
  for (std::uint32_t y = 0; y < H; ++y) {
    for (std::uint32_t x = 0; x < W; ++x) {
      const acc::Reference r = disc(x, y);
      const std::size_t i = std::size_t{y} * W + x;
      const std::uint64_t hash = (i * 2654435761u) % 1000u;
      const double dx = x - 150.0, dy = y - 120.0, d2 = dx * dx + dy * dy;
      if (r.outcome != acc::Outcome::hit) {
        if (d2 <= 91.0 * 91.0) s[i] = {.hit = true, .t = 10.0 + x / 100.0, .normal = {0.0, 0.0, 1.0}, .steps = 9.0};
        continue;
      }
      if (hash < 20) continue;  // a miss
      const double footprints = hash < 25 ? 4.0 : 0.1;
      s[i] = {.hit = true, .t = r.t * (1.0 + footprints * frame.pixel_angle), .normal = {0.0, 0.0, 1.0}, .steps = 12.0};
    }
  }
  return s;
}

}  // namespace

TEST_CASE("stratified: at stride 1 every pixel is traced and the metrics are measure()'s") {
  const acc::StratifiedTruth t = acc::stratified_truth(frame, 1, 1, disc);
  CHECK(t.traced == frame.pixels());
  const std::vector<acc::Sample> s = method();
  const acc::Metrics a = acc::measure_stratified(frame, s, t), b = acc::measure(frame, s, t.pixels);
  for (std::size_t c = 0; c < 4; ++c) {
    CHECK(a.classes[c].rays == b.classes[c].rays);
    CHECK(a.classes[c].false_misses == b.classes[c].false_misses);
    CHECK(a.classes[c].false_hits == b.classes[c].false_hits);
  }
  CHECK(a.all.depth.median == b.all.depth.median);
  CHECK(a.all.depth.p99 == b.all.depth.p99);
  CHECK(a.all.wrong_surface == b.all.wrong_surface);
  const acc::SampleConfidence c = acc::confidence(frame, s, t);
  CHECK(c.false_miss_rate == doctest::Approx(b.all.false_misses / double(b.all.both_hit + b.all.false_misses)));
  CHECK(c.false_miss_rate_95 == c.false_miss_rate);
  CHECK(c.wrong_surface_rate == doctest::Approx(b.all.wrong_surface_rate()));
}

TEST_CASE("stratified: at stride 8 a fraction is traced, silhouettes exactly, the rates within their bounds") {
  std::atomic<std::size_t> calls{0};
  const acc::StratifiedTruth t = acc::stratified_truth(frame, 8, 7, [&](std::uint32_t x, std::uint32_t y) {
    ++calls;
    return disc(x, y);
  });
  CHECK(calls.load() == t.traced);  // each pixel once
  CHECK(t.traced < frame.pixels() * 35 / 100);
  CHECK(t.band > 0);
  CHECK(t.sampled > 0);
  const std::vector<acc::Sample> s = method();
  const acc::StratifiedTruth full = acc::stratified_truth(frame, 1, 1, disc);
  const acc::Metrics est = acc::measure_stratified(frame, s, t), exact = acc::measure(frame, s, full.pixels);
  // The band holds every silhouette pixel: those classes are exact.
  for (const acc::PixelClass c : {acc::PixelClass::silhouette_1px, acc::PixelClass::silhouette_2px}) {
    CAPTURE(acc::name(c));
    CHECK(est[c].rays == exact[c].rays);
    CHECK(est[c].false_hits == exact[c].false_hits);
    CHECK(est[c].false_misses == exact[c].false_misses);
  }
  // Elsewhere, estimates: counts near the frame's, the rates under their upper bounds.
  CHECK(double(est.all.rays) == doctest::Approx(double(exact.all.rays)).epsilon(0.05));
  const acc::SampleConfidence c = acc::confidence(frame, s, t);
  const double miss_rate = exact.all.false_misses / double(exact.all.both_hit + exact.all.false_misses);
  CAPTURE(miss_rate);
  CAPTURE(c.false_miss_rate);
  CAPTURE(c.false_miss_rate_95);
  CHECK(c.false_miss_rate == doctest::Approx(miss_rate).epsilon(0.3));
  CHECK(c.false_miss_rate_95 >= miss_rate);
  CHECK(c.false_miss_rate_95 > c.false_miss_rate);
  CHECK(c.wrong_surface_rate_95 >= exact.all.wrong_surface_rate());
  CHECK(est.all.depth.median == doctest::Approx(exact.all.depth.median).epsilon(0.01));
}

TEST_CASE("stratified: the sample follows the seed, and a stride of 0 is refused") {
  const acc::StratifiedTruth a = acc::stratified_truth(frame, 8, 1, disc), b = acc::stratified_truth(frame, 8, 1, disc),
                             c = acc::stratified_truth(frame, 8, 2, disc);
  CHECK(a.weight == b.weight);
  CHECK(a.weight != c.weight);
  CHECK_THROWS_WITH_AS(acc::stratified_truth(frame, 0, 1, disc),
                       doctest::Contains("stride is 0; give 1 (every pixel) or more"), proceduray::UsageError);
}
