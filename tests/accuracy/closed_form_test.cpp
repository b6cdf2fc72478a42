// Tests for proceduray/accuracy/closed_form.hpp: ray/sphere and ray/box in double, checked
// against answers known without it: exact cases, long double, and a textbook slab test.
#include "proceduray/accuracy/closed_form.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace proceduray;
using namespace proceduray::accuracy;

namespace {

using LVec = glm::vec<3, long double>;

/// Near sphere root in long double by the same geometry (closest point of the line, then back
/// along the ray by the half chord): the 11 extra bits make it the reference for double.
long double long_double_entry(glm::dvec3 origin, glm::dvec3 dir, glm::dvec3 centre, double radius) {
  const LVec f = LVec(origin) - LVec(centre), d = LVec(dir);
  const long double a = glm::dot(d, d), b = glm::dot(f, d);
  const LVec closest = f - (b / a) * d;
  const long double disc = a * ((long double)radius * radius - glm::dot(closest, closest));
  return (-b - std::sqrt(disc)) / a;
}

/// The textbook quadratic in double, b^2 - a c: what the closed form must beat far away.
double naive_entry(glm::dvec3 origin, glm::dvec3 dir, glm::dvec3 centre, double radius) {
  const glm::dvec3 f = origin - centre;
  const double a = glm::dot(dir, dir), b = glm::dot(f, dir), c = glm::dot(f, f) - radius * radius;
  return (-b - std::sqrt(b * b - a * c)) / a;
}

/// A plain slab test leaning on IEEE inf: fine in double on the CPU for non-zero components.
double textbook_box_entry(glm::dvec3 o, glm::dvec3 d, glm::dvec3 lo, glm::dvec3 hi, bool& hit) {
  const glm::dvec3 inv = 1.0 / d, t1 = (lo - o) * inv, t2 = (hi - o) * inv;
  const glm::dvec3 tmin = glm::min(t1, t2), tmax = glm::max(t1, t2);
  const double near = std::max({tmin.x, tmin.y, tmin.z}), far = std::min({tmax.x, tmax.y, tmax.z});
  hit = near <= far && near >= 0.0;
  return near;
}

bool close(glm::dvec3 a, glm::dvec3 b, double tol) { return glm::length(a - b) <= tol; }

}  // namespace

TEST_CASE("closed form sphere entry matches an exact case") {
  // Impact parameter 3 on a radius-5 sphere: the chord's half is 4, so t = 10 - 4 exactly.
  const Result r = intersect_sphere({0, 3, -10}, {0, 0, 1}, glm::dvec3(0.0), 5.0, 0.0, 100.0);
  REQUIRE(r.outcome == Outcome::hit);
  CHECK(r.t == 6.0);
  CHECK(close(r.normal, {0.0, 0.6, -0.8}, 1e-15));
  CHECK_FALSE(r.starts_inside);
  // A direction of length 2 halves t; the point and normal stay.
  const Result s = intersect_sphere({0, 3, -10}, {0, 0, 2}, glm::dvec3(0.0), 5.0, 0.0, 100.0);
  CHECK(s.t == 3.0);
  CHECK(close(s.normal, r.normal, 1e-15));
  // Ranges that end before the entry or start after the exit miss.
  CHECK(intersect_sphere({0, 3, -10}, {0, 0, 1}, glm::dvec3(0.0), 5.0, 0.0, 5.99).outcome == Outcome::miss);
  CHECK(intersect_sphere({0, 3, -10}, {0, 0, 1}, glm::dvec3(0.0), 5.0, 14.01, 100.0).outcome == Outcome::miss);
}

TEST_CASE("closed form sphere from inside returns the exit") {
  const Result r = intersect_sphere({1, 2, 3}, {0, -1, 0}, {1, 2, 3}, 2.0, 0.0, 10.0);
  REQUIRE(r.outcome == Outcome::hit);
  CHECK(r.starts_inside);
  CHECK(r.t == 2.0);
  CHECK(close(r.normal, {0, -1, 0}, 1e-15));
  // The same ray with t_lo past the entry of a sphere ahead: inside at t_lo, so the exit at 14.
  const Result s = intersect_sphere({0, 3, -10}, {0, 0, 1}, glm::dvec3(0.0), 5.0, 7.0, 100.0);
  REQUIRE(s.outcome == Outcome::hit);
  CHECK(s.starts_inside);
  CHECK(s.t == 14.0);
  CHECK(close(s.normal, {0.0, 0.6, 0.8}, 1e-15));
}

