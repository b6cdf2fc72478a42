// examples/02_paper_scene/reference.hpp, the paper scene's ground truth per camera ray, checked
// by what it does not use: the plane by its closed form written here, fractal hits by the
// shaders' own distance estimates (0 exactly inside) in double, the Pac-men by pacman.glsl's
// interval CSG, misses by a slab test written here; and against the float sphere tracer
// (sphere_trace.glsl with marching/field.glsl's settings, the paper's defaults) run in C++.
#include "test_knobs.hpp"
#include "02_paper_scene/accuracy.hpp"
#include "02_paper_scene/paper_scene.hpp"
#include "02_paper_scene/reference.hpp"

namespace paper_reference_test {
using namespace proceduray::glsl_cpp;
/// The shaders' Pac-man CSG in double.
template <class T>
struct pac {
  PROCEDURAY_GLSL_CPP_SCALAR(T)
#include "primitives/pacman.glsl"
};
/// marching/field.glsl's marcher in float on one fractal: kind 0 the Mandelbulb, 1 the cut Julia set.
template <int kind>
struct march {
  PROCEDURAY_GLSL_CPP_SCALAR(float)
  static inline uint count = 1;   // the iteration count the shader uses at this time
  static inline pr_real4 c{0.0f};    // the Julia constant
  /// What the distance reads besides p (the shaders' Bulb and Julia fields).
  struct Field {
    uint count;
    pr_real4 c;
  };
  static pr_real field_distance(pr_real3 p, Field f) {
    if constexpr (kind == 0) {
      return proceduray::glsl::mandelbulb<float>::mandelbulb_distance(p, f.count);
    } else {
      return proceduray::glsl::julia<float>::julia_cut_distance(p, f.c, f.count, paper::julia_cut);  // julia.rint's cut
    }
  }
#define PROCEDURAY_MARCHER field
#define PROCEDURAY_MARCHER_FIELD Field
#define PROCEDURAY_MARCHER_DISTANCE field_distance
#include "marching/marcher.glsl"
  using MarchKnobs = proceduray::MarchKnobs;
#include "common/ray.glsl"
#include "marching/knobs.glsl"
};
}  // namespace paper_reference_test

#include <doctest/doctest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

namespace acc = proceduray::accuracy;
using paper_reference_test::march;
using paper_reference_test::pac;

namespace {

constexpr std::uint32_t W = 48, H = 32;

const paper::Frame& constants() {
  static const paper::Frame c = test_knobs::pinned(paper::default_frame(W, H, 0.0f));
  return c;
}
/// The default reference at 48 x 32 (spacing 1e-3 footprints: ~0.2 s in a Release build).
const paper::ReferenceImage& truth() {
  static const paper::ReferenceImage r = paper::reference_image(constants(), W, H);
  return r;
}

glm::dvec3 xyz(glm::vec4 v) { return {v.x, v.y, v.z}; }

/// camera.glsl's ray, written here in double.
glm::dvec3 direction(std::uint32_t x, std::uint32_t y) {
  const proceduray::Camera& c = constants().camera;
  const glm::dvec2 uv = (glm::dvec2(x, y) + 0.5) / glm::dvec2(W, H) * 2.0 - 1.0;
  return glm::normalize(xyz(c.forward) + uv.x * xyz(c.right) - uv.y * xyz(c.up));
}

/// A plain slab test: does eye + t dir, t >= 0, meet the box?
bool meets_box(glm::dvec3 o, glm::dvec3 d, glm::dvec3 lo, glm::dvec3 hi) {
  double t0 = 0.0, t1 = 1e30;
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0.0) {
      if (o[a] < lo[a] || o[a] > hi[a]) return false;
      continue;
    }
    const double ta = (lo[a] - o[a]) / d[a], tb = (hi[a] - o[a]) / d[a];
    t0 = std::max(t0, std::min(ta, tb));
    t1 = std::min(t1, std::max(ta, tb));
  }
  return t0 <= t1;
}

