// Tests for proceduray/accuracy/ground_truth.hpp: the searchers against closed forms
// (closed_form.hpp, itself checked against exact and long-double answers), and the failure
// modes they exist to avoid: thin features, grazing rays, exhausted budgets.
#include "proceduray/accuracy/ground_truth.hpp"

#include "proceduray/accuracy/closed_form.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace proceduray;
using namespace proceduray::accuracy;

namespace {

/// Exact distance to a sphere: Lipschitz bound 1.
struct SphereDistance {
  glm::dvec3 centre;
  double radius;
  double operator()(glm::dvec3 p) const { return glm::length(p - centre) - radius; }
};

/// Exact distance to a box of half size b centred at the origin.
double box_distance(glm::dvec3 q, glm::dvec3 b) {
  const glm::dvec3 e = glm::abs(q) - b;
  return glm::length(glm::max(e, 0.0)) + std::min(std::max({e.x, e.y, e.z}), 0.0);
}

/// A box distance evaluated on scaled coordinates S (p - c): its surface is the box of half size
/// b / S around c, and its Lipschitz bound is the largest scale.
struct ScaledBox {
  glm::dvec3 centre, scale, half;
  double operator()(glm::dvec3 p) const { return box_distance(scale * (p - centre), half); }
  double lipschitz() const { return std::max({scale.x, scale.y, scale.z}); }
};

}  // namespace

TEST_CASE("ground truth lipschitz search on a sphere agrees with the closed form") {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const SphereDistance sphere{{0.2, -0.1, 0.3}, 0.8};
  double worst = 0.0, evaluations = 0.0;
  int inside = 0;
  for (int i = 0; i < 300; ++i) {
    // A third of the rays start inside (the exit is the answer), the rest 2..5 away.
    const bool from_inside = i % 3 == 0;
    const glm::dvec3 origin = sphere.centre + (from_inside ? 0.5 : 3.5) * glm::dvec3(u(rng), u(rng), u(rng));
    const glm::dvec3 dir = glm::normalize(sphere.centre + 0.7 * glm::dvec3(u(rng), u(rng), u(rng)) - origin);
    const Result exact = intersect_sphere(origin, dir, sphere.centre, sphere.radius, 0.0, 20.0);
    const Result r = lipschitz_search(sphere, 1.0, origin, dir, 0.0, 20.0, {.min_step = 1e-9});
    REQUIRE(r.outcome == exact.outcome);
    CHECK(r.starts_inside == exact.starts_inside);
    if (r.outcome != Outcome::hit) continue;
    inside += r.starts_inside;
    CHECK(r.bracket <= 1e-13 * r.t + 1e-300);
    worst = std::max(worst, std::abs(r.t - exact.t));
    evaluations += double(r.evaluations);
  }
  MESSAGE("sphere: worst |t - closed form| " << worst << ", evaluations per ray " << evaluations / 300.0);
  CHECK(worst <= 1e-12);
  CHECK(inside > 50);
}

TEST_CASE("ground truth lipschitz search on a scaled box agrees with the closed form") {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const ScaledBox box{{0.1, 0.2, -0.3}, {3.0, 1.0, 0.5}, {0.6, 0.4, 0.3}};
  const glm::dvec3 lo = box.centre - box.half / box.scale, hi = box.centre + box.half / box.scale;
  double worst = 0.0;
  int hits = 0;
  for (int i = 0; i < 300; ++i) {
    const glm::dvec3 origin = box.centre + 3.0 * glm::dvec3(u(rng), u(rng), u(rng));
    const glm::dvec3 dir = glm::normalize(box.centre + 0.8 * glm::dvec3(u(rng), u(rng), u(rng)) - origin);
    const Result exact = intersect_box(origin, dir, lo, hi, 0.0, 20.0);
    const Result r = lipschitz_search(box, box.lipschitz(), origin, dir, 0.0, 20.0, {.min_step = 1e-9});
    REQUIRE(r.outcome == exact.outcome);
    if (r.outcome != Outcome::hit) continue;
    ++hits;
    CHECK(r.starts_inside == exact.starts_inside);
    worst = std::max(worst, std::abs(r.t - exact.t));
  }
  MESSAGE("scaled box: worst |t - closed form| " << worst << " over " << hits << " hits");
  CHECK(worst <= 1e-12);
  CHECK(hits > 100);
}

