// Tests for proceduray/accuracy/field_truth.hpp: a user's GLSL field compiled as C++ in double
// gives the closed form's hits (a ball, a box) to 1e-9; a bound below the field's slope, NaN
// inside the box and bad boxes are refused with the point, the value and the fix.
#include "proceduray/accuracy/field_truth.hpp"

#include "proceduray/accuracy/closed_form.hpp"
#include "proceduray/shader/glsl_cpp.hpp"
#include "test_fields.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace field_truth_test {
using namespace proceduray::glsl_cpp;
template <class T>
struct sdf {
  PROCEDURAY_GLSL_CPP_SCALAR(T)
#include "primitives/sdf.glsl"
};
}  // namespace field_truth_test

namespace acc = proceduray::accuracy;
using namespace field_truth_test;

namespace {

const acc::FieldBounds unit{.name = "ball", .min = glm::dvec3(-1.25), .max = glm::dvec3(1.25), .lipschitz = 1.0};

/// Random rays from a shell around the box towards points near the origin (some miss).
struct Rays {
  std::mt19937_64 rng{29};
  std::uniform_real_distribution<double> u{-1.0, 1.0};
  glm::dvec3 origin() {
    glm::dvec3 o(u(rng), u(rng), u(rng));
    return 4.0 * glm::normalize(o + glm::dvec3(1e-9));
  }
  glm::dvec3 towards(glm::dvec3 o) { return glm::dvec3(1.4 * u(rng), 1.4 * u(rng), 1.4 * u(rng)) - o; }
};

std::string refusal(auto&& f) {
  try {
    f();
  } catch (const proceduray::UsageError& e) {
    return e.what();
  }
  return {};
}

}  // namespace

TEST_CASE("field truth: a ball and a box declared as fields give the closed forms' hits to 1e-9") {
  auto ball_d = [](glm::dvec3 p) { return test_fields::ball_cpu(p); };
  const glm::dvec3 half(0.7, 0.4, 0.9);
  auto box_d = [&](glm::dvec3 p) { return sdf<double>::sdf_box(p, half); };
  const acc::FieldBounds box_bounds{.name = "box", .min = -half - 0.1, .max = half + 0.1, .lipschitz = 1.0};
  Rays rays;
  int hits = 0, misses = 0;
  for (int i = 0; i < 2000; ++i) {
    const glm::dvec3 o = rays.origin(), d = rays.towards(o);
    const acc::Result truth[2] = {acc::field_hit(ball_d, unit, o, d, 0.0, 10.0),
                                  acc::field_hit(box_d, box_bounds, o, d, 0.0, 10.0)};
    const acc::Result closed[2] = {acc::intersect_sphere(o, d, glm::dvec3(0.0), 1.0, 0.0, 10.0),
                                   acc::intersect_box(o, d, -half, half, 0.0, 10.0)};
    for (int k = 0; k < 2; ++k) {
      CAPTURE(i);
      CAPTURE(k);
      REQUIRE(truth[k].outcome == closed[k].outcome);
      if (closed[k].outcome != acc::Outcome::hit) {
        ++misses;
        continue;
      }
      ++hits;
      CHECK(std::abs(truth[k].t - closed[k].t) <= 1e-9 * glm::length(d) + 1e-12);
    }
  }
  CHECK(hits > 800);  // both outcomes well represented
  CHECK(misses > 800);
}

TEST_CASE("field truth: the declared bound is checked by sampling; too small a bound names the slope") {
  auto gyroid_d = [](glm::dvec3 p) { return test_fields::gyroid_cpu(p); };
  acc::FieldBounds g{.name = "gyroid", .min = glm::dvec3(-1.0), .max = glm::dvec3(1.0), .lipschitz = 1.75};
  const acc::FieldScan scan = acc::scan_field(gyroid_d, g, "test");
  CHECK(scan.max_slope > 1.5);   // the gyroid term's sqrt(3) is nearly reached on the grid
  CHECK(scan.max_slope <= 1.75);
  CHECK(scan.points == 24u * 24u * 24u);
  g.lipschitz = 1.0;  // what plain sphere tracing assumes
  const std::string m = refusal([&] { acc::scan_field(gyroid_d, g, "calibrate"); });
  CHECK(m.find("calibrate: field 'gyroid' has slope 1.") != std::string::npos);
  CHECK(m.find("above its declared Lipschitz bound 1") != std::string::npos);
  CHECK(m.find("declare a bound of at least") != std::string::npos);
  // The exact ball passes at 1.
  CHECK_NOTHROW(acc::scan_field([](glm::dvec3 p) { return test_fields::ball_cpu(p); }, unit, "test"));
}

TEST_CASE("field truth: NaN inside the box, bad boxes and bounds are refused") {
  auto hole = [](glm::dvec3 p) { return p.x > 0.5 ? std::sqrt(-1.0 - p.x) : glm::length(p) - 1.0; };
  std::string m = refusal([&] { acc::scan_field(hole, unit, "measure"); });
  CHECK(m.find("measure: field 'ball' is NaN at (") != std::string::npos);
  CHECK(m.find("make the distance finite") != std::string::npos);
  acc::FieldBounds b = unit;
  b.max.y = -2.0;
  auto ball_d = [](glm::dvec3 p) { return test_fields::ball_cpu(p); };
  CHECK(refusal([&] { acc::field_hit(ball_d, b, glm::dvec3(0, 0, -4), glm::dvec3(0, 0, 1), 0.0, 9.0); })
            .find("is not finite with min < max") != std::string::npos);
  for (double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN()}) {
    b = unit;
    b.lipschitz = bad;
    CHECK(refusal([&] { acc::scan_field(ball_d, b, "test"); }).find("Lipschitz bound") != std::string::npos);
  }
  CHECK(refusal([&] { acc::scan_field(ball_d, unit, "test", 1); }).find("pass 2 to 1024") != std::string::npos);
  // A ray that misses the box misses, without evaluating the field.
  const acc::Result r = acc::field_hit(ball_d, unit, glm::dvec3(0, 5, -4), glm::dvec3(0, 0, 1), 0.0, 9.0);
  CHECK(r.outcome == acc::Outcome::miss);
  CHECK(r.evaluations == 0);
}

TEST_CASE("field truth: field_bounds takes a scene's declaration") {
  const proceduray::DistanceField f{.id = "gyroid", .glsl = "gyroid.glsl", .aabb = {glm::vec3(-2.0f), glm::vec3(1.0f)},
                                    .lipschitz = 1.75f};
  const acc::FieldBounds b = acc::field_bounds(f);
  CHECK(b.name == "gyroid");
  CHECK(b.min == glm::dvec3(-2.0));
  CHECK(b.lipschitz == 1.75);
  CHECK(acc::field_bounds({.id = "ball", .glsl = "ball.glsl", .exact = true}).lipschitz == 1.0);
}
