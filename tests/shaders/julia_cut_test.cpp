// Stability of the paper scene's cut Julia set (ACCURACY.md scenario 9): rays parallel to the cut
// plane just above and below it, and rays grazing it at 1e-1 .. 1e-6 rad onto the cut face. The
// method is the shipped one, in float: shaders/marching/sphere_trace.glsl marching julia.glsl's
// julia_cut_distance with the half-footprint knobs of test_knobs.hpp (256 steps, epsilon 1e-4
// world, threshold 0.5 pixel footprints, refined hits, step scale 1) at a 320x240 camera's pixel angle, as
// marching/field.glsl sets them up in object space. The truth is the reference's own (reference_objects.hpp):
// paper::julia_cut_inside, the escape test plus the kept half-space, searched along the same float
// ray in double by accuracy::predicate_search. Why: a plane cut by max(d_julia, d_plane) turns the
// face into a plane that rays can run along at any height, where a march may creep (probes of a
// 64th of a threshold) or take the removed side for a surface, and where float's resolution
// of the height decides the hit at grazing angles.
#include "test_knobs.hpp"
#include "02_paper_scene/reference_objects.hpp"

namespace julia_cut_test {
using namespace proceduray::glsl_cpp;
using julia = proceduray::glsl::julia<float>;
/// julia.rint's constant, count and plane, as the GPU holds them (paper scene at time 0).
inline const paper::Frame constants = test_knobs::pinned(paper::default_frame(320, 240, 0.0f));
inline const glm::vec4 julia_c = julia::julia_animated_c(constants.time);
inline const std::uint32_t julia_count = std::max(constants.knobs[paper::julia_id].iterations, 1u);
inline const proceduray::MarchKnobs& knobs = constants.knobs[paper::julia_id];
inline const glm::vec4 cut_plane = glm::vec4(paper::julia_cut_plane);
inline float march_distance(vec3 p) { return julia::julia_cut_distance(p, julia_c, julia_count, cut_plane); }
#include "common/ray.glsl"
using MarchKnobs = proceduray::MarchKnobs;
#include "marching/knobs.glsl"
/// The marcher of this test's shape (marching/marcher.glsl): prefix shape, no field data.
struct Shape {};
inline float shape_distance(vec3 p, Shape) { return march_distance(p); }
#define PROCEDURAY_MARCHER shape
#define PROCEDURAY_MARCHER_FIELD Shape
#define PROCEDURAY_MARCHER_DISTANCE shape_distance
#include "marching/marcher.glsl"
}  // namespace julia_cut_test

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>
#include <vector>

using namespace julia_cut_test;
namespace acc = proceduray::accuracy;