struct World {
  glm::dvec3 translation;
  double scale;
  glm::dvec3 lo, hi;
};
World world(const proceduray::Placement& p, const proceduray::Aabb& box) {
  const glm::dvec3 t(p.translation);
  return {t, p.scale, t + double(p.scale) * glm::dvec3(box.min), t + double(p.scale) * glm::dvec3(box.max)};
}
World world_of(paper::ObjectId id) {
  if (id == paper::julia_id) return world(paper::julia_placement, paper::julia_aabb);
  if (id == paper::mandelbulb_id) return world(paper::mandelbulb_placement, paper::mandelbulb_aabb);
  return world(paper::pacman_placements.at(id - paper::pacman0_id), paper::pacman_aabb);
}

/// Membership by the shaders' estimates in double (0 exactly inside), object space, at time 0:
/// the paper's defaults, 8 Mandelbulb and 10 Julia iterations.
bool estimate_inside(paper::ObjectId id, glm::dvec3 p) {
  REQUIRE(constants().time == 0.0f);
  if (id == paper::mandelbulb_id) return proceduray::glsl::mandelbulb<double>::mandelbulb_distance(p, 8u) == 0.0;
  const glm::dvec4 c(proceduray::glsl::julia<float>::julia_animated_c(0.0f));
  return proceduray::glsl::julia<double>::julia_distance(p, c, 10u) == 0.0 &&
         glm::dot(glm::dvec3(0.27617f, 0.27617f, 0.92057f), p) <= double(0.1f);
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(p * double(v.size())))];
}

std::string read(const std::string& path) {
  std::ifstream f(path);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

}  // namespace

TEST_CASE("paper reference: the cut plane and the mouth are data the shaders and the reference share") {
  const std::string dir = std::string(PROCEDURAY_EXAMPLES_DIR) + "/02_paper_scene/shaders/";
  // The cut is data: the Julia field takes it from the uniform (a parameter), and the reference
  // from the same C++ value.
  bool cut_parameter = false;
  const paper::PaperScene scene;
  for (const auto& p : scene.fields()[0].parameters) cut_parameter = cut_parameter || p.member == "julia_cuts";
  CHECK(cut_parameter);
  CHECK(read(dir + "fractals.glsl").find("cuts.plane[0]") != std::string::npos);
  CHECK(read(dir + "fractals.glsl").find("0.27617") == std::string::npos);
  const paper::Frame defaults = test_knobs::pinned(paper::default_frame(64, 48, 0.0f));
  CHECK(defaults.julia_cuts.count == 1u);
  CHECK(glm::dvec4(defaults.julia_cuts.plane[0]) == paper::julia_cut_plane);
  CHECK(read(dir + "pacman.rint").find("constants.pacman_mouth") != std::string::npos);
  CHECK(read(dir + "pacman.rint").find("0.6") == std::string::npos);
  CHECK(double(defaults.pacman_mouth) == paper::pacman_mouth_half_angle);
  CHECK(paper::julia_cut_plane == glm::dvec4(0.27617f, 0.27617f, 0.92057f, 0.1f));
  CHECK(paper::pacman_mouth_half_angle == double(0.6f));
}

TEST_CASE("paper reference: camera directions and plane hits are the closed forms") {
  const paper::ReferenceScene s = paper::reference_scene(constants());
  const paper::ReferenceImage& r = truth();
  std::size_t plane_pixels = 0;
  for (std::uint32_t y = 0; y < H; ++y) {
    for (std::uint32_t x = 0; x < W; ++x) {
      const glm::dvec3 d = direction(x, y);
      CHECK(glm::length(paper::camera_direction(s, x, y, W, H) - d) <= 1e-15);
      const std::size_t i = y * W + x;
      if (r.objects[i] != paper::plane_id) continue;
      ++plane_pixels;
      const double t = -s.eye.y / d.y;  // y = 0
      CHECK(r.pixels[i].outcome == acc::Outcome::hit);
      CHECK(std::abs(r.pixels[i].t - t) <= 1e-12 * t);
      CHECK(r.pixels[i].normal == glm::dvec3(0.0, 1.0, 0.0));
    }
  }
  // The bottom row's middle pixel looks at open ground far from every object.
  CHECK(r.objects[(H - 1) * W + W / 2] == paper::plane_id);
  CHECK(plane_pixels > W * H / 3);  // seen: 864 - the objects in front
}

