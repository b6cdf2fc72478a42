// scene/world_origin.hpp: scenario 14 of the accuracy plan (the whole scene translated by 10^k,
// k = 0..7). A sphere is placed at 10^k and seen from 4 units away; each ray goes the way the
// GPU takes it: float eye, float instance matrix, the driver's float inverse applied to the
// ray, then the shaders' own float sphere (shaders/primitives/sphere.glsl). Ground truth is
// the closed form in double from the exact eye and centre. Without re-origin the error grows
// with 10^k (coordinates rounded to |x| 2^-24) until it is many pixel footprints; with the
// origin at the eye it stays at float rounding of t whatever k is.
#include <proceduray/shader/glsl_cpp.hpp>

namespace world_origin_test {
using namespace proceduray::glsl_cpp;
#include "primitives/sphere.glsl"
}  // namespace world_origin_test

#include <proceduray/accuracy/closed_form.hpp>
#include <proceduray/accuracy/percentiles.hpp>
#include <proceduray/scene/world_origin.hpp>

#include <doctest/doctest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace {
namespace pr = proceduray;

constexpr double pixel_angle = 1e-3;  // about a 1000-pixel-wide frame at a 57 degree field of view

struct Errors {
  double median = 0, max = 0;  // |t - t_ref| in pixel footprints (pixel_angle * t_ref)
};

/// Appends the errors of rays from eye at the unit sphere placed by world_from_object,
/// rendered with coordinates relative to `origin`; a ray the float path misses counts as
/// `missed` footprints (far beyond every bound below).
constexpr double missed = 1e9;
void trace(const glm::dmat4& world_from_object, glm::dvec3 eye, const pr::WorldOrigin& origin,
           std::vector<double>& errors) {
  const glm::dvec3 centre(world_from_object[3]);
  // What the GPU holds: float coordinates relative to the origin, and the driver's inverse.
  const glm::mat4 object_from_world = glm::inverse(origin.transform(world_from_object));
  const glm::vec3 eye_f = origin.point(eye);
  const glm::vec3 o = glm::vec3(object_from_world * glm::vec4(eye_f, 1.0f));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.9, 0.9);
  const glm::dvec3 ahead = glm::normalize(centre - eye);
  const glm::dvec3 side = glm::normalize(glm::cross(ahead, glm::dvec3(0.0, 1.0, 0.0)));
  const glm::dvec3 up = glm::cross(side, ahead);
  for (int i = 0; i < 100; ++i) {
    // Aim inside the silhouette (radius 1 at distance ~4: half-angle 0.25 rad; these rays reach 0.22).
    const glm::dvec3 dir = glm::normalize(ahead + 0.17 * (u(rng) * side + u(rng) * up));
    const pr::accuracy::Result truth = pr::accuracy::intersect_sphere(eye, dir, centre, 1.0, 0.0, 100.0);
    REQUIRE(truth.outcome == pr::accuracy::Outcome::hit);
    const glm::vec3 d = glm::mat3(object_from_world) * glm::vec3(dir);
    float t_near = 0.0f, t_far = 0.0f;
    if (!world_origin_test::ray_sphere(o, d, glm::vec3(0.0f), 1.0f, t_near, t_far)) {
      errors.push_back(missed);
      continue;
    }
    errors.push_back(std::abs(double(t_near) - truth.t) / (pixel_angle * truth.t));
  }
}

/// A rotated unit sphere (the inverse then mixes coordinates, as a general instance does) at
/// distance `scale` from the world's origin, in direction `which` of a fixed set.
glm::dmat4 placed_at(double scale, int which) {
  const glm::dvec3 dir = glm::normalize(glm::dvec3(1.0 + 0.37 * which, 0.7 - 0.21 * which, 0.4 + 0.13 * which));
  return glm::rotate(glm::translate(glm::dmat4(1.0), scale * dir), 0.6 + 0.1 * which,
                     glm::normalize(glm::dvec3(0.2, 1.0, 0.3)));
}

glm::dvec3 eye_for(const glm::dmat4& m) { return glm::dvec3(m[3]) + glm::dvec3(0.3, 0.2, -4.0); }

/// The errors over 8 placements at distance `scale`; where_origin(eye) is the origin used.
template <class Origin>
pr::accuracy::Distribution errors_at(double scale, Origin where_origin) {
  std::vector<double> errors;
  for (int which = 0; which < 8; ++which) {
    const glm::dmat4 m = placed_at(scale, which);
    trace(m, eye_for(m), where_origin(eye_for(m)), errors);
  }
  return pr::accuracy::summarize(errors);
}

pr::WorldOrigin world_zero(glm::dvec3) { return pr::WorldOrigin(); }
pr::WorldOrigin at_eye(glm::dvec3 eye) { return pr::WorldOrigin(eye); }
}  // namespace