namespace {

const paper::ReferenceScene scene = paper::reference_scene(constants);
const double pixel_angle = constants.camera.pixel_angle;
const glm::dvec3 cut_normal(paper::julia_cut_plane);  // |n| = 1 to 6e-6 (rounded floats): a distance per unit
const double cut_w = paper::julia_cut_plane.w;

/// marching/field.glsl's settings in object space: the absolute epsilon divided by the instance's scale.
MarchSettings settings() {
  return march_settings(knobs, paper::julia_placement.scale, constants.camera.pixel_angle, 1.0f);
}

/// Object-space distance of the ray origins from the face: the default camera's distance from the
/// Julia instance (about 9.7 object units), so the threshold is the one its pixels use there.
const double camera_distance =
    glm::length(glm::dvec3(constants.camera.eye) - glm::dvec3(paper::julia_placement.translation)) /
    paper::julia_placement.scale;
/// The hit threshold at the face: 0.5 footprints, ~0.019 object units.
const double threshold = march_epsilon(settings(), static_cast<float>(camera_distance));

bool inside(glm::dvec3 p) { return paper::julia_cut_inside(p, scene.julia_c, scene.julia_iterations); }
bool inside_uncut(glm::dvec3 p) { return paper::julia_inside(p, scene.julia_c, scene.julia_iterations); }

/// An orthonormal basis of the plane and the plane's point nearest the origin.
struct Face {
  glm::dvec3 n = glm::normalize(cut_normal);
  glm::dvec3 e1 = glm::normalize(glm::cross(n, glm::dvec3(0.0, 1.0, 0.0)));
  glm::dvec3 e2 = glm::cross(n, e1);
  glm::dvec3 centre = cut_normal * cut_w / glm::dot(cut_normal, cut_normal);
  glm::dvec3 at(double a, double b) const { return centre + a * e1 + b * e2; }
  glm::dvec3 along(double angle) const { return std::cos(angle) * e1 + std::sin(angle) * e2; }
};

/// One float ray clipped to julia_aabb as marching/field.glsl clips it, marched, and its reference.
struct Trace {
  glm::vec3 o{0.0f}, u{0.0f};
  float t0 = 0.0f, t1 = 0.0f;
  bool clipped = false;  ///< the ray meets the box
  bool found = false;
  float s = 0.0f;
  std::uint32_t steps = 0;
  acc::Result truth{};
};

Trace trace(glm::vec3 o, glm::vec3 u) {
  Trace r;
  r.o = o;
  r.u = u;
  r.t0 = 0.0f;
  r.t1 = 1.0e30f;
  r.clipped = ray_clip_aabb(o, u, paper::julia_aabb.min, paper::julia_aabb.max, r.t0, r.t1);
  if (!r.clipped) return r;
  r.found = shape_trace(o, u, r.t0, r.t1, settings(), {}, r.s, r.steps);
  // Spacing 1e-2 footprints at the entry (what the reference's tests use); the rays below hit the
  // set's body or the face, not filaments thinner than that.
  r.truth = acc::predicate_search(inside, glm::dvec3(o), glm::dvec3(u), r.t0, r.t1, 1.0e-2 * pixel_angle * r.t0);
  return r;
}

/// The reference's membership in every point of a ball of `radius` around p (a 9^3 grid within
/// it): the set is solid there, away from the face's fractal boundary.
bool solid_ball(glm::dvec3 p, double radius, bool uncut) {
  for (int i = -4; i <= 4; ++i) {
    for (int j = -4; j <= 4; ++j) {
      for (int k = -4; k <= 4; ++k) {
        const glm::dvec3 q(i, j, k);
        if (glm::dot(q, q) > 16.0) continue;
        const glm::dvec3 x = p + radius / 4.0 * q;
        if (!(uncut ? inside_uncut(x) : inside(x))) return false;
      }
    }
  }
  return true;
}

/// How far the ray runs within `delta` of the cut set before t_end (the reference's membership at
/// the point and 26 neighbours at delta, every delta / 8): where the march probes instead of stepping.
double near_run(const Trace& r, double t_end, double delta) {
  const glm::dvec3 o(r.o), u(r.u);
  const double spacing = delta / 8.0;
  double run = 0.0;
  for (double t = r.t0; t < t_end; t += spacing) {
    bool near = false;
    for (int i = -1; i <= 1 && !near; ++i) {
      for (int j = -1; j <= 1 && !near; ++j) {
        for (int k = -1; k <= 1 && !near; ++k) {
          const glm::dvec3 e(i, j, k);
          near = inside(o + t * u + (i == 0 && j == 0 && k == 0 ? e : delta * glm::normalize(e)));
        }
      }
    }
    if (near) run += spacing;
  }
  return run;
}

double angle_degrees(glm::dvec3 a, glm::dvec3 b) {
  return glm::degrees(std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)));
}

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

TEST_CASE("julia cut: setup matches the paper scene") {
  // The knobs the scenario is about (pinned: test_knobs.hpp); if they change, the bounds below need measuring again.
  CHECK(knobs.max_steps == 256u);
  CHECK(knobs.threshold == 0.5f);
  CHECK(knobs.step_scale == 1.0f);
  CHECK(julia_count == 10u);
  CHECK(threshold == doctest::Approx(0.5 * pixel_angle * camera_distance).epsilon(1e-5));
  CHECK(scene.julia_c == glm::dvec4(julia_c));
  // The face has a solid interior to test on (the reference's membership on the plane).
  const Face f;
  CHECK(std::abs(glm::dot(cut_normal, f.centre) - cut_w) < 1e-12);
  CHECK(inside(f.at(0.0, -0.5)));
}