TEST_CASE("paper reference: rays that meet no bounds and no ground are misses") {
  const paper::ReferenceImage& r = truth();
  const glm::dvec3 eye = xyz(constants().camera.eye);
  std::size_t misses = 0;
  for (std::uint32_t y = 0; y < H; ++y) {
    for (std::uint32_t x = 0; x < W; ++x) {
      const glm::dvec3 d = direction(x, y);
      const std::size_t i = y * W + x;
      const glm::dvec3 ground = eye + (-eye.y / d.y) * d;
      bool meets = d.y < 0.0 && ground.x >= paper::plane_min.x && ground.x <= paper::plane_max.x &&
                   ground.z >= paper::plane_min.y && ground.z <= paper::plane_max.y;
      for (paper::ObjectId id : {paper::pacman0_id, paper::pacman1_id, paper::julia_id, paper::mandelbulb_id}) {
        const World w = world_of(id);
        const bool in_box = meets_box(eye, d, w.lo, w.hi);
        meets = meets || in_box;
        if (r.objects[i] == id) CHECK(in_box);  // a hit lies in its object's bounds
      }
      CHECK(r.pixels[i].outcome != acc::Outcome::undetermined);
      if (meets) continue;
      ++misses;
      CHECK(r.pixels[i].outcome == acc::Outcome::miss);
      CHECK(r.objects[i] == paper::sky_id);
    }
  }
  CHECK(misses > W * H / 4);  // the sky above the horizon
}

TEST_CASE("paper reference: fractal hits are entries of the shaders' own sets") {
  const paper::ReferenceImage& r = truth();
  const glm::dvec3 eye = xyz(constants().camera.eye);
  std::size_t hits[6] = {}, cut_face = 0, back_facing = 0;
  for (std::size_t i = 0; i < r.pixels.size(); ++i) {
    const paper::ObjectId id = r.objects[i];
    if (id != paper::julia_id && id != paper::mandelbulb_id) continue;
    ++hits[id];
    const glm::dvec3 d = direction(std::uint32_t(i % W), std::uint32_t(i / W));
    const World w = world_of(id);
    const double t = r.pixels[i].t, tol = 1e-9 * t;
    CAPTURE(i);
    CHECK_FALSE(estimate_inside(id, (eye + (t - tol) * d - w.translation) / w.scale));
    CHECK(estimate_inside(id, (eye + (t + tol) * d - w.translation) / w.scale));
    CHECK(std::abs(glm::length(r.pixels[i].normal) - 1.0) <= 1e-12);  // every fractal hit got a normal
    // At a footprint of ~0.2 (48x32) the bulb is rough: a crevice's normal may face away.
    back_facing += glm::dot(r.pixels[i].normal, d) >= 0.0;
    cut_face += r.pixels[i].normal == glm::normalize(glm::dvec3(paper::julia_cut_plane));
  }
  MESSAGE("fractal hits at 48x32: Julia " << hits[paper::julia_id] << " (" << cut_face << " on the cut face), Mandelbulb "
                                          << hits[paper::mandelbulb_id] << "; normals facing away " << back_facing);
  CHECK(hits[paper::julia_id] >= 20);       // seen: 37
  CHECK(cut_face >= 10);                    // seen: 33 (the cut removes the front: the camera sees the slice)
  CHECK(cut_face < hits[paper::julia_id]);  // seen: 4 on the set's own surface
  CHECK(hits[paper::mandelbulb_id] >= 30);  // seen: 56
  CHECK(back_facing * 10 <= hits[paper::julia_id] + hits[paper::mandelbulb_id]);  // seen: 5 of 93, all Mandelbulb
}