TEST_CASE("closed form sphere far away keeps relative t error below 1e-12") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double worst = 0.0, worst_naive = 0.0;
  for (double distance = 1.0; distance <= 1.0e6; distance *= 10.0) {
    for (int i = 0; i < 200; ++i) {
      const glm::dvec3 centre(u(rng), u(rng), u(rng));
      const glm::dvec3 away = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)));
      const glm::dvec3 origin = centre + (distance + 1.5) * away;
      // Aim at a point within 0.87 of the radius of the centre: every ray hits.
      const glm::dvec3 target = centre + 0.5 * glm::dvec3(u(rng), u(rng), u(rng));
      const glm::dvec3 dir = glm::normalize(target - origin);
      const Result r = intersect_sphere(origin, dir, centre, 1.0, 0.0, 1.0e7);
      REQUIRE(r.outcome == Outcome::hit);
      const long double ref = long_double_entry(origin, dir, centre, 1.0);
      worst = std::max(worst, double(std::abs((r.t - ref) / ref)));
      worst_naive = std::max(worst_naive, double(std::abs((naive_entry(origin, dir, centre, 1.0) - ref) / ref)));
      // The normal is the unit vector from the centre to the hit point (itself good to ~1e-16 |origin|).
      const LVec p = LVec(origin) + (long double)r.t * LVec(dir) - LVec(centre);
      CHECK(glm::length(glm::dvec3(p) - r.normal) <= 1e-15 * (distance + 2.0) + 1e-15);
    }
  }
  MESSAGE("worst relative t error at distances 1..1e6: closed form " << worst << ", textbook b^2 - ac " << worst_naive);
  CHECK(worst < 1e-12);        // seen: ~1e-16
  CHECK(worst_naive > 1e-12);  // the textbook form loses it at 1e6: the test can tell them apart
}

TEST_CASE("closed form sphere grazing rays fall on the right side") {
  // Impact parameter r (1 +- delta) along an oblique ray (so the closest point is not exact).
  const glm::dvec3 centre(0.25, -0.5, 2.0), dir = glm::normalize(glm::dvec3(1.0, 2.0, 2.0));
  const glm::dvec3 side = glm::normalize(glm::cross(dir, glm::dvec3(0.0, 0.0, 1.0)));
  const double radius = 1.5;
  for (double delta = 1e-1; delta >= 0.99e-9; delta /= 10.0) {
    CAPTURE(delta);
    for (const double sign : {1.0, -1.0}) {
      const glm::dvec3 origin = centre + radius * (1.0 + sign * delta) * side - 10.0 * dir;
      const Result r = intersect_sphere(origin, dir, centre, radius, 0.0, 100.0);
      CHECK(r.outcome == (sign > 0.0 ? Outcome::miss : Outcome::hit));
      CHECK(std::isfinite(r.t));
      if (r.outcome == Outcome::hit) {
        // Near a graze t is ill-conditioned: an error e in the closest point (~1e-16 |origin -
        // centre|, from rounding alone) moves it by e r / half chord, r sqrt(2 delta - delta^2).
        const double half_chord = radius * std::sqrt(2.0 * delta - delta * delta);
        const double ref = double(long_double_entry(origin, dir, centre, radius));
        CHECK(std::abs(r.t - ref) <= 1e-14 * 10.0 * radius / half_chord);
        CHECK(std::abs(r.t - (10.0 - half_chord)) <= 1e-9);  // the geometry, up to the origin's rounding
        CHECK(std::abs(glm::length(r.normal) - 1.0) <= 1e-15);
      }
    }
  }
}

