// Tests for proceduray/accuracy/evaluation_split.hpp: a square's hits, its 2-pixel ring of near
// misses and the rest of the frame, each with known evaluations; weights and undetermined
// truths; bad counts refused.
#include <proceduray/accuracy/evaluation_split.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace acc = proceduray::accuracy;

namespace {

constexpr std::uint32_t W = 20, H = 10;
const acc::Frame frame{.width = W, .height = H, .pixel_angle = 1.0e-3};

/// The truth: a 6 x 4 square of hits at x 5..10, y 3..6; every other pixel a miss.
std::vector<acc::Reference> square() {
  std::vector<acc::Reference> out(W * H);
  for (std::uint32_t y = 3; y <= 6; ++y) {
    for (std::uint32_t x = 5; x <= 10; ++x) out[y * W + x] = {.outcome = acc::Outcome::hit, .t = 5.0, .normal = {0, 0, 1}};
  }
  return out;
}

/// 10 evaluations for a hit, 30 within 2 pixels of the square (the near misses), 2 elsewhere.
std::vector<acc::Sample> marched() {
  std::vector<acc::Sample> out(W * H);
  for (std::uint32_t y = 0; y < H; ++y) {
    for (std::uint32_t x = 0; x < W; ++x) {
      const bool in = x >= 5 && x <= 10 && y >= 3 && y <= 6;
      const bool ring = x + 2 >= 5 && x <= 12 && y + 2 >= 3 && y <= 8;
      out[y * W + x].steps = in ? 10.0 : (ring ? 30.0 : 2.0);
    }
  }
  return out;
}

}  // namespace

TEST_CASE("split_evaluations: hits, near misses within 2 pixels and far misses, each with its evaluations") {
  const acc::EvaluationSplit s = acc::split_evaluations(frame, square(), marched());
  // Hits: 24 pixels; the ring 2 pixels wide around the 6 x 4 square: 10 x 8 - 24 = 56 (the frame
  // holds all of it); the rest: 200 - 80.
  CHECK(s.hit.rays == 24.0);
  CHECK(s.near_miss.rays == 56.0);
  CHECK(s.far_miss.rays == 120.0);
  CHECK(s.hit.per_ray() == 10.0);
  CHECK(s.near_miss.per_ray() == 30.0);
  CHECK(s.far_miss.per_ray() == 2.0);
  CHECK(s.evaluations() == 24.0 * 10 + 56.0 * 30 + 120.0 * 2);
  CHECK(s.share(s.near_miss) == doctest::Approx(1680.0 / 2160.0));
}

TEST_CASE("split_evaluations: weights count a pixel that many times, undetermined truths not at all") {
  std::vector<acc::Reference> truth = square();
  truth[0].outcome = acc::Outcome::undetermined;  // a far pixel
  std::vector<std::uint32_t> weights(W * H, 1);
  weights[1] = 0;                  // left out
  weights[3 * W + 5] = 4;          // a hit standing for 4
  const acc::EvaluationSplit s = acc::split_evaluations(frame, truth, marched(), weights);
  CHECK(s.hit.rays == 27.0);
  CHECK(s.hit.evaluations == 270.0);
  CHECK(s.far_miss.rays == 118.0);
  const acc::EvaluationSplit none = acc::split_evaluations(frame, std::vector<acc::Reference>(W * H), std::vector<acc::Sample>(W * H));
  CHECK(std::isnan(none.hit.per_ray()));
  CHECK(std::isnan(none.share(none.hit)));
}

TEST_CASE("split_evaluations: counts other than the frame's are refused, naming the call and the count") {
  CHECK_THROWS_WITH_AS(acc::split_evaluations(frame, square(), std::vector<acc::Sample>(3)),
                       doctest::Contains("accuracy::split_evaluations: samples has 3 elements for a 20x10 frame"),
                       proceduray::UsageError);
  CHECK_THROWS_WITH_AS(acc::split_evaluations(frame, square(), marched(), std::vector<std::uint32_t>(5, 1)),
                       doctest::Contains("weights has 5 elements"), proceduray::UsageError);
}

TEST_CASE("ray_classes: each pixel's class, unknown where the truth is undetermined or left out") {
  std::vector<acc::Reference> truth = square();
  truth[0].outcome = acc::Outcome::undetermined;
  std::vector<std::uint32_t> weights(W * H, 1);
  weights[W - 1] = 0;
  const std::vector<acc::RayClass> c = acc::ray_classes(frame, truth, weights);
  REQUIRE(c.size() == W * H);
  CHECK(c[0] == acc::RayClass::unknown);
  CHECK(c[W - 1] == acc::RayClass::unknown);
  CHECK(c[3 * W + 5] == acc::RayClass::hit);
  CHECK(c[3 * W + 3] == acc::RayClass::near_miss);  // 2 pixels left of the square
  CHECK(c[3 * W + 2] == acc::RayClass::far_miss);   // 3 pixels left
  CHECK(static_cast<int>(acc::RayClass::near_miss) == 2);  // the value the tool writes
  CHECK_THROWS_WITH_AS(acc::ray_classes(frame, truth, std::vector<std::uint32_t>(2, 1)),
                       doctest::Contains("accuracy::ray_classes: weights has 2 elements"), proceduray::UsageError);
}