TEST_CASE("paper reference: pac-man hits equal pacman.glsl's interval CSG") {
  const paper::ReferenceImage& r = truth();
  const glm::dvec3 eye = xyz(constants().camera.eye);
  std::size_t hits = 0;
  for (std::size_t i = 0; i < r.pixels.size(); ++i) {
    const paper::ObjectId id = r.objects[i];
    const glm::dvec3 d = direction(std::uint32_t(i % W), std::uint32_t(i / W));
    for (paper::ObjectId pacman : {paper::pacman0_id, paper::pacman1_id}) {
      const World at = world_of(pacman);
      double s = 0.0;
      glm::dvec3 n(0.0);
      // Object space: origin (eye - T) / scale, direction d / scale, so the CSG's t is the world t.
      const bool csg = pac<double>::pacman_intersect((eye - at.translation) / at.scale, d / at.scale, double(0.6f), 0.0,
                                                      1e30, s, n);
      CAPTURE(i);
      if (id == pacman) {
        ++hits;
        REQUIRE(csg);
        CHECK(std::abs(r.pixels[i].t - s) <= 1e-9);
        CHECK(glm::length(r.pixels[i].normal - glm::normalize(n)) <= 1e-9);
      } else if (csg && r.pixels[i].outcome == acc::Outcome::hit) {
        CHECK(r.pixels[i].t < s);  // something nearer hides the Pac-man
      }
    }
  }
  CHECK(hits >= 60);  // seen: 104, both Pac-men
}

namespace {

struct Marched {
  bool hit = false;
  double t = 0.0;
};

/// One pixel marched as marching/field.glsl does on the GPU, in float: camera.glsl's ray, the object ray
/// (eye - T) / scale and dir / scale, clipped to the object's AABB, sphere traced along the unit
/// object direction with the paper's default knobs, t converted back by the direction's length.
template <int kind>
Marched march_ray(std::uint32_t x, std::uint32_t y, const World& w, const proceduray::Aabb& box) {
  using M = march<kind>;
  const paper::Frame& k = constants();
  const proceduray::Camera& cam = k.camera;
  const glm::vec2 uv = (glm::vec2(float(x), float(y)) + 0.5f) / glm::vec2(float(W), float(H)) * 2.0f - 1.0f;
  const glm::vec3 dir = glm::normalize(glm::vec3(cam.forward) + uv.x * glm::vec3(cam.right) - uv.y * glm::vec3(cam.up));
  const float scale = float(w.scale);
  const glm::vec3 o = (glm::vec3(cam.eye) - glm::vec3(w.translation)) / scale, d = dir / scale;
  float t0 = 0.0f, t1 = 1.0e30f;
  if (!M::ray_clip_aabb(o, d, box.min, box.max, t0, t1)) return {};
  const float len = glm::length(d);
  const float world_per_object = std::max(glm::length(dir) / len, 1.0e-20f);
  const typename M::MarchSettings m =
      M::march_settings(k.knobs[kind == 0 ? paper::mandelbulb_id : paper::julia_id], world_per_object, cam.pixel_angle, 1.0f);
  float s = 0.0f;
  std::uint32_t steps = 0;
  if (!M::field_trace(o, d / len, t0 * len, t1 * len, m, {M::count, M::c}, s, steps)) return {};
  return {true, double(s / len)};
}

struct Agreement {
  std::size_t both = 0, only_march = 0, only_reference = 0, behind = 0;
  std::size_t only_march_off_silhouette = 0;  ///< only the march hit, no reference hit within 1 pixel
  std::vector<double> front;                  ///< (t_ref - t_march) / footprint, both hit
};

/// Pixels that only the march hit and whose 3 x 3 neighbourhood has no reference hit.
std::size_t off_silhouette(const std::vector<bool>& march_hit, const std::vector<bool>& reference_hit) {
  std::size_t n = 0;
  for (std::uint32_t y = 0; y < H; ++y) {
    for (std::uint32_t x = 0; x < W; ++x) {
      if (!march_hit[y * W + x] || reference_hit[y * W + x]) continue;
      bool near = false;
      for (std::uint32_t yy = y > 0 ? y - 1 : 0; yy <= std::min(y + 1, H - 1); ++yy) {
        for (std::uint32_t xx = x > 0 ? x - 1 : 0; xx <= std::min(x + 1, W - 1); ++xx) near = near || reference_hit[yy * W + xx];
      }
      n += !near;
    }
  }
  return n;
}

/// The float march of one fractal, alone, against the reference of that object alone (no occlusion).
template <int kind>
Agreement compare(paper::ObjectId id, const proceduray::Aabb& box) {
  const paper::ReferenceScene s = paper::reference_scene(constants());
  Agreement a;
  std::vector<bool> march_hit(W * H), reference_hit(W * H);
  for (std::uint32_t y = 0; y < H; ++y) {
    for (std::uint32_t x = 0; x < W; ++x) {
      const acc::Result ref = paper::trace_object(s, id, s.eye, direction(x, y)).result;
      const Marched m = march_ray<kind>(x, y, world_of(id), box);
      REQUIRE(ref.outcome != acc::Outcome::undetermined);
      const bool hit = ref.outcome == acc::Outcome::hit;
      march_hit[y * W + x] = m.hit;
      reference_hit[y * W + x] = hit;
      a.only_march += m.hit && !hit;
      a.only_reference += hit && !m.hit;
      if (!(m.hit && hit)) continue;
      ++a.both;
      const double footprints = (ref.t - m.t) / (ref.t * s.pixel_angle);
      a.front.push_back(footprints);
      a.behind += footprints < -2.0;  // more than two footprints behind the reference
    }
  }
  a.only_march_off_silhouette = off_silhouette(march_hit, reference_hit);
  return a;
}

}  // namespace

