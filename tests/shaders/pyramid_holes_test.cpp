// Stability scenario 11 of ACCURACY.md: the D3D12 scene's fractal (Sierpinski) pyramid, rays
// through its holes and along its fold seams, float march (d3d12_intersect compiled as C++ in
// float, with the half-footprint knobs of test_knobs.hpp: 512 Lipschitz steps, epsilon 1e-4,
// half a pixel footprint at 1280x720, step scale 1, no relaxation) against the scene's reference (examples/03_d3d12_scene/
// reference_objects.hpp: trace_object, a Lipschitz search in double).
// Why: sdf_fractal_pyramid_distance follows the copy of the nearest vertex at each level, so
// it jumps where the nearest vertex changes (the fold seams: the planes x = 0 and z = 0 between
// base corners and +-x +-z - 2y = 1 between apex and corners, repeated at every level); a
// float rounding that picks the other side of a seam, or a probe across a thin part, could give
// a hit in empty space (a false hit) or pass a part the truth hits.
// Ray families, in the pyramid's unscaled frame q = p / 0.95:
//   - tunnels: horizontal rays along x and z through the tunnels under each copy's top copy,
//     lying in the seam planes x = 0, z = 0 (level 1), +-1/2 (level 2), +-1/4, +-3/4 (level 3)
//     ... (depths on the 1/16 grid), at heights halfway between 1/16 steps: the leaves' bases lie
//     at multiples of 1/8, and a ray in a base plane grazes it (a search of 1e8 evaluations);
//   - seam planes: rays lying in the four apex-corner seam planes of level 1;
//   - aimed: rays from six eyes around the pyramid aimed at random points inside its outer hull
//     where the distance says empty space (> 0.01), i.e. between the tetrahedra.
// A ray "through a hole" passes the outer hull (sdf_pyramid_planes, 1-Lipschitz) and the truth
// misses, or hits more than a threshold behind the hull's entry.
#include "test_knobs.hpp"
#include "03_d3d12_scene/reference_objects.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace {

namespace acc = proceduray::accuracy;
using F = d3d12::glsl::d3d12_primitives<float>;
using Dp = d3d12::glsl::d3d12_primitives<double>;

const d3d12::SceneConstants& constants() {
  static const d3d12::SceneConstants c =
      test_knobs::pinned(d3d12::default_constants(d3d12::sample_camera(1280, 720), 0.0f));
  return c;
}
const d3d12::ReferenceScene& scene() {
  static const d3d12::ReferenceScene s = d3d12::reference_scene(constants());
  return s;
}
const d3d12::Primitive& pyramid() {
  static const d3d12::Primitive p = d3d12::default_primitive(d3d12::fractal_pyramid);
  return p;
}
glm::dvec3 placement() { return glm::dvec3(d3d12::placement(d3d12::fractal_pyramid, d3d12::Layout::sample)); }

/// The pinned knobs as intersect.glsl passes them (the instance only translates, so object and
/// world lengths agree).
const proceduray::MarchKnobs& knobs() { return constants().knobs[d3d12::object_id(d3d12::fractal_pyramid)]; }
/// What d3d12_intersect_knobs marches with (the threshold for the checks below).
F::MarchSettings settings() { return F::march_settings(knobs(), 1.0f, constants().camera.pixel_angle, 1.0f); }

enum Family { tunnels, seam_planes, aimed, family_count };
const std::string family_names[] = {"tunnels", "seam planes", "aimed at empty points"};

/// An object-space ray in float (what the shader gets), unit direction, and its family.
struct Ray {
  glm::vec3 o, d;
  Family family;
};

Ray make(glm::dvec3 q_origin, glm::dvec3 q_dir, Family f) {
  const double scale = double(pyramid().params.x);
  return {glm::vec3(q_origin * scale), glm::vec3(glm::normalize(q_dir)), f};
}