TEST_CASE("ground truth lipschitz search needs the true bound to keep a thin scaled box") {
  // Scaled by 100 along x, the box is 2e-3 thick: steps of f / 1 jump straight through it.
  const ScaledBox plate{glm::dvec3(0.0), {100.0, 1.0, 1.0}, {0.1, 1.0, 1.0}};
  const glm::dvec3 origin(-5.0, 0.2, 0.1), dir(1.0, 0.0, 0.0);
  const Result wrong = lipschitz_search(plate, 1.0, origin, dir, 0.0, 10.0);
  CHECK(wrong.outcome == Outcome::miss);
  const Result right = lipschitz_search(plate, plate.lipschitz(), origin, dir, 0.0, 10.0);
  REQUIRE(right.outcome == Outcome::hit);
  CHECK(right.t == doctest::Approx(4.999).epsilon(1e-12));
}

TEST_CASE("ground truth predicate search on sphere membership agrees with the closed form") {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const glm::dvec3 centre(-0.2, 0.4, 0.1);
  const double radius = 0.9;
  auto ball = [&](glm::dvec3 p) { return glm::dot(p - centre, p - centre) <= radius * radius; };
  double worst = 0.0, worst_ratio = 0.0, evaluations = 0.0;
  for (int i = 0; i < 200; ++i) {
    const bool from_inside = i % 4 == 0;
    const glm::dvec3 origin = centre + (from_inside ? 0.5 : 3.5) * glm::dvec3(u(rng), u(rng), u(rng));
    const glm::dvec3 dir = glm::normalize(centre + 0.8 * glm::dvec3(u(rng), u(rng), u(rng)) - origin);
    const Result exact = intersect_sphere(origin, dir, centre, radius, 0.0, 20.0);
    const Result r = predicate_search(ball, origin, dir, 0.0, 20.0, 1e-2, {.tolerance = 1e-10});
    REQUIRE(r.outcome == exact.outcome);
    CHECK(r.starts_inside == exact.starts_inside);
    if (r.outcome != Outcome::hit) continue;
    CHECK(r.bracket <= 1e-10);
    worst = std::max(worst, std::abs(r.t - exact.t));
    worst_ratio = std::max(worst_ratio, std::abs(r.t - exact.t) / (0.5 * r.bracket));
    evaluations += double(r.evaluations);
  }
  MESSAGE("ball: worst |t - closed form| " << worst << " (" << worst_ratio << " half brackets), evaluations per ray "
                                           << evaluations / 200.0);
  CHECK(worst <= 0.5e-10 + 1e-15);  // the half bracket, plus the membership test's rounding
}

TEST_CASE("ground truth lipschitz search finds a slab that a coarser fixed step misses") {
  // A slab 1e-6 thick at x = 0.5005: samples every 1e-3 (at 0.500 and 0.501) step over it; the
  // bounded steps shrink towards it and find it, 1000 times thicker than min_step.
  const double centre = 0.5005005, half = 0.5e-6;
  auto slab = [&](glm::dvec3 p) { return std::abs(p.x - centre) - half; };
  const glm::dvec3 origin(0.0, 0.3, 0.2), dir(1.0, 0.0, 0.0);
  const Result coarse = predicate_search([&](glm::dvec3 p) { return slab(p) <= 0.0; }, origin, dir, 0.0, 1.0, 1e-3);
  CHECK(coarse.outcome == Outcome::miss);
  CHECK(coarse.evaluations == 1001);
  const Result fine = lipschitz_search(slab, 1.0, origin, dir, 0.0, 1.0, {.min_step = 1e-9});
  REQUIRE(fine.outcome == Outcome::hit);
  CHECK(std::abs(fine.t - (centre - half)) <= 1e-12);
  MESSAGE("thin slab: lipschitz_search took " << fine.evaluations << " evaluations");
  // From the far side the first crossing is the other face.
  const Result back = lipschitz_search(slab, 1.0, glm::dvec3(1.0, 0.3, 0.2), -dir, 0.0, 1.0, {.min_step = 1e-9});
  REQUIRE(back.outcome == Outcome::hit);
  CHECK(std::abs(back.t - (1.0 - centre - half)) <= 1e-12);
}