TEST_CASE("paper reference: the float sphere tracer lands at the reference surface") {
  const paper::Frame& k = constants();
  march<0>::count = proceduray::glsl::mandelbulb<float>::mandelbulb_animated_iterations(k.knobs[paper::mandelbulb_id].iterations, k.time);
  march<1>::count = std::max(k.knobs[paper::julia_id].iterations, 1u);
  march<1>::c = proceduray::glsl::julia<float>::julia_animated_c(k.time);
  const Agreement bulb = compare<0>(paper::mandelbulb_id, paper::mandelbulb_aabb);
  const Agreement julia = compare<1>(paper::julia_id, paper::julia_aabb);
  for (const auto& [name, a] : {std::pair{std::string("Mandelbulb"), &bulb}, std::pair{std::string("Julia"), &julia}}) {
    std::vector<double> error(a->front.size());
    std::transform(a->front.begin(), a->front.end(), error.begin(), [](double f) { return std::abs(f); });
    MESSAGE(name << " alone at 48x32, float march vs reference: both hit " << a->both << ", only the march "
                 << a->only_march << " (" << a->only_march_off_silhouette << " off the silhouette), only the reference " << a->only_reference << ", more than 2 footprints behind "
                 << a->behind << "; |t_ref - t| in footprints: median " << percentile(error, 0.5) << " p99 "
                 << percentile(error, 0.99) << " max " << percentile(error, 1.0) << "; t_ref - t: min "
                 << percentile(a->front, 0.0) << " max " << percentile(a->front, 1.0));
  }
  // Seen: Mandelbulb 53 both, 0 only the march, 3 only the reference (parts thinner than the
  // probes, which grazing rays step over), Julia 37, 0 and 0; |t_ref - t| in footprints:
  // Mandelbulb median 0.010, max 1.13 (one hit behind the reference: probes stepped over a
  // thin part in front of the body), Julia median 0.0009, max 0.008 (within the 1/32-threshold
  // refinement everywhere; its cut face is exact). With the classic rule (stop below the
  // threshold): Mandelbulb 56 both, 23 only the march, Julia 37 and 29, every one of those
  // within a pixel of the reference silhouette (the threshold of half a footprint caught rays
  // that pass that close), none only the reference; every hit in front of the reference,
  // Mandelbulb by 0.64 to 4.9 footprints (median 1.37), Julia by 0.014 to 1.3 (median 0.07).
  CHECK(bulb.both >= 40);
  CHECK(julia.both >= 25);
  for (const Agreement* a : {&bulb, &julia}) {
    std::vector<double> error(a->front.size());
    std::transform(a->front.begin(), a->front.end(), error.begin(), [](double f) { return std::abs(f); });
    CHECK(a->only_march_off_silhouette == 0);
    CHECK(a->only_march <= 2);      // grazing rays are no longer hits
    CHECK(a->only_reference <= 4);  // but parts thinner than the probes may be missed
    CHECK(a->behind == 0);
    CHECK(percentile(error, 0.5) <= 0.1);
  }
  // Every march hit within 2.5 footprints of the reference (Mandelbulb), 0.05 (Julia).
  CHECK(percentile(bulb.front, 0.0) >= -2.5);
  CHECK(percentile(bulb.front, 1.0) <= 2.5);
  CHECK(percentile(julia.front, 0.0) >= -0.05);
  CHECK(percentile(julia.front, 1.0) <= 0.05);
}