std::vector<Ray> rays() {
  std::vector<Ray> out;
  // Tunnels and the seams x = 0, z = 0, +-1/2: along +x and +z on the 1/16 grid.
  for (int i = 0; i < 32; ++i) {
    for (int j = 1; j < 32; ++j) {
      const double y = -1.0 + (i + 0.5) / 16.0, w = -1.0 + j / 16.0;
      out.push_back(make({-3.0, y, w}, {1.0, 0.0, 0.0}, tunnels));
      out.push_back(make({w, y, -3.0}, {0.0, 0.0, 1.0}, tunnels));
    }
  }
  // The apex-corner seams sx x + sz z - 2 y = 1: rays in each plane, horizontal (along its
  // in-plane e1) and tilted within the plane, offset along e2 across the pyramid.
  for (const double sx : {-1.0, 1.0}) {
    for (const double sz : {-1.0, 1.0}) {
      const glm::dvec3 n = glm::dvec3(sx, -2.0, sz) / std::sqrt(6.0);
      const glm::dvec3 e1 = glm::dvec3(sx, 0.0, -sz) / std::sqrt(2.0), e2 = glm::cross(n, e1);
      const glm::dvec3 p0 = n / std::sqrt(6.0);  // the plane's point nearest the origin
      for (int k = 0; k < 32; ++k) {
        const glm::dvec3 p = p0 + (-1.3 + 2.6 * k / 31.0) * e2;
        for (const double tilt : {0.0, 0.35, -0.35}) {
          const glm::dvec3 d = glm::normalize(e1 + tilt * e2);
          out.push_back(make(p - 3.0 * d, d, seam_planes));
        }
      }
    }
  }
  // Aimed at empty points inside the hull, from six eyes.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const glm::dvec3 eyes[] = {{0.0, 0.3, 3.5}, {3.2, 1.5, 0.4}, {-2.5, 2.5, -1.5},
                             {1.5, -0.6, -3.0}, {-3.0, -0.5, 1.0}, {0.4, 3.6, 0.9}};
  std::size_t made = 0;
  while (made < 900) {
    const glm::dvec3 q(u(rng), u(rng), u(rng));
    if (!(Dp::sdf_pyramid_planes(q) < -0.02) || !(Dp::sdf_fractal_pyramid_distance(q, 4u) > 0.01)) continue;
    const glm::dvec3& eye = eyes[made % 6];
    out.push_back(make(eye, q - eye, aimed));
    ++made;
  }
  return out;
}

/// The pyramid's own distance in double at an object-space point.
double local_distance(glm::dvec3 p) { return Dp::sdf_distance(d3d12::fractal_pyramid, p, glm::dvec4(pyramid().params)); }

/// How one family fared.
struct Tally {
  std::size_t rays = 0, truth_hits = 0, through_holes = 0, see_through = 0, both_miss = 0, agree = 0;
  std::size_t false_hits = 0, in_front = 0;  ///< float hit where the truth misses / before the truth's t
  std::size_t far_false = 0;                 ///< ... more than a threshold away from the surface
  std::size_t behind = 0, false_misses = 0;  ///< a part the truth hits was passed (stepped over)
  std::size_t passed_long = 0;               ///< ... and it was at least a threshold long
  double worst_t = 0;                        ///< max |t - t_ref| / (threshold / 32) over agreeing rays
  double worst_footprints = 0;               ///< max |t - t_ref| in footprints over hits not behind the truth
};

}  // namespace

