// Stability scenario 13 (../shared/ACCURACY.md): shadow rays on every primitive, acne rate and
// contact leaks per way of starting the secondary ray. Why: a shadow ray that starts on the
// surface it left may hit that surface again (acne: black speckles), and one that starts too
// far off may start past a nearby occluder (a leak: light where there should be contact
// shadow). Which happens depends on the offset method and on the distance from the origin,
// since float hit points are only as good as the ulps of their coordinates there.
//
// Hit points come from the library's float code, in the object space of a translated instance
// (o - centre, as a translation-only instance transform gives): ray_sphere_first
// (primitives/spheres.glsl, on primitives/sphere.glsl's ray_sphere), ray_box (primitives/box.glsl)
// and sphere_trace + tetrahedral_normal (marching/sphere_trace.glsl) on an exact sphere SDF. The
// world hit point is o + t d in float, as the closest-hit shaders form it. The truth is the
// double closed form (accuracy/closed_form.hpp) of the same float ray: the true point p*, normal n*.
//
// Methods for the shadow ray's origin and t_min (scene scale 1):
//   none     p, t_min 0
//   tmin     p, t_min 1e-3 (what many samples do)
//   normal   p + 1e-4 n, t_min 0
//   ulps     offset_ray_origin(p, n) (common/ray.glsl, Waechter and Binder)
//   scene    offset_ray_origin(p + offset n, n), offset 0 for exact primitives and 2 thresholds
//            for marched ones: what examples/03_d3d12_scene and 02_paper_scene's shade.rchit do
//            (their comment says "twice as far out"; the paper scene passes its knobs' epsilon
//            for a procedural hit without steps, which none of its objects produces).
// Acne: the light is on n*'s side (and on the float normal's, else the shader traces nothing),
// so on a convex primitive the truth is "visible"; a hit of the float shadow ray against the same
// primitive in [t_min, distance to the light] is acne. No culling (the paper scene culls nothing;
// the D3D12 scene culls back faces, which hides an origin inside the primitive).
// Leaks: a sphere occluder of radius 4 sits a gap g above p* along n*, the light behind it
// (truth: blocked, checked in double from p*). The occluder is thin: only its front face counts
// (cull back faces, as the D3D12 scene's shadow rays do), so an origin inside it or past it is
// a leak. The leak gap is the largest true gap at which any sample leaks.
//
// Set PROCEDURAY_SHADOW_TABLE=1 to print the measured table.
#include <proceduray/shader/glsl_cpp.hpp>

namespace shadow_offset_test {
using namespace proceduray::glsl_cpp;
/// The marched primitive: the unit sphere's exact distance in object space (Lipschitz 1).
inline float march_distance(vec3 p) { return length(p) - 1.0f; }
#include "primitives/box.glsl"
#include "primitives/spheres.glsl"
#include "marching/sphere_trace.glsl"
/// The marcher of this test's shape (marching/marcher.glsl): prefix shape, no field data.
struct Shape {};
inline float shape_distance(vec3 p, Shape) { return march_distance(p); }
#define PROCEDURAY_MARCHER shape
#define PROCEDURAY_MARCHER_FIELD Shape
#define PROCEDURAY_MARCHER_DISTANCE shape_distance
#include "marching/marcher.glsl"
}  // namespace shadow_offset_test

#include <doctest/doctest.h>

#include "proceduray/accuracy/closed_form.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>