TEST_CASE("paper reference: the mandelbulb reference converges at the default spacing") {
  // Spacing 1e-3 footprints (the default) against 1e-4: the reference's own error. Seen: no
  // class change, hits moved by at most 0.042 footprints (median 1e-12: the same crossing);
  // spacing 1e-2 changes 2 classes and moves hits by up to 1.13 footprints.
  const paper::ReferenceScene coarse = paper::reference_scene(constants());
  const paper::ReferenceScene fine = paper::reference_scene(constants(), {.spacing = 1.0e-4});
  std::size_t changed = 0, hits = 0;
  double worst = 0.0;
  for (std::uint32_t y = 0; y < H; ++y) {
    for (std::uint32_t x = 0; x < W; ++x) {
      const glm::dvec3 d = direction(x, y);
      const acc::Result a = paper::trace_object(coarse, paper::mandelbulb_id, coarse.eye, d).result;
      const acc::Result b = paper::trace_object(fine, paper::mandelbulb_id, fine.eye, d).result;
      changed += a.outcome != b.outcome;
      if (a.outcome != acc::Outcome::hit || b.outcome != acc::Outcome::hit) continue;
      ++hits;
      // Either may be the later one: the grids of the two spacings do not share points exactly,
      // and a run of the set ~1e-4 footprints long can fall between the finer grid's samples.
      worst = std::max(worst, std::abs(a.t - b.t) / (b.t * coarse.pixel_angle));
    }
  }
  MESSAGE("mandelbulb reference, spacing 1e-3 vs 1e-4 footprints: " << changed << " class changes, worst move " << worst
                                                                      << " footprints over " << hits << " hits");
  CHECK(changed <= 1);
  CHECK(worst <= 0.2);
  CHECK(hits >= 40);
}

TEST_CASE("paper reference: twice the iterations moves few fractal pixels") {
  const paper::ReferenceImage& once = truth();
  const paper::ReferenceImage twice = paper::reference_image(constants(), W, H, {.iteration_factor = 2});
  std::size_t changed[6] = {}, both[6] = {};
  std::vector<double> moved;  // |t_2x - t| in footprints where both hit the same object
  for (std::size_t i = 0; i < once.pixels.size(); ++i) {
    for (paper::ObjectId id : {paper::julia_id, paper::mandelbulb_id}) {
      const bool a = once.objects[i] == id, b = twice.objects[i] == id;
      changed[id] += a != b;
      both[id] += a && b;
      if (a && b) moved.push_back(std::abs(twice.pixels[i].t - once.pixels[i].t) / (once.pixels[i].t * once.pixel_angle));
    }
  }
  MESSAGE("2x iterations at 48x32: mask changes Mandelbulb " << changed[paper::mandelbulb_id] << " of "
                                                             << both[paper::mandelbulb_id] << ", Julia "
                                                             << changed[paper::julia_id] << " of " << both[paper::julia_id]
                                                             << "; depth moves median " << percentile(moved, 0.5)
                                                             << " max " << percentile(moved, 1.0) << " footprints");
  // Seen: Mandelbulb 0 of 56, Julia 0 of 37; depth moves median 0.0015, max 1.13 footprints:
  // at 48x32 truncation after 8 (10) iterations is far below what the march's threshold costs.
  CHECK(changed[paper::mandelbulb_id] <= 3);
  CHECK(changed[paper::julia_id] <= 3);
  CHECK(both[paper::mandelbulb_id] >= 40);
  CHECK(percentile(moved, 0.5) <= 0.1);
  CHECK(percentile(moved, 1.0) <= 4.0);
  CHECK(twice.evaluations > 0);
}