TEST_CASE("world origin - translated by 10^k the error grows with k and re-origin keeps it at rounding") {
  int breaks_at = -1;  // the first k where the median error exceeds half a footprint
  for (int k = 0; k <= 7; ++k) {
    CAPTURE(k);
    const pr::accuracy::Distribution plain = errors_at(std::pow(10.0, k), world_zero);
    const pr::accuracy::Distribution moved = errors_at(std::pow(10.0, k), at_eye);
    MESSAGE("10^" << k << ": world coordinates median " << plain.median << " p99 " << plain.p99
                  << " footprints; origin at the eye median " << moved.median << " max " << moved.max);
    // Re-origin: float rounding of t ~ 4 (2^-22 relative) is ~5e-4 footprints; 0.01 leaves 20x.
    CHECK(moved.max < 0.01);
    if (breaks_at < 0 && plain.median > 0.5) breaks_at = k;
    if (k <= 2) CHECK(plain.max < 0.05);  // near the origin the world's coordinates are fine too
  }
  // The spacing at 10^k is up to 10^k 2^-23: a footprint (4e-3) at 10^4.5. The world-coordinate
  // path must have broken by 10^5 and not before 10^4 (seen: 10^5, median 0.93 and p99 3.2).
  CHECK(breaks_at >= 4);
  CHECK(breaks_at <= 5);
  // At 10^6 (the 1.7 % of t at t = 4) the error is tens of footprints; at 10^7 rays miss.
  CHECK(errors_at(1e6, world_zero).median > 5.0);
  CHECK(errors_at(1e7, world_zero).p99 == missed);
}

TEST_CASE("world origin - needs_reorigin says so before the rounding reaches the footprint") {
  // With the origin at 0 for every k = 0..7: whenever needs_reorigin is false (rounding at the
  // eye under 1/64 of the nearest footprint, 1e-3 x 3), the error stays under a tenth of one.
  int kept = 0;
  for (int k = 0; k <= 7; ++k) {
    CAPTURE(k);
    const double scale = std::pow(10.0, k);
    const glm::dvec3 eye = eye_for(placed_at(scale, 0));
    if (pr::WorldOrigin().needs_reorigin(eye, pixel_angle * 3.0)) continue;
    ++kept;
    CHECK(errors_at(scale, world_zero).max < 0.1);
  }
  CHECK(kept >= 3);  // 10^0..10^2 at least
  CHECK(kept <= 4);  // and not from 10^4 on (spacing 1e-3 there: a third of a footprint)
  CHECK_FALSE(pr::WorldOrigin().needs_reorigin(glm::dvec3(1e7), 1e-3, 1e9));  // a huge budget accepts anything
  // An origin left 10^3 from the eye costs what 10^3 costs, however far out the world is.
  const auto off_by_1e3 = [](glm::dvec3 eye) { return pr::WorldOrigin(eye + glm::dvec3(1e3, 0.0, 0.0)); };
  CHECK(errors_at(1e7, off_by_1e3).max < 0.1);
  CHECK(errors_at(1e3, world_zero).max < 0.1);
}

TEST_CASE("world origin - points and transforms are relative to the origin and round once") {
  const pr::WorldOrigin origin(glm::dvec3(1e8, -2e8, 3e8));
  CHECK(origin.point(glm::dvec3(1e8 + 0.25, -2e8, 3e8 - 1.5)) == glm::vec3(0.25f, 0.0f, -1.5f));
  CHECK(origin.world(glm::vec3(0.25f, 0.0f, -1.5f)) == glm::dvec3(1e8 + 0.25, -2e8, 3e8 - 1.5));
  const glm::dmat4 m = glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(1e8 + 3.0, -2e8, 3e8)), glm::dvec3(2.0));
  const glm::mat4 t = origin.transform(m);
  CHECK(t[3] == glm::vec4(3.0f, 0.0f, 0.0f, 1.0f));
  CHECK(t[0] == glm::vec4(2.0f, 0.0f, 0.0f, 0.0f));  // rotation and scale pass through
  const pr::InstanceTransform rows = origin.instance(m);
  CHECK(rows[0] == glm::vec4(2.0f, 0.0f, 0.0f, 3.0f));  // the 3x4 rows carry the translation last
  CHECK(pr::float_spacing(1.0) == 0x1p-23);
  CHECK(pr::float_spacing(1e6) == 0.0625);
  CHECK(pr::float_spacing(0.0) == 0x1p-149);
  CHECK(origin.spacing_at(glm::dvec3(1e8 + 3.0, -2e8, 3e8)) == pr::float_spacing(3.0));
}

TEST_CASE("world origin - bad input names the call the value and the fix") {
  using doctest::Contains;
  const double nan = std::nan("");
  CHECK_THROWS_WITH_AS(pr::WorldOrigin(glm::dvec3(0.0, nan, 0.0)), Contains("WorldOrigin: origin"), pr::UsageError);
  CHECK_THROWS_WITH_AS(pr::WorldOrigin(glm::dvec3(0.0, nan, 0.0)), Contains("pass a finite point"), pr::UsageError);
  CHECK_THROWS_WITH_AS((void)pr::WorldOrigin().point(glm::dvec3(INFINITY, 0.0, 0.0)), Contains("WorldOrigin::point"),
                       pr::UsageError);
  glm::dmat4 projective(1.0);
  projective[2][3] = -1.0;
  CHECK_THROWS_WITH_AS((void)pr::WorldOrigin().transform(projective), Contains("WorldOrigin::transform: the last row is"),
                       pr::UsageError);
  CHECK_THROWS_WITH_AS((void)pr::WorldOrigin().transform(projective), Contains("affine"), pr::UsageError);
  glm::dmat4 bad(1.0);
  bad[3][1] = nan;
  CHECK_THROWS_WITH_AS((void)pr::WorldOrigin().transform(bad), Contains("element [3][1]"), pr::UsageError);
  CHECK_THROWS_WITH_AS((void)pr::WorldOrigin().needs_reorigin(glm::dvec3(0.0), 0.0),
                       Contains("WorldOrigin::needs_reorigin: footprint"), pr::UsageError);
  CHECK_THROWS_WITH_AS((void)pr::WorldOrigin().needs_reorigin(glm::dvec3(0.0), 1.0, -1.0), Contains("budget"),
                       pr::UsageError);
}