TEST_CASE("ground truth grazing sphere rays at one part in a billion fall on the right side") {
  const glm::dvec3 centre(0.25, -0.5, 2.0), dir = glm::normalize(glm::dvec3(1.0, 2.0, 2.0));
  const glm::dvec3 side = glm::normalize(glm::cross(dir, glm::dvec3(0.0, 0.0, 1.0)));
  const double radius = 1.5, delta = 1e-9;
  const SphereDistance sphere{centre, radius};
  auto ball = [&](glm::dvec3 p) { return glm::dot(p - centre, p - centre) <= radius * radius; };
  for (const double sign : {1.0, -1.0}) {
    CAPTURE(sign);
    const glm::dvec3 origin = centre + radius * (1.0 + sign * delta) * side - 10.0 * dir;
    const Result exact = intersect_sphere(origin, dir, centre, radius, 0.0, 20.0);
    const Result marched = lipschitz_search(sphere, 1.0, origin, dir, 0.0, 20.0, {.min_step = 1e-9});
    // Sampled only near the closest point (t = 10), at 1e-6: the chord there is 1.3e-4 long.
    const Result sampled = predicate_search(ball, origin, dir, 9.999, 10.001, 1e-6, {.tolerance = 1e-13});
    const Outcome expected = sign > 0.0 ? Outcome::miss : Outcome::hit;
    CHECK(exact.outcome == expected);
    CHECK(marched.outcome == expected);
    CHECK(sampled.outcome == expected);
    MESSAGE("impact r(1 " << (sign > 0.0 ? "+" : "-") << " 1e-9): lipschitz_search " << marched.evaluations
                          << " evaluations, predicate_search " << sampled.evaluations);
    if (expected != Outcome::hit) continue;
    // t is ill-conditioned here (see the closed-form test): rounding of 1e-16 in the distance
    // moves the root by 1e-16 r / (half chord 6.7e-5 r).
    const double half_chord = radius * std::sqrt(2.0 * delta);
    CHECK(std::abs(marched.t - exact.t) <= 1e-14 * 10.0 * radius / half_chord);
    CHECK(std::abs(sampled.t - exact.t) <= 1e-14 * 10.0 * radius / half_chord);
  }
}