TEST_CASE("closed form box entry with its face normal") {
  const Result r = intersect_box({-5.0, 0.2, 0.3}, {1.0, 0.1, 0.0}, glm::dvec3(-1.0), glm::dvec3(1.0), 0.0, 100.0);
  REQUIRE(r.outcome == Outcome::hit);
  CHECK(r.t == 4.0);
  CHECK(r.normal == glm::dvec3(-1.0, 0.0, 0.0));
  // Leaving through +y at t = 8 from inside: the exit with its outward normal.
  const Result s = intersect_box({0.0, 0.2, 0.3}, {0.1, 0.1, 0.0}, glm::dvec3(-1.0), glm::dvec3(1.0), 0.0, 100.0);
  REQUIRE(s.outcome == Outcome::hit);
  CHECK(s.starts_inside);
  CHECK(s.t == doctest::Approx(8.0).epsilon(1e-15));
  CHECK(s.normal == glm::dvec3(0.0, 1.0, 0.0));
  // A ray passing beside the box, and one whose range ends before it.
  const glm::dvec3 lo(-1.0), hi(1.0);
  CHECK(intersect_box({-5.0, 1.5, 0.0}, {1.0, 0.0, 0.0}, lo, hi, 0.0, 100.0).outcome == Outcome::miss);
  CHECK(intersect_box({-5.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, lo, hi, 0.0, 3.9).outcome == Outcome::miss);
}

TEST_CASE("closed form box with zero and negative zero direction components") {
  const glm::dvec3 lo(-1.0), hi(1.0);
  for (const double zero : {0.0, -0.0}) {
    CAPTURE(std::signbit(zero));
    const Result r = intersect_box({0.5, 0.5, -5.0}, {zero, zero, 1.0}, lo, hi, 0.0, 100.0);
    REQUIRE(r.outcome == Outcome::hit);
    CHECK(r.t == 4.0);
    CHECK(r.normal == glm::dvec3(0.0, 0.0, -1.0));
    // Parallel to the y slab and outside it: no t can enter.
    CHECK(intersect_box({0.5, 2.0, -5.0}, {zero, zero, 1.0}, lo, hi, 0.0, 100.0).outcome == Outcome::miss);
    // Along the x = -1 face (on the slab plane, parallel to it): the closed box is hit at z = -1.
    const Result face = intersect_box({-1.0, 0.0, -5.0}, {zero, 0.0, 1.0}, lo, hi, 0.0, 100.0);
    REQUIRE(face.outcome == Outcome::hit);
    CHECK(face.t == 4.0);
    // Backwards along z with a -0 elsewhere: the normal's sign follows the non-zero component.
    const Result back = intersect_box({0.0, 0.0, 5.0}, {zero, zero, -2.0}, lo, hi, 0.0, 100.0);
    REQUIRE(back.outcome == Outcome::hit);
    CHECK(back.t == 2.0);
    CHECK(back.normal == glm::dvec3(0.0, 0.0, 1.0));
  }
}

TEST_CASE("closed form box origin on a slab plane") {
  const glm::dvec3 lo(-1.0), hi(1.0);
  // On the x = -1 plane heading in: the entry is the origin itself, t = +0.
  const Result in = intersect_box({-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, lo, hi, 0.0, 100.0);
  REQUIRE(in.outcome == Outcome::hit);
  CHECK(in.t == 0.0);
  CHECK_FALSE(std::signbit(in.t));
  CHECK(in.normal == glm::dvec3(-1.0, 0.0, 0.0));
  CHECK_FALSE(in.starts_inside);
  // Heading out through that plane: the boundary point at t = 0 is the exit; -0 reads as +0.
  const Result out = intersect_box({-1.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}, lo, hi, 0.0, 100.0);
  REQUIRE(out.outcome == Outcome::hit);
  CHECK(out.t == 0.0);
  CHECK_FALSE(std::signbit(out.t));
  CHECK(out.normal == glm::dvec3(-1.0, 0.0, 0.0));
  // Same, with t_lo just past the origin: nothing of the box is ahead.
  CHECK(intersect_box({-1.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}, lo, hi, 1e-12, 100.0).outcome == Outcome::miss);
}

TEST_CASE("closed form box with denormal direction components stays finite") {
  const double tiny = std::numeric_limits<double>::denorm_min();
  const glm::dvec3 lo(-1.0), hi(1.0);
  // 1 / tiny overflows: the planes of y and z are known to be beyond the range without it.
  const Result r = intersect_box({-5.0, 0.5, -0.5}, {1.0, tiny, -tiny}, lo, hi, 0.0, 1.0e300);
  REQUIRE(r.outcome == Outcome::hit);
  CHECK(r.t == 4.0);
  CHECK(r.normal == glm::dvec3(-1.0, 0.0, 0.0));
  CHECK(intersect_box({-5.0, 1.5, 0.0}, {1.0, tiny, 0.0}, lo, hi, 0.0, 1.0e300).outcome == Outcome::miss);
  const Result up = intersect_box({0.0, -5.0, 0.0}, {tiny, 1.0, -tiny}, lo, hi, 0.0, 1.0e300);
  REQUIRE(up.outcome == Outcome::hit);
  CHECK(up.t == 4.0);
  CHECK(up.normal == glm::dvec3(0.0, -1.0, 0.0));
  // Inside, leaving through the only plane in range.
  const Result inside = intersect_box({0.0, 0.0, 0.0}, {tiny, -2.0, 0.0}, lo, hi, 0.0, 1.0e300);
  REQUIRE(inside.outcome == Outcome::hit);
  CHECK(inside.starts_inside);
  CHECK(inside.t == 0.5);
  CHECK(inside.normal == glm::dvec3(0.0, -1.0, 0.0));
  // A direction of denormals alone cannot be squared in double: refused, not guessed.
  CHECK_THROWS_WITH_AS(intersect_box({0.0, -5.0, 0.0}, {0.0, tiny, 0.0}, lo, hi, 0.0, 1.0),
                       doctest::Contains("normalise it"), UsageError);
}

TEST_CASE("closed form box agrees with a textbook slab test on random rays") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  int hits = 0, misses = 0;
  for (int i = 0; i < 2000; ++i) {
    const glm::dvec3 lo(u(rng) * 0.3 - 0.5, u(rng) * 0.3 - 0.5, u(rng) * 0.3 - 0.5), hi = lo + glm::dvec3(0.2, 0.7, 1.1);
    // Aimed at the box grown by 40% of its size each way: most hit, some pass beside it.
    const glm::dvec3 aim(u(rng) * 0.23 + 0.5, u(rng) * 0.23 + 0.5, u(rng) * 0.23 + 0.5);
    const glm::dvec3 origin(u(rng), u(rng), u(rng)), dir = lo + aim * (hi - lo) - origin;
    if (glm::all(glm::greaterThanEqual(origin, lo)) && glm::all(glm::lessThanEqual(origin, hi))) continue;
    bool expect = false;
    const double t = textbook_box_entry(origin, dir, lo, hi, expect);
    const Result r = intersect_box(origin, dir, lo, hi, 0.0, 100.0);
    REQUIRE((r.outcome == Outcome::hit) == expect);
    if (!expect) {
      ++misses;
      continue;
    }
    ++hits;
    CHECK(std::abs(r.t - t) <= 1e-14 * std::max(1.0, t));  // divides where the textbook multiplies by 1 / d
    // The hit point lies on the face the normal names.
    const glm::dvec3 p = origin + r.t * dir;
    const int axis = r.normal.x != 0.0 ? 0 : (r.normal.y != 0.0 ? 1 : 2);
    CHECK(std::abs(p[axis] - (r.normal[axis] < 0.0 ? lo[axis] : hi[axis])) <= 1e-13);
  }
  CHECK(hits > 500);
  CHECK(misses > 100);
}

TEST_CASE("closed form bad inputs throw UsageError naming the call") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH_AS(intersect_sphere({nan, 0, 0}, {0, 0, 1}, glm::dvec3(0.0), 1.0, 0.0, 1.0),
                       doctest::Contains("intersect_sphere: origin (nan"), UsageError);
  CHECK_THROWS_WITH_AS(intersect_sphere({0, 0, -5}, glm::dvec3(0.0), glm::dvec3(0.0), 1.0, 0.0, 1.0),
                       doctest::Contains("intersect_sphere: direction (0, 0, 0) has zero length"), UsageError);
  CHECK_THROWS_WITH_AS(intersect_sphere({0, 0, -5}, {0, 0, 1}, glm::dvec3(0.0), 0.0, 0.0, 1.0),
                       doctest::Contains("intersect_sphere: radius = 0"), UsageError);
  CHECK_THROWS_WITH_AS(intersect_sphere({0, 0, -5}, {0, 0, 1}, glm::dvec3(0.0), 1.0, 2.0, 1.0),
                       doctest::Contains("intersect_sphere: t_lo = 2 > t_hi = 1"), UsageError);
  CHECK_THROWS_WITH_AS(intersect_box({0, 0, -5}, {0, 0, 1}, glm::dvec3(1.0), glm::dvec3(-1.0), 0.0, 1.0),
                       doctest::Contains("intersect_box: box [(1, 1, 1), (-1, -1, -1)]"), UsageError);
  const double inf = std::numeric_limits<double>::infinity();
  CHECK_THROWS_WITH_AS(intersect_box({0, 0, -5}, {0, 0, 1}, glm::dvec3(-1.0), glm::dvec3(1.0), 0.0, inf),
                       doctest::Contains("intersect_box: t range [0, inf]"), UsageError);
}