TEST_CASE("paper reference: a search out of budget makes its pixels undetermined, never wrong") {
  const paper::ReferenceImage& full = truth();
  const paper::ReferenceImage tight = paper::reference_image(constants(), W, H, {.budget = 200});
  std::size_t same = 0;
  for (std::size_t i = 0; i < full.pixels.size(); ++i) {
    const acc::Reference& a = full.pixels[i];
    const acc::Reference& b = tight.pixels[i];
    if (b.outcome == acc::Outcome::undetermined) continue;
    ++same;
    CHECK(b.outcome == a.outcome);
    CHECK(b.t == a.t);
    CHECK(tight.objects[i] == full.objects[i]);
  }
  CHECK(tight.undetermined > 20);                    // fractal rays need ~1e4 samples at this spacing
  CHECK(same + tight.undetermined == full.pixels.size());
  CHECK(full.undetermined == 0);
  CHECK(tight.evaluations < full.evaluations);
  // A ray from inside an object: undetermined at its start, as documented.
  const paper::ReferenceScene s = paper::reference_scene(constants());
  const acc::Result inside =
      paper::trace_object(s, paper::mandelbulb_id, glm::dvec3(paper::mandelbulb_placement.translation),
                          glm::dvec3(0.0, 0.0, 1.0)).result;
  CHECK(inside.outcome == acc::Outcome::undetermined);
  CHECK(inside.starts_inside);
}

TEST_CASE("paper reference: costs are counted per object") {
  const paper::ReferenceImage& r = truth();
  std::uint64_t sum = 0;
  for (paper::ObjectId id : paper::reference_objects) {
    const paper::ObjectCost& c = r.costs[id];
    sum += c.evaluations;
    CHECK(c.hits <= c.rays);
    CHECK(c.hit_evaluations <= c.evaluations);
  }
  CHECK(sum == r.evaluations);
  CHECK(r.costs[paper::plane_id].rays == W * H);
  CHECK(r.costs[paper::sky_id].rays == 0);
  const paper::ObjectCost& bulb = r.costs[paper::mandelbulb_id];
  MESSAGE("reference cost at 48x32: " << r.evaluations << " evaluations; per Mandelbulb hit ray "
                                      << bulb.hit_evaluations / bulb.hits << ", Julia hit ray "
                                      << r.costs[paper::julia_id].hit_evaluations / r.costs[paper::julia_id].hits
                                      << ", Pac-man hit ray "
                                      << r.costs[paper::pacman0_id].hit_evaluations / r.costs[paper::pacman0_id].hits);
  // Seen: 1989723 in all; per hit ray Mandelbulb 3591, Julia 6252, Pac-man 46.
  CHECK(bulb.hit_evaluations / bulb.hits > 1000);
}

