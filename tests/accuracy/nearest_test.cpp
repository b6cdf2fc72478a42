// accuracy/nearest.hpp: one ray's ground truth over several objects' searches.
#include <proceduray/accuracy/nearest.hpp>

#include <doctest/doctest.h>

using namespace proceduray::accuracy;

TEST_CASE("nearest hit takes the smallest t over the objects and its normal") {
  NearestHit n;
  n.add({.outcome = Outcome::hit, .t = 5.0, .normal = {1, 0, 0}}, 3);
  n.add({.outcome = Outcome::miss}, 4);
  n.add({.outcome = Outcome::hit, .t = 2.0, .normal = {0, 1, 0}}, 7);
  const Reference r = n.reference();
  CHECK(r.outcome == Outcome::hit);
  CHECK(r.t == 2.0);
  CHECK(r.normal == glm::dvec3(0, 1, 0));
  CHECK(n.object(0) == 7);
}

TEST_CASE("nearest hit is undetermined when a search stopped undecided in front of it") {
  NearestHit n;
  n.add({.outcome = Outcome::hit, .t = 5.0}, 3);
  n.add({.outcome = Outcome::undetermined, .t = 4.0}, 4);
  CHECK(n.reference().outcome == Outcome::undetermined);
  CHECK(n.object(0) == 0);
  NearestHit behind;  // undecided only beyond the hit: the hit stands
  behind.add({.outcome = Outcome::undetermined, .t = 6.0}, 4);
  behind.add({.outcome = Outcome::hit, .t = 5.0}, 3);
  CHECK(behind.reference().outcome == Outcome::hit);
  CHECK(behind.object(0) == 3);
  NearestHit none;
  none.add({.outcome = Outcome::miss}, 1);
  CHECK(none.reference().outcome == Outcome::miss);
  CHECK(none.object(9) == 9);
}