TEST_CASE("julia cut: rays parallel to the cut plane never hit the removed side") {
  const Face f;
  const double ks[] = {1e-3, 1e-2, 1e-1, 1.0, 10.0};  // heights in thresholds
  std::size_t kept = 0, kept_agree = 0, kept_hits = 0, skipped = 0, removed = 0, exhausted = 0;
  std::vector<std::size_t> disagree(std::size(ks), 0);
  for (int j = 0; j < 4; ++j) {
    const double angle = 0.25 * std::numbers::pi * j + 0.1;  // off the basis axes
    const glm::dvec3 v = f.along(angle), across = glm::cross(f.n, v);
    for (int b = -12; b <= 12; ++b) {
      for (std::size_t ki = 0; ki < std::size(ks); ++ki) {
        for (double side : {-1.0, 1.0}) {  // -1: the kept side, dot(n, p) < w
          const glm::dvec3 start = f.centre + 0.1 * b * across + side * ks[ki] * threshold * f.n - camera_distance * v;
          const Trace r = trace(glm::vec3(start), glm::vec3(v));
          CAPTURE(angle);
          CAPTURE(b);
          CAPTURE(ks[ki]);
          CAPTURE(side);
          if (!r.clipped) continue;
          CHECK(std::isfinite(r.s));
          CHECK(r.steps <= knobs.max_steps);
          if (side > 0.0) {
            // The removed side: the whole ray lies above the plane (the float direction tilts it by
            // ~1e-7 over the box, the height is >= 1.9e-5), so the reference says miss, and so must the march.
            ++removed;
            REQUIRE(r.truth.outcome == acc::Outcome::miss);
            CHECK_FALSE(r.found);
            exhausted += r.steps >= knobs.max_steps;
            continue;
          }
          if (r.truth.outcome == acc::Outcome::undetermined) {
            ++skipped;
            continue;
          }
          ++kept;
          const bool truth_hit = r.truth.outcome == acc::Outcome::hit;
          kept_hits += truth_hit;
          if (r.found == truth_hit) {
            ++kept_agree;
            if (truth_hit) {
              // Same surface: within a threshold (0.5 footprints) of the reference's t.
              CHECK(std::abs(r.s - r.truth.t) / (pixel_angle * r.truth.t) < 0.5);
            }
          } else {
            ++disagree[ki];
            // A disagreement may only be a miss of a hit (an exhausted march or a run of the set
            // thinner than the probes), never a hit where the reference sees nothing.
            CHECK(truth_hit);
          }
        }
      }
    }
  }
  INFO("kept-side rays " << kept << ", reference hits " << kept_hits << ", agree " << kept_agree
                         << ", removed-side rays " << removed << " (exhausted " << exhausted << ")");
  CHECK(skipped == 0);
  CHECK(removed >= 400);
  CHECK(kept_hits >= 200);
  // Measured: 0 disagreements at every height. Allow 1 % of the kept rays per height: a ray through
  // a filament thinner than the probes (1/128 footprint) may miss it and the reference find it.
  for (std::size_t ki = 0; ki < std::size(ks); ++ki) {
    CAPTURE(ks[ki]);
    CHECK(disagree[ki] * 100 <= kept / std::size(ks));
  }
}