TEST_CASE("paper reference: bad input is refused with the call, the value and the fix") {
  const auto message = [](auto&& call) {
    try {
      call();
    } catch (const proceduray::UsageError& e) {
      return std::string(e.what());
    }
    return std::string("(nothing thrown)");
  };
  const std::string size = message([] { paper::reference_image(constants(), 0, 32); });
  CHECK(size.find("paper::reference_image") != std::string::npos);
  CHECK(size.find("0x32") != std::string::npos);
  CHECK(size.find("pass width and height") != std::string::npos);
  paper::Frame bad = constants();
  bad.camera.eye.y = std::numeric_limits<float>::quiet_NaN();
  const std::string eye = message([&] { paper::reference_image(bad, W, H); });
  CHECK(eye.find("camera.eye") != std::string::npos);
  CHECK(eye.find("nan") != std::string::npos);
  CHECK(eye.find("look_at") != std::string::npos);
  bad = constants();
  bad.camera.pixel_angle = 0.0f;
  CHECK(message([&] { paper::reference_image(bad, W, H); }).find("camera.pixel_angle = 0") != std::string::npos);
  CHECK(message([] { paper::reference_image(constants(), W, H, {.spacing = -1.0}); }).find("options.spacing = -1") !=
        std::string::npos);
  CHECK(message([] { paper::reference_image(constants(), W, H, {.iteration_factor = 0}); }).find("iteration_factor") !=
        std::string::npos);
  const paper::ReferenceScene s = paper::reference_scene(constants());
  CHECK(message([&] { paper::trace_object(s, paper::sky_id, s.eye, glm::dvec3(0.0, 0.0, -1.0)); })
            .find("paper::trace_object: object id 0") != std::string::npos);
}

TEST_CASE("paper reference: a stratified reference is the full one where traced, and estimates its metrics") {
  // Stride 1 traces every pixel: reference_image's pixels and objects, every weight 1.
  const paper::ReferenceImage all = paper::stratified_reference_image(constants(), W, H, 1);
  REQUIRE(all.pixels.size() == truth().pixels.size());
  CHECK(all.objects == truth().objects);
  CHECK(all.traced == all.pixels.size());
  std::size_t same = 0;
  for (std::size_t i = 0; i < all.pixels.size(); ++i) {
    same += all.pixels[i].outcome == truth().pixels[i].outcome && all.pixels[i].t == truth().pixels[i].t &&
            all.weights[i] == 1u;
  }
  CHECK(same == all.pixels.size());
  // Stride 4 at 96 x 64: fewer pixels traced, each equal to the full reference's; a render whose
  // hits all lie 0.1 footprint behind the truth measures the same per object either way.
  const std::uint32_t w = 96, h = 64;
  const paper::Frame c = test_knobs::pinned(paper::default_frame(w, h, 0.0f));
  const paper::ReferenceImage full = paper::reference_image(c, w, h), sample = paper::stratified_reference_image(c, w, h, 4);
  CHECK(sample.traced < full.pixels.size() * 3 / 4);
  std::vector<proceduray::accuracy::Sample> render(full.pixels.size());
  std::size_t traced = 0, agree = 0;
  for (std::size_t i = 0; i < full.pixels.size(); ++i) {
    const proceduray::accuracy::Reference& r = full.pixels[i];
    if (sample.weights[i] > 0) {
      ++traced;
      agree += sample.pixels[i].t == r.t && sample.objects[i] == full.objects[i];
    }
    if (r.outcome != proceduray::accuracy::Outcome::hit) continue;
    render[i] = {.hit = true, .t = r.t * (1.0 + 0.1 * full.pixel_angle), .normal = r.normal, .steps = 10.0};
  }
  CHECK(traced > 0);
  CHECK(agree == traced);
  const std::vector<paper::ObjectId> seen = full.objects;
  for (const paper::ObjectId id : {paper::julia_id, paper::mandelbulb_id, paper::plane_id}) {
    CAPTURE(id);
    const proceduray::accuracy::Metrics a = paper::measure_object(full, render, seen, id);
    const proceduray::accuracy::Metrics b = paper::measure_object(sample, render, seen, id);
    CHECK(a.all.both_hit > 50);
    CHECK(b.all.depth.median == doctest::Approx(a.all.depth.median).epsilon(0.02));
    CHECK(b.all.depth.median == doctest::Approx(0.1).epsilon(0.02));
    CHECK(b.all.false_hits + b.all.false_misses == 0);
    // The hit count is estimated: within 10% of the full frame's.
    CHECK(double(b.all.both_hit) == doctest::Approx(double(a.all.both_hit)).epsilon(0.1));
  }
  CHECK_THROWS_AS(paper::stratified_reference_image(c, w, h, 0), proceduray::UsageError);
}