TEST_CASE("fractal pyramid - no false hits through holes and along fold seams at half a footprint") {
  const std::vector<Ray> rs = rays();
  const F::MarchSettings m = settings();
  const double pixel_angle = double(constants().camera.pixel_angle);
  Tally tally[family_count];
  Tally all;
  for (const Ray& r : rs) {
    const glm::dvec3 o(r.o), d(r.d);
    const acc::Result ref =
        d3d12::trace_object(scene(), d3d12::object_id(d3d12::fractal_pyramid), o + placement(), d).result;
    REQUIRE(ref.outcome != acc::Outcome::undetermined);
    float t = 0.0f, steps = 0.0f;
    glm::vec3 n(0.0f);
    const bool hit = F::d3d12_intersect_knobs(d3d12::fractal_pyramid, pyramid().params, pyramid().spin,
                                              constants().time, r.o, r.d, 0.0f, 1e30f, 0u, knobs(), 1.0f,
                                              constants().camera.pixel_angle, t, n, steps);
    const bool truth = ref.outcome == acc::Outcome::hit;
    CAPTURE(r.family);
    CAPTURE(r.o);
    CAPTURE(r.d);
    CHECK(std::isfinite(t));
    // The outer hull's entry (1-Lipschitz planes, scaled like the fractal).
    auto hull = [](glm::dvec3 p) { return Dp::sdf_pyramid_planes(p / double(pyramid().params.x)) * double(pyramid().params.x); };
    const acc::Result in_hull = acc::lipschitz_search(hull, 1.0, o, d, 0.0, 10.0, {.min_step = 1e-9});
    const double threshold = double(F::march_epsilon(m, float(truth ? ref.t : 0.0)));
    const bool through = in_hull.outcome == acc::Outcome::hit && (!truth || ref.t > in_hull.t + threshold);
    for (Tally* k : {&tally[r.family], &all}) {
      ++k->rays;
      k->truth_hits += truth;
      k->through_holes += through;
      k->see_through += through && !truth;
      k->both_miss += !truth && !hit;
      k->false_hits += !truth && hit;
    }
    // A false hit near a boundary is a rounding of the sign within the hit threshold of the
    // surface (the double distance there is below it); one farther out is a hit in empty space.
    const bool far_from_surface = hit && local_distance(o + double(t) * d) > double(F::march_epsilon(m, t));
    if (!truth) {
      for (Tally* k : {&tally[r.family], &all}) k->far_false += far_from_surface;
      continue;
    }
    // The hit rule's tolerance: the outside end of a bracket of threshold / 32, plus float
    // rounding (64 spacings of t; the bracket alone covers what was measured).
    const double tolerance = threshold * double(F::march_refine_fraction) + 64.0 * std::ldexp(1.0, -24) * ref.t;
    const double err = double(t) - ref.t;
    const bool agree = hit && std::abs(err) <= tolerance;
    const bool front = hit && err < -tolerance;
    const bool passed = !hit || err > tolerance;
    double run = 0.0;
    if (passed) {
      // The inside run the march did not see: from the truth's entry to its exit.
      const acc::Result exit = acc::lipschitz_search(local_distance, 1.0, o, d, ref.t + 1e-9, ref.t + 1.0,
                                                     {.min_step = 1e-10});
      run = exit.starts_inside ? exit.t - ref.t : 0.0;
    }
    for (Tally* k : {&tally[r.family], &all}) {
      k->agree += agree;
      k->in_front += front;
      k->far_false += front && far_from_surface;
      k->behind += hit && passed;
      k->false_misses += !hit;
      k->passed_long += passed && run >= threshold;
      if (agree) k->worst_t = std::max(k->worst_t, std::abs(err) / (threshold * double(F::march_refine_fraction)));
      if (hit && !passed) k->worst_footprints = std::max(k->worst_footprints, std::abs(err) / (pixel_angle * ref.t));
    }
  }
  for (int f = 0; f <= family_count; ++f) {
    const Tally& k = f < family_count ? tally[f] : all;
    MESSAGE((f < family_count ? family_names[f] : std::string("all")) << ": rays " << k.rays << ", truth hits "
            << k.truth_hits << ", through holes " << k.through_holes << " (seen through " << k.see_through
            << "); both miss " << k.both_miss
            << ", agree within threshold/32 " << k.agree << "; false hits " << k.false_hits << ", hits in front "
            << k.in_front << " (farther than a threshold from the surface " << k.far_false << "); behind " << k.behind << ", false misses " << k.false_misses
            << " (a run of a threshold or more passed: " << k.passed_long << "); worst |t - t_ref| / (threshold/32) "
            << k.worst_t << ", worst |t - t_ref| in footprints " << k.worst_footprints);
  }
  for (int f = 0; f < family_count; ++f) {
    const Tally& k = tally[f];
    CAPTURE(family_names[f]);
    // Each family really probes holes: rays through the hull that the truth sees through or
    // hits behind a gap (seen: 700, 208 and 667 of 1984, 384 and 900; 700, 96 and 103 seen through).
    CHECK(k.through_holes >= k.rays / 10);
    CHECK(k.see_through >= 10);
    // False hits: none in empty space (farther than the hit threshold from the surface); near a
    // boundary at most 0.5 % of the rays (seen: 0 of each).
    CHECK(k.far_false == 0);
    CHECK(double(k.false_hits + k.in_front) <= 0.005 * double(k.rays));
    // The other way: a part the truth hits is passed only if thinner than a threshold (the hit
    // rule's documented limit), and for at most 0.5 % of the truth's hits (seen: 0).
    CHECK(k.passed_long == 0);
    CHECK(double(k.behind + k.false_misses) <= 0.005 * double(k.truth_hits));
    // Where both hit: within the hit rule's bracket (threshold / 32 + float, by construction of
    // `agree`), which is 0.016 footprints here (seen); 0.05 leaves margin for the float term.
    CHECK(k.worst_footprints <= 0.05);
  }
}