TEST_CASE("ground truth exhausted budgets give undetermined and never a hit") {
  const SphereDistance sphere{glm::dvec3(0.0), 1.0};
  const glm::dvec3 origin(0.3, 0.0, -1000.0), dir(0.0, 0.0, 1.0);
  const double exact = intersect_sphere(origin, dir, sphere.centre, 1.0, 0.0, 2000.0).t;
  // Marching: five evaluations get nowhere near.
  const Result marched = lipschitz_search(sphere, 1.0, origin, dir, 0.0, 2000.0, {.budget = 5});
  CHECK(marched.outcome == Outcome::undetermined);
  CHECK(marched.evaluations == 5);
  CHECK(marched.t < exact);
  // A near-grazing ray piles its steps up at the silhouette: a budget that suffices head-on does not.
  const glm::dvec3 graze(1.0 + 1e-7, 0.0, -1000.0);
  CHECK(lipschitz_search(sphere, 1.0, graze, dir, 0.0, 2000.0, {.budget = 1000}).outcome == Outcome::undetermined);
  CHECK(lipschitz_search(sphere, 1.0, origin, dir, 0.0, 2000.0, {.budget = 1000}).outcome == Outcome::hit);
  // Sampling: 100 samples of 1e-3 cover 0.1 of the 1000 to go.
  auto ball = [](glm::dvec3 p) { return glm::dot(p, p) <= 1.0; };
  const glm::dvec3 near(0.3, 0.0, -2.0);
  const double near_exact = intersect_sphere(near, dir, glm::dvec3(0.0), 1.0, 0.0, 4.0).t;
  const Result sampled = predicate_search(ball, near, dir, 0.0, 4.0, 1e-3, {.budget = 100});
  CHECK(sampled.outcome == Outcome::undetermined);
  CHECK(sampled.evaluations == 100);
  // Budget enough to bracket (1 + 1047 samples) but not to bisect to 1e-13: undetermined, though
  // the bracket it stopped with still holds the crossing.
  const Result bracketed = predicate_search(ball, near, dir, 0.0, 4.0, 1e-3, {.budget = 1050});
  CHECK(bracketed.outcome == Outcome::undetermined);
  CHECK(bracketed.bracket > 1e-13);
  CHECK(std::abs(bracketed.t - near_exact) <= 0.5 * bracketed.bracket);
  const Result enough = predicate_search(ball, near, dir, 0.0, 4.0, 1e-3, {.budget = 2000});
  REQUIRE(enough.outcome == Outcome::hit);
  CHECK(enough.evaluations <= 2000);
  CHECK(std::abs(enough.t - near_exact) <= 1e-12);
}

TEST_CASE("ground truth searches report misses over the whole range") {
  const SphereDistance sphere{glm::dvec3(0.0), 1.0};
  const glm::dvec3 origin(1.5, 0.0, -3.0), dir(0.0, 0.0, 1.0);
  const Result marched = lipschitz_search(sphere, 1.0, origin, dir, 0.0, 6.0);
  CHECK(marched.outcome == Outcome::miss);
  CHECK(marched.t == 0.0);
  CHECK(marched.evaluations > 2);
  auto ball = [](glm::dvec3 p) { return glm::dot(p, p) <= 1.0; };
  const Result sampled = predicate_search(ball, origin, dir, 0.0, 6.0, 0.5);
  CHECK(sampled.outcome == Outcome::miss);
  CHECK(sampled.evaluations == 13);  // t = 0, 0.5, ..., 6: the end of the range is sampled too
  // A range that ends before the sphere is a miss too, and one of a single point is sampled once.
  CHECK(lipschitz_search(sphere, 1.0, {0, 0, -3}, dir, 0.0, 1.9).outcome == Outcome::miss);
  CHECK(predicate_search(ball, {0, 0, -3}, dir, 1.0, 1.0, 0.5).evaluations == 1);
}

TEST_CASE("ground truth gradient normal matches the closed-form normal for a good h") {
  const SphereDistance sphere{{0.1, 0.2, 0.3}, 1.0};
  const glm::dvec3 origin(2.0, 1.5, -3.0), dir = glm::normalize(glm::dvec3(-0.5, -0.3, 1.0));
  const Result exact = intersect_sphere(origin, dir, sphere.centre, 1.0, 0.0, 10.0);
  REQUIRE(exact.outcome == Outcome::hit);
  const glm::dvec3 p = origin + exact.t * dir;
  // |n - n_exact| is the angle for small angles, without acos's loss near 1.
  auto angle = [&](double h) { return glm::length(gradient_normal(sphere, p, h) - exact.normal); };
  const double coarse = angle(0.3), good = angle(1e-5), tiny = angle(1e-14);
  MESSAGE("gradient normal angle error: h = 0.3: " << coarse << ", h = 1e-5: " << good << ", h = 1e-14: " << tiny);
  CHECK(good <= 1e-9);
  CHECK(coarse > 10.0 * good);  // truncation: too large an h blurs
  CHECK(tiny > 10.0 * good);    // rounding: too small an h cancels
  // A field flat at this h gives no direction rather than a made-up one.
  CHECK(gradient_normal([](glm::dvec3) { return 1.0; }, p, 1e-3) == glm::dvec3(0.0));
}