namespace {

namespace so = shadow_offset_test;
namespace acc = proceduray::accuracy;

enum Primitive { sphere, box, marched, primitive_count };
enum Method { none, tmin, normal, ulps, scene, method_count };
constexpr std::array<const char*, primitive_count> primitive_names = {"sphere", "box", "marched sphere"};
constexpr std::array<const char*, method_count> method_names = {"none", "tmin 1e-3", "normal 1e-4", "offset_ray_origin",
                                                                "paper scene"};
constexpr std::array<double, 3> distances = {0.0, 1.0e2, 1.0e4};
constexpr int distance_count = static_cast<int>(distances.size());

constexpr float fixed_tmin = 1.0e-3f;    // method tmin: a common sample value, scene scale 1
constexpr float fixed_offset = 1.0e-4f;  // method normal: 1e-4 scene scales
constexpr float light_distance = 10.0f;
constexpr float occluder_radius = 4.0f;  // big enough to cover gaps up to 0.5 at 60 degrees
// The paper scene's defaults: epsilon 1e-4 world units, threshold growth 0.5 pixel footprints
// per unit distance at a pixel angle of ~1 mrad (1000 pixels over ~1 radian).
const so::MarchSettings march{512u, 1.0e-4f, 0.5f * 1.0e-3f, 1.0f, 1.0f};

constexpr int acne_samples = 3000;  // camera rays per primitive and distance
constexpr int leak_samples = 300;   // of those, how many get an occluder sweep

/// Spacing of floats at x (one ulp of |x|).
double ulp(float x) {
  const float a = std::abs(x);
  return static_cast<double>(std::nextafter(a, std::numeric_limits<float>::infinity()) - a);
}
/// A double point rounded to float, out of line: GCC 12.2's SLP vectorizer at -O2 was seen to
/// widen an inline glm::vec3(dvec3) back to double without the rounding (clang and -O1 round),
/// which made the truth for the occluder disagree with the float code by up to 1.5e-4 at 1e4.
[[gnu::noinline]] glm::vec3 to_float(glm::dvec3 v) { return glm::vec3(v); }
double max_abs(glm::vec3 v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

/// Uniforms from mt19937's raw output, so every standard library draws the same numbers.
struct Random {
  std::mt19937 gen;
  explicit Random(std::uint32_t seed) : gen(seed) {}
  double uniform() { return static_cast<double>(gen() >> 8) * 0x1.0p-24; }
  glm::dvec3 unit() {
    for (;;) {
      const glm::dvec3 v(2.0 * uniform() - 1.0, 2.0 * uniform() - 1.0, 2.0 * uniform() - 1.0);
      const double len2 = glm::dot(v, v);
      if (len2 > 1.0e-4 && len2 <= 1.0) return v / std::sqrt(len2);
    }
  }
};

/// The primitive: centred on `centre` (world), a sphere or the box [-1, 1]^3 in object space.
struct Object {
  Primitive kind;
  glm::vec3 centre;
  float radius = 1.0f;  // sphere only (the occluder's); the marched sphere is the unit one
};

/// A float hit as a shader sees it: t, the object-space unit normal, and for marches the threshold.
struct FloatHit {
  float t = 0.0f;
  glm::vec3 n{0.0f};
  float threshold = 0.0f;
};

/// The library's float intersection of the world ray (o, d) with the object, t in [t_lo, t_hi].
/// `front_only` culls back faces (a ray leaving through the surface). d must be unit length.
bool intersect(const Object& obj, glm::vec3 o, glm::vec3 d, float t_lo, float t_hi, FloatHit& hit,
               bool front_only = false) {
  const glm::vec3 oo = o - obj.centre;  // a translation-only instance's object-space origin
  const std::uint32_t cull = front_only ? so::hit_cull_back : 0u;
  switch (obj.kind) {
    case sphere:
      return so::ray_sphere_first(oo, d, glm::vec3(0.0f), obj.radius, t_lo, t_hi, cull, hit.t, hit.n);
    case box:
      return so::ray_box(oo, d, glm::vec3(-1.0f), glm::vec3(1.0f), t_lo, t_hi, cull, hit.t, hit.n);
    default: {
      float s = 0.0f;
      std::uint32_t steps = 0u;
      if (!so::shape_trace(oo, d, t_lo, t_hi, march, {}, s, steps)) return false;
      hit.t = s;
      hit.threshold = so::march_epsilon(march, s);
      hit.n = so::shape_tetrahedral_normal(oo + s * d, std::max(hit.threshold, 1.0e-5f), {});
      return true;
    }
  }
}

/// The double closed form for the same primitive (the marched one is the exact sphere).
acc::Result truth(const Object& obj, glm::dvec3 o, glm::dvec3 d, double t_lo, double t_hi) {
  const glm::dvec3 c(obj.centre);
  if (obj.kind == box) return acc::intersect_box(o, d, c - 1.0, c + 1.0, t_lo, t_hi);
  return acc::intersect_sphere(o, d, c, 1.0, t_lo, t_hi);
}

/// The shadow ray's origin and t_min for a method, from the float hit point p and normal n.
struct ShadowStart {
  glm::vec3 origin;
  float t_min;
};
ShadowStart start(Method m, glm::vec3 p, glm::vec3 n, const FloatHit& hit) {
  switch (m) {
    case none: return {p, 0.0f};
    case tmin: return {p, fixed_tmin};
    case normal: return {p + fixed_offset * n, 0.0f};
    case ulps: return {so::offset_ray_origin(p, n), 0.0f};
    default: return {so::offset_ray_origin(p + 2.0f * hit.threshold * n, n), 0.0f};
  }
}

/// One camera hit with the float and the true point.
struct Sample {
  glm::vec3 p;       // float world hit point
  glm::vec3 n;       // float unit normal (world = object for a translation)
  FloatHit hit;
  glm::dvec3 p_true;
  glm::dvec3 n_true;
};

struct Cell {
  int rays = 0;                 // shadow rays traced (acne test)
  int acne = 0;                 // of which hit their own primitive
  int inside = 0;               // origins inside the primitive (double)
  int leak_samples = 0;         // samples whose leak gap was measured
  double leak_gap = 0.0;        // largest leak gap over the samples
  double leak_over_bound = 0.0; // max over samples of leak gap / offset_ray_origin's bound (ulps)
};

struct Measurement {
  Cell cell[primitive_count][distance_count][method_count];
  int samples[primitive_count][distance_count] = {};
  double max_hit_error[primitive_count][distance_count] = {};  // |p - p*|
  double ulp_bound[primitive_count][distance_count] = {};      // max of offset_ray_origin's per-sample bound
  double max_threshold[distance_count] = {};
  // Marched sphere, per sample: the leak gap the scene's 2-threshold offset adds over
  // offset_ray_origin alone, in thresholds; the largest excess over its own bound, the mean.
  double extra_excess[distance_count] = {};
  double extra_mean[distance_count] = {};
};

/// Camera rays from ~4 units away towards points inside the object's box, until `count` hit in
/// float and in truth; every primitive at every distance uses its own fixed seed.
std::vector<Sample> camera_hits(const Object& obj, int count, std::uint32_t seed) {
  Random rng(seed);
  std::vector<Sample> out;
  int tries = 0;
  while (static_cast<int>(out.size()) < count && tries < 10 * count) {
    ++tries;
    const glm::vec3 o = obj.centre + to_float((3.0 + rng.uniform()) * rng.unit());
    const glm::vec3 target =
        obj.centre + to_float(0.9 * glm::dvec3(2.0 * rng.uniform() - 1.0, 2.0 * rng.uniform() - 1.0,
                                               2.0 * rng.uniform() - 1.0));
    const glm::vec3 d = so::safe_normalize(target - o, glm::vec3(0.0f, 0.0f, 1.0f));
    FloatHit hit;
    if (!intersect(obj, o, d, 0.0f, 100.0f, hit)) continue;
    const acc::Result r = truth(obj, glm::dvec3(o), glm::dvec3(d), 0.0, 100.0);
    if (r.outcome != acc::Outcome::hit || r.starts_inside) continue;
    Sample s;
    s.p = o + hit.t * d;  // gl_WorldRayOriginEXT + gl_HitTEXT * gl_WorldRayDirectionEXT
    s.n = hit.n;
    s.hit = hit;
    s.p_true = glm::dvec3(o) + r.t * glm::dvec3(d);
    s.n_true = r.normal;
    out.push_back(s);
  }
  return out;
}

/// A light direction on n*'s side with cos(n*, l) >= min_cos and on the float normal's side.
bool light_direction(Random& rng, const Sample& s, double min_cos, glm::dvec3& l) {
  for (int i = 0; i < 100; ++i) {
    l = rng.unit();
    if (glm::dot(l, s.n_true) < 0.0) l = -l;
    if (glm::dot(l, s.n_true) >= min_cos && glm::dot(glm::vec3(l), s.n) > 0.0f) return true;
  }
  return false;
}

/// The shader's shadow ray towards the world light position: direction and distance in float.
void towards(glm::vec3 p, glm::vec3 light, glm::vec3& dir, float& dist) {
  const glm::vec3 to_light = light - p;
  dist = glm::length(to_light);
  dir = so::safe_normalize(to_light, glm::vec3(0.0f, 1.0f, 0.0f));
}

/// offset_ray_origin's own displacement bound from p: int_scale = 256 ulps of the largest
/// coordinate (|n_i| <= 1 in each; counted at the far end o, since the step may cross into the
/// next binade), or float_scale = 2^-16 for coordinates within 1/32 of 0. Plus 4 ulps at the
/// occluder's object-space scale (its radius 4): the float occluder test's own error.
double ulps_offset_bound(glm::vec3 p, glm::vec3 o) {
  return std::max(256.0 * ulp(static_cast<float>(std::max(max_abs(p), max_abs(o)))), 0x1.0p-16) + 4.0 * ulp(4.0f);
}

/// The leak gap of one shadow start: the true gap (above p*, along n*) of an occluder that the
/// shadow ray just misses, found by bisection over log2 of the nominal gap in [2^-40, 2^-1]
/// (leaks below the origin's height, none above); 0 when even 2^-40 is detected.
double leak_gap(const Sample& s, glm::dvec3 l, Method method) {
  const glm::vec3 light = to_float(s.p_true + static_cast<double>(light_distance) * l);
  glm::vec3 dir;
  float dist;
  towards(s.p, light, dir, dist);
  const ShadowStart st = start(method, s.p, s.n, s.hit);
  double last_leak = 0.0;
  // true: leaks, or the float centre moved the occluder onto p* (below any gap that matters).
  const auto probe = [&](double log2_gap) {
    const double gap = std::exp2(log2_gap);
    const glm::vec3 centre = to_float(s.p_true + (gap + static_cast<double>(occluder_radius)) * s.n_true);
    const glm::dvec3 c(centre);
    const double true_gap = glm::length(s.p_true - c) - static_cast<double>(occluder_radius);
    if (!(true_gap > 0.0)) return true;
    const acc::Result blocked =
        acc::intersect_sphere(s.p_true, glm::dvec3(light) - s.p_true, c, static_cast<double>(occluder_radius), 0.0, 1.0);
    REQUIRE(blocked.outcome == acc::Outcome::hit);  // truth: the occluder is between p* and the light
    REQUIRE_FALSE(blocked.starts_inside);
    FloatHit ignored;
    const bool leak = !intersect(Object{sphere, centre, occluder_radius}, st.origin, dir, st.t_min, dist, ignored, true);
    if (leak) last_leak = std::max(last_leak, true_gap);
    return leak;
  };
  double lo = -40.0, hi = -1.0;
  if (probe(hi)) return last_leak;  // leaks everywhere tested: the bounds below catch it
  if (!probe(lo)) return 0.0;
  for (int i = 0; i < 24; ++i) {
    const double mid = 0.5 * (lo + hi);
    (probe(mid) ? lo : hi) = mid;
  }
  return last_leak;
}

/// Acne of every method for sample s, lit by a random light on the normal's side.
void measure_acne(Measurement& m, const Object& obj, int pk, int k, const Sample& s, Random& rng) {
  // Any light on the normal's side; grazing ones are the hard cases.
  glm::dvec3 l;
  if (!light_direction(rng, s, 1.0e-3, l)) return;
  const glm::vec3 light = to_float(s.p_true + static_cast<double>(light_distance) * l);
  glm::vec3 dir;
  float dist;
  towards(s.p, light, dir, dist);
  for (int mk = 0; mk < method_count; ++mk) {
    const ShadowStart st = start(static_cast<Method>(mk), s.p, s.n, s.hit);
    Cell& c = m.cell[pk][k][mk];
    FloatHit ignored;
    ++c.rays;
    if (intersect(obj, st.origin, dir, st.t_min, dist, ignored)) ++c.acne;
    const acc::Result in = truth(obj, glm::dvec3(st.origin), glm::dvec3(dir), 0.0, 1.0e-30);
    if (in.starts_inside) ++c.inside;
  }
}

/// Leaks of every method for sample s: the light behind the occluder, steep enough (cos >= 0.5)
/// that the radius-4 occluder covers the way to it at every gap up to 2^-1. Returns whether
/// the marched primitive's scene - ulps gap was measured.
bool measure_leaks(Measurement& m, int pk, int k, const Sample& s, double bound, Random& rng) {
  glm::dvec3 l;
  if (!light_direction(rng, s, 0.5, l)) return false;
  std::array<double, method_count> gaps{};
  for (int mk = 0; mk < method_count; ++mk) {
    gaps[mk] = leak_gap(s, l, static_cast<Method>(mk));
    Cell& c = m.cell[pk][k][mk];
    ++c.leak_samples;
    c.leak_gap = std::max(c.leak_gap, gaps[mk]);
    c.leak_over_bound = std::max(c.leak_over_bound, gaps[mk] / bound);
  }
  if (pk != marched) return false;
  // The scene's origin is offset_ray_origin's from p + 2 thr n: the same ulps on a point
  // 2 thr higher, give or take the rounding of p + 2 thr n and the float grid of the
  // occluder centres behind both measured gaps (sqrt(3) / 2 ulps of the largest
  // coordinate each), and n's angle to n* (which only lowers it).
  const double thr = static_cast<double>(s.hit.threshold);
  const double extra = gaps[scene] - gaps[ulps];
  const double rounding = 3.0 * std::sqrt(3.0) * 0.5 * ulp(static_cast<float>(max_abs(s.p)));
  m.extra_excess[k] = std::max(m.extra_excess[k], (extra - 2.0 * thr - rounding) / thr);
  m.extra_mean[k] += extra / thr;
  return true;
}

/// One primitive at one distance: hit errors, bounds, acne and leaks of every method.
void measure_cell(Measurement& m, int pk, int k, int& extra_count) {
  const glm::dvec3 axis = glm::normalize(glm::dvec3(0.8, 0.5, 0.33));  // every coordinate far from 0
  const Object obj{static_cast<Primitive>(pk), to_float(distances[k] * axis)};
  const std::vector<Sample> hits = camera_hits(obj, acne_samples, 1000u + 10u * k + pk);
  m.samples[pk][k] = static_cast<int>(hits.size());
  Random rng(7000u + 10u * k + pk);
  for (std::size_t i = 0; i < hits.size(); ++i) {
    const Sample& s = hits[i];
    const double hit_error = glm::length(glm::dvec3(s.p) - s.p_true);
    m.max_hit_error[pk][k] = std::max(m.max_hit_error[pk][k], hit_error);
    // offset_ray_origin leaks up to its displacement plus the float point's own error
    // (for a march that includes the up to 1/32 threshold it reports outside the crossing).
    const double bound = hit_error + ulps_offset_bound(s.p, start(ulps, s.p, s.n, s.hit).origin);
    m.ulp_bound[pk][k] = std::max(m.ulp_bound[pk][k], bound);
    if (pk == marched) m.max_threshold[k] = std::max(m.max_threshold[k], static_cast<double>(s.hit.threshold));
    measure_acne(m, obj, pk, k, s, rng);
    // Leaks, on the first samples only.
    if (static_cast<int>(i) < leak_samples && measure_leaks(m, pk, k, s, bound, rng)) ++extra_count;
  }
}

/// The table behind the numbers, with PROCEDURAY_SHADOW_TABLE set.
void print_table(const Measurement& m) {
  std::printf("%-15s %-8s %-18s %10s %10s %7s %11s\n", "primitive", "distance", "method", "acne rate", "leak gap",
              "inside", "leak/bound");
  for (int pk = 0; pk < primitive_count; ++pk) {
    for (int k = 0; k < distance_count; ++k) {
      for (int mk = 0; mk < method_count; ++mk) {
        const Cell& c = m.cell[pk][k][mk];
        std::printf("%-15s %-8.0e %-18s %10.5f %10.3e %7d %11.3f\n", primitive_names[pk], distances[k],
                    method_names[mk], c.rays > 0 ? static_cast<double>(c.acne) / c.rays : 0.0, c.leak_gap,
                    c.inside, c.leak_over_bound);
      }
      std::printf("  %d hits (%d lit, %d leak sweeps), max |p - p*| %.3e, ulps bound %.3e\n", m.samples[pk][k],
                  m.cell[pk][k][0].rays, m.cell[pk][k][0].leak_samples, m.max_hit_error[pk][k], m.ulp_bound[pk][k]);
      if (pk == marched) {
        std::printf("  max threshold %.3e, scene - ulps leak: mean %.3f thr, max excess over 2 thr + rounding %.4f thr\n",
                    m.max_threshold[k], m.extra_mean[k], m.extra_excess[k]);
      }
    }
  }
}

const Measurement& measure() {
  static const Measurement result = [] {
    Measurement m{};
    for (int k = 0; k < distance_count; ++k) {
      int extra_count = 0;
      for (int pk = 0; pk < primitive_count; ++pk) measure_cell(m, pk, k, extra_count);
      m.extra_mean[k] /= std::max(extra_count, 1);
    }
    if (std::getenv("PROCEDURAY_SHADOW_TABLE") != nullptr) print_table(m);
    return m;
  }();
  return result;
}

}  // namespace

TEST_CASE("offset_ray_origin moves each coordinate by ulps or by 2^-16 near the origin") {
  // Far from the origin: 256 |n_i| ulps of each coordinate, away from the surface on both signs.
  const glm::vec3 p(1.0e4f, -1.0e4f, 3.0f);
  const glm::vec3 o = so::offset_ray_origin(p, glm::vec3(1.0f, 0.0f, 0.0f));
  CHECK(o.x == std::nextafter(p.x, 2.0e4f) + 255.0f * static_cast<float>(ulp(p.x)));  // 256 ulps, same binade
  CHECK(o.y == p.y);
  CHECK(o.z == p.z);
  const glm::vec3 q = so::offset_ray_origin(p, glm::vec3(0.0f, -1.0f, 0.0f));
  CHECK(q.y < p.y);
  CHECK(static_cast<double>(p.y - q.y) == doctest::Approx(256.0 * ulp(p.y)));
  // Near the origin ulps are tiny: a fixed 2^-16 along n instead.
  const glm::vec3 r = so::offset_ray_origin(glm::vec3(0.0f, 0.01f, -0.02f), glm::vec3(0.0f, 0.0f, -1.0f));
  CHECK(r.z == -0.02f - 0x1.0p-16f);
  CHECK(r.x == 0.0f);
}

TEST_CASE("shadow acne per offset method on sphere and box and marched sphere") {
  const Measurement& m = measure();
  for (int pk = 0; pk < primitive_count; ++pk) {
    for (int k = 0; k < distance_count; ++k) {
      CAPTURE(primitive_names[pk]);
      CAPTURE(distances[k]);
      // Nearly every aimed camera ray hits; a broken hit path must not pass as "no acne".
      REQUIRE(m.samples[pk][k] == acne_samples);
      REQUIRE(m.cell[pk][k][ulps].rays > acne_samples / 2);
      CHECK(m.cell[pk][k][ulps].acne == 0);
      CHECK(m.cell[pk][k][scene].acne == 0);
    }
  }
  // The failure mode exists: starting on the surface with t_min 0 finds the surface again on
  // both exact primitives, at some distance from the origin.
  for (int pk : {sphere, box}) {
    CAPTURE(primitive_names[pk]);
    int acne = 0;
    for (int k = 0; k < distance_count; ++k) acne += m.cell[pk][k][none].acne;
    CHECK(acne > 0);
  }
  // A fixed t_min of 1e-3 holds near the origin but not at 1e4, where the float hit point is
  // off the curved surface by ~ulp(1e4) = 1e-3 and grazing shadow rays meet it again past t_min
  // (measured ~4.5 % on both spheres; the box's flat faces give t ~ 0 and stay clean).
  for (int pk : {sphere, marched}) {
    CAPTURE(primitive_names[pk]);
    CHECK(m.cell[pk][0][tmin].acne == 0);
    CHECK(m.cell[pk][1][tmin].acne == 0);
    CHECK(m.cell[pk][2][tmin].acne > 0);
  }
}

TEST_CASE("contact leak gap per offset method") {
  const Measurement& m = measure();
  for (int pk = 0; pk < primitive_count; ++pk) {
    for (int k = 0; k < distance_count; ++k) {
      CAPTURE(primitive_names[pk]);
      CAPTURE(distances[k]);
      const Cell* c = m.cell[pk][k];
      REQUIRE(c[ulps].leak_samples > leak_samples / 2);
      // offset_ray_origin leaks only within its own displacement (256 ulps of the largest
      // coordinate, or 2^-16 near the origin) plus the float hit point's error, per sample.
      CHECK(c[ulps].leak_over_bound <= 1.0);
      // A fixed t_min skips an occluder up to t_min along the ray: gaps near t_min leak
      // (cos >= 0.5 and the gap grid's factor 2^0.25 leave more than t_min / 4).
      CHECK(c[tmin].leak_gap >= 0.25 * static_cast<double>(fixed_tmin));
      CHECK(c[tmin].leak_gap <= static_cast<double>(fixed_tmin) + m.ulp_bound[pk][k]);
      if (pk == marched) continue;
      // The normal offset leaks below its 1e-4 where the float spacing can hold it (up to
      // ulp/2 = 1e-3 at 1e4 it rounds away, and then it is no better than none).
      if (ulp(static_cast<float>(distances[k] + 2.0)) < 0.5 * static_cast<double>(fixed_offset)) {
        CHECK(c[normal].leak_gap >= 0.5 * static_cast<double>(fixed_offset));
      }
      CHECK(c[normal].leak_gap <= static_cast<double>(fixed_offset) + m.ulp_bound[pk][k]);
    }
  }
}

TEST_CASE("marched sphere with the paper scene offset starts outside and leaks about two thresholds") {
  const Measurement& m = measure();
  for (int k = 0; k < distance_count; ++k) {
    CAPTURE(distances[k]);
    const Cell& c = m.cell[marched][k][scene];
    // sphere_trace reports the outside end and the offset adds to it: never inside (double).
    CHECK(c.inside == 0);
    // The price of starting 2 thresholds off the surface: occluders that near go unseen. Per
    // sample, what the scene adds over offset_ray_origin alone is at most 2 thresholds plus the
    // float rounding above (measured: 0.13 threshold left over at 1e4 with one rounding term); 1/32 threshold of margin for the bisection and a changed ulp
    // spacing between p and p + 2 thr n (both ~0.01 threshold).
    CHECK(m.extra_excess[k] <= 1.0 / 32.0);
    // ...and about 2 thresholds on average: the known cost is real (n is within a few degrees
    // of n*, and the rounding averages out).
    CHECK(m.extra_mean[k] >= 1.5);
    CHECK(m.extra_mean[k] <= 2.0 + 1.0 / 32.0);
  }
}