TEST_CASE("julia cut: grazing rays onto the cut face - t error and evaluations") {
  const Face f;
  const MarchSettings m = settings();
  const double margin = 0.05;      // solid ball around the face point: ~2.6 thresholds
  const double approach = 0.15;    // the ray crosses onto the solid face at most this far before it
  const double near_limit = 0.2;   // and runs within 2 thresholds of the set for at most this long
  std::size_t rays = 0, bounded = 0, long_runs = 0, normals = 0;
  double worst_normal = 0.0;
  for (int a = -30; a <= 30; a += 3) {
    for (int b = -30; b <= 30; b += 3) {
      const glm::dvec3 p = f.at(0.05 * a, 0.05 * b);
      if (!inside_uncut(p) || !solid_ball(p, margin, true)) continue;
      for (int j = 0; j < 8; ++j) {
        const glm::dvec3 v = f.along(0.25 * std::numbers::pi * j);
        double solid_run = 0.0;  // how far back from p the face stays solid (the reference's membership)
        while (solid_run <= approach && inside_uncut(p - solid_run * v)) solid_run += 1.0e-3;
        if (solid_run > approach) continue;
        for (double alpha = 1.0e-1; alpha > 0.5e-6; alpha *= 0.1) {
          const glm::vec3 u(std::cos(alpha) * v - std::sin(alpha) * f.n);  // down onto the face
          const glm::vec3 o(p - camera_distance * glm::dvec3(u));
          const Trace r = trace(o, u);
          CAPTURE(a);
          CAPTURE(b);
          CAPTURE(j);
          CAPTURE(alpha);
          REQUIRE(r.clipped);
          REQUIRE(r.truth.outcome == acc::Outcome::hit);
          const glm::dvec3 hit = glm::dvec3(r.o) + r.truth.t * glm::dvec3(r.u);
          // Float rounding of u moves the crossing by up to ~0.03 t / (alpha * 1e7) from p: only
          // rays the reference says hit the face (on the plane, solid around) count as face hits.
          if (std::abs(glm::dot(cut_normal, hit) - cut_w) > 1.0e-9 || !solid_ball(hit, margin, true)) continue;
          ++rays;
          CHECK(std::isfinite(r.s));
          CHECK(r.steps <= knobs.max_steps);
          // t error. The hit rule puts s within threshold / 32 (1/64 footprint) of a crossing; float
          // puts the crossing itself where the float height dot(n, o + s u) - w changes sign, and
          // rounding o + s u (s ~ 10) errs by ~s 2^-24 in height, i.e. by that / sin(alpha) along
          // the ray. Bound: 1/16 footprint plus that term (15 footprints at 1e-6 rad, 1.5 at 1e-5);
          // measured at most 0.02 footprints down to 1e-3 rad, then 0.064, 0.55 and 5.7 at 1e-4,
          // 1e-5 and 1e-6 rad.
          const double bound = 1.0 / 16.0 + std::ldexp(1.0, -24) / (std::sin(alpha) * pixel_angle);
          if (r.found) {
            CHECK(std::abs(r.s - r.truth.t) / (pixel_angle * r.truth.t) < bound);
          }
          // Evaluations: on the face the distance is the plane's, below a threshold the march
          // probes a 64th of one at a time, so the cost follows how long the ray runs near the
          // set. Where that is short (0.2, ~10 thresholds) and the angle is 1e-2 rad or more it
          // must not exhaust the budget (measured: none does). Below, the last t / 128 above the
          // face takes ~1 / (2 alpha) probes: at <= 1e-3 rad many rays run out of their 256 steps
          // and miss (never a wrong hit: the t check above). With a floor of t / 16 most fitted
          // (6 per angle did not); sphere_trace.glsl says why the floor is t / 64.
          if (alpha >= 0.5e-2 && near_run(r, r.truth.t, 2.0 * threshold) <= near_limit) {
            ++bounded;
            CHECK(r.found);
            CHECK(r.steps < knobs.max_steps);
          } else {
            ++long_runs;  // may exhaust: then a miss, which the t check above leaves alone
          }
          if (!r.found) continue;
          // Normal at the reported point, where the reference says the set is solid within twice
          // the tetrahedron's reach: the tetrahedral normal there vs the plane's exact normal.
          const glm::vec3 q = r.o + r.s * r.u;
          const float h = std::max(march_epsilon(m, r.s), 1.0e-5f);  // marching/field.glsl's
          if (!solid_ball(glm::dvec3(q), 2.0 * std::sqrt(3.0) * h + 1.0e-3, true)) continue;
          const glm::vec3 n = shape_tetrahedral_normal(q, h, {});
          REQUIRE(finite(n));
          ++normals;
          const double error = angle_degrees(glm::dvec3(n), cut_normal);
          worst_normal = std::max(worst_normal, error);
          // The tetrahedron's samples below the plane read 0, not a negative distance
          // (julia_distance is 0 inside), which tilts the estimate by a fixed angle at any h:
          // normalize(sum a_i max(n.a_i, 0)) vs n is 17.34 deg for this plane; measured 17.23 ..
          // 17.33 deg. Bound 18 deg. julia.rint does not use it on the face: it takes the plane's
          // normal where d_plane >= julia_distance, which holds at every reported face point.
          CHECK(error < 18.0);
          CHECK(dot(glm::vec3(cut_plane), q) - cut_plane.w >= julia::julia_distance(q, julia_c, julia_count));
        }
      }
    }
  }
  INFO("face hits " << rays << ", short near runs " << bounded << ", long " << long_runs << ", normals " << normals
                    << ", worst normal " << worst_normal);
  CHECK(bounded >= 80);   // measured 98 (the 1e-1 and 1e-2 rad rays with short runs)
  CHECK(normals >= 80);   // measured 92
}