TEST_CASE("ground truth bad inputs throw UsageError naming the call") {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const SphereDistance sphere{glm::dvec3(0.0), 1.0};
  auto ball = [](glm::dvec3 p) { return glm::dot(p, p) <= 1.0; };
  const glm::dvec3 o(0.0, 0.0, -3.0), d(0.0, 0.0, 1.0);
  CHECK_THROWS_WITH_AS(lipschitz_search(sphere, 1.0, {0, inf, 0}, d, 0.0, 6.0),
                       doctest::Contains("lipschitz_search: origin (0, inf, 0) is not finite"), UsageError);
  CHECK_THROWS_WITH_AS(lipschitz_search(sphere, 1.0, o, {nan, 0, 1}, 0.0, 6.0),
                       doctest::Contains("lipschitz_search: direction (nan, 0, 1) is not finite"), UsageError);
  CHECK_THROWS_WITH_AS(predicate_search(ball, o, glm::dvec3(0.0), 0.0, 6.0, 0.1),
                       doctest::Contains("predicate_search: direction (0, 0, 0) has zero length"), UsageError);
  CHECK_THROWS_WITH_AS(predicate_search(ball, o, d, 6.0, 0.0, 0.1),
                       doctest::Contains("predicate_search: t_lo = 6 > t_hi = 0; pass t_lo <= t_hi"), UsageError);
  CHECK_THROWS_WITH_AS(lipschitz_search(sphere, 0.0, o, d, 0.0, 6.0),
                       doctest::Contains("lipschitz_search: the Lipschitz bound L = 0 is not a positive"), UsageError);
  CHECK_THROWS_WITH_AS(lipschitz_search(sphere, -2.0, o, d, 0.0, 6.0), doctest::Contains("L = -2"), UsageError);
  CHECK_THROWS_WITH_AS(lipschitz_search(sphere, 1e-300, o, 1e-10 * d, 0.0, 6.0),
                       doctest::Contains("lipschitz_search: L * |dir| = 1e-300 * 1e-10 is out of range"), UsageError);
  CHECK_THROWS_WITH_AS(lipschitz_search(sphere, 1.0, o, d, 0.0, 6.0, {.min_step = 0.0}),
                       doctest::Contains("lipschitz_search: options.min_step = 0"), UsageError);
  CHECK_THROWS_WITH_AS(predicate_search(ball, o, d, 0.0, 6.0, -0.1),
                       doctest::Contains("predicate_search: spacing = -0.1 is not a positive finite number"), UsageError);
  CHECK_THROWS_WITH_AS(predicate_search(ball, o, d, 0.0, 6.0, 0.1, {.budget = 0}),
                       doctest::Contains("predicate_search: options.budget = 0"), UsageError);
  CHECK_THROWS_WITH_AS(predicate_search(ball, o, d, 0.0, 6.0, 0.1, {.tolerance = nan}),
                       doctest::Contains("predicate_search: options.tolerance = nan"), UsageError);
  CHECK_THROWS_WITH_AS(lipschitz_search([](glm::dvec3 p) { return std::sqrt(p.z); }, 1.0, o, d, 0.0, 6.0),
                       doctest::Contains("lipschitz_search: the distance function returned NaN at t = 0"), UsageError);
  CHECK_THROWS_WITH_AS(gradient_normal(sphere, o, 0.0), doctest::Contains("gradient_normal: h = 0"), UsageError);
  CHECK_THROWS_WITH_AS(gradient_normal([](glm::dvec3 p) { return std::log(p.x); }, glm::dvec3(0.0), 1e-3),
                       doctest::Contains("gradient_normal: the differences at p = (0, 0, 0) are not finite"), UsageError);
}
