// Normals by differences (shaders/marching/sphere_trace.glsl: central_normal, tetrahedral_normal,
// normal_offset), compiled as C++ in float, against closed-form normals (ACCURACY.md scenario 16).
// Why: differences fail two ways. A large offset h blurs (central differences O((h/r)^2), the
// tetrahedron's asymmetric samples O(h/r)); a small one cancels, and in float "small" is
// relative to |p|: p + h rounds by a different fraction per axis, so far from the origin an
// offset tied to the pixel footprint tilts the normal by degrees, and one under half a float
// spacing leaves p unchanged (the fallback normal). The shapes are moved up to 1e4 from the
// origin to grow that spacing; ground truth is the exact gradient of each shape's distance in
// double at the very float point the method sees, so rounding the surface point costs nothing.
#include <proceduray/shader/glsl_cpp.hpp>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <numbers>
#include <vector>

namespace normals_test {
using namespace proceduray::glsl_cpp;
// 0: unit sphere; 1: torus (ring radius 1 in the xz plane, tube 0.4); 2: rounded box (half
// extents 0.8, 0.6, 0.5 plus 0.1 rounding) turned by `turn`, so its face normals are not axes
// (an axis-aligned face gives exact normals at any h: only one difference is non-zero). All
// centred at `center`.
inline int shape = 0;
inline vec3 center(0.0f);
inline mat3 turn(1.0f);
inline float march_distance(vec3 p) {
  const vec3 q = p - center;
  if (shape == 0) return length(q) - 1.0f;
  if (shape == 1) return length(vec2(length(vec2(q.x, q.z)) - 1.0f, q.y)) - 0.4f;
  const vec3 d = abs(turn * q) - vec3(0.8f, 0.6f, 0.5f);
  return length(max(d, vec3(0.0f))) + min(max(d.x, max(d.y, d.z)), 0.0f) - 0.1f;
}
#include "marching/sphere_trace.glsl"
/// The marcher of this test's shape (marching/marcher.glsl): prefix shape, no field data.
struct Shape {};
inline float shape_distance(vec3 p, Shape) { return march_distance(p); }
#define PROCEDURAY_MARCHER shape
#define PROCEDURAY_MARCHER_FIELD Shape
#define PROCEDURAY_MARCHER_DISTANCE shape_distance
#include "marching/marcher.glsl"
}  // namespace normals_test

#include <doctest/doctest.h>

using namespace normals_test;

namespace {

constexpr int sphere = 0, torus = 1, box = 2;
constexpr double torus_tube = 0.4;
enum class Method { central, tetrahedral };

struct Sample {
  glm::vec3 p;   // the float point handed to the method
  glm::dvec3 n;  // the exact unit gradient of the shape's distance at p
};

glm::mat3 box_turn() {
  const double a = 0.5, b = 0.9;
  const glm::dmat3 rx(1.0, 0.0, 0.0, 0.0, std::cos(a), std::sin(a), 0.0, -std::sin(a), std::cos(a));
  const glm::dmat3 ry(std::cos(b), 0.0, -std::sin(b), 0.0, 1.0, 0.0, std::sin(b), 0.0, std::cos(b));
  return glm::mat3(rx * ry);
}

/// 64 surface points of `s` centred at c, by closed form in double, rounded to float; the normal
/// is the exact gradient at the rounded point (the box's: of the float-coefficient distance).
std::vector<Sample> surface(int s, glm::vec3 c) {
  const double pi = std::numbers::pi;
  const glm::dvec3 cd(c);
  const glm::dmat3 m(turn);
  std::vector<Sample> out;
  for (int i = 0; i < 64; ++i) {
    const double u = (i + 0.5) / 64.0;
    const double v = std::fmod(i * 0.6180339887498949, 1.0);
    if (s == sphere) {
      const double z = 2.0 * u - 1.0, r = std::sqrt(1.0 - z * z), phi = 2.0 * pi * v;
      const glm::vec3 p(cd + glm::dvec3(r * std::cos(phi), r * std::sin(phi), z));
      out.push_back({p, glm::normalize(glm::dvec3(p) - cd)});
    } else if (s == torus) {
      const glm::dvec3 ring(std::cos(2.0 * pi * u), 0.0, std::sin(2.0 * pi * u));
      const glm::dvec3 tube = std::cos(2.0 * pi * v) * ring + std::sin(2.0 * pi * v) * glm::dvec3(0.0, 1.0, 0.0);
      const glm::vec3 p(cd + ring + torus_tube * tube);
      const glm::dvec3 q = glm::dvec3(p) - cd;
      out.push_back({p, glm::normalize(q - glm::normalize(glm::dvec3(q.x, 0.0, q.z)))});
    } else {
      // On the six flat faces, at least 0.3 from their rounded edges: the distance is linear
      // there for offsets up to ~0.2, so any error is rounding, never blur.
      const double a = 2.0 * u - 1.0, b = 2.0 * v - 1.0, side = (i / 3) % 2 ? 1.0 : -1.0;
      const int axis = i % 3;
      glm::dvec3 local = axis == 0   ? glm::dvec3(0.9 * side, 0.3 * a, 0.25 * b)
                         : axis == 1 ? glm::dvec3(0.4 * a, 0.7 * side, 0.25 * b)
                                     : glm::dvec3(0.4 * a, 0.3 * b, 0.6 * side);
      glm::dvec3 face(0.0);
      face[axis] = side;
      const glm::vec3 p(cd + glm::inverse(m) * local);
      out.push_back({p, glm::normalize(glm::transpose(m) * face)});
    }
  }
  return out;
}

double angle_deg(glm::dvec3 a, glm::dvec3 b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * 180.0 / std::numbers::pi;
}

glm::vec3 normal(Method m, glm::vec3 p, float h) {
  return m == Method::central ? shape_central_normal(p, h, {}) : shape_tetrahedral_normal(p, h, {});
}

/// Centres |c| ~ distance in three directions: the components' float spacings differ, and
/// with them how p + h rounds per axis.
std::vector<glm::vec3> centres(double distance) {
  std::vector<glm::vec3> out;
  for (glm::dvec3 d : {glm::dvec3(1.0, 0.7, -0.4), glm::dvec3(-0.3, 1.0, 0.55), glm::dvec3(0.2, -0.5, -1.0)}) {
    out.emplace_back(glm::normalize(d) * distance);
  }
  return out;
}

/// The largest angle error (degrees) of method m over the surface points of shape s at every
/// centre at `distance`, with the offset h_of(p) for each point.
template <class H>
double worst(int s, double distance, Method m, H&& h_of) {
  shape = s;
  turn = box_turn();
  double e = 0.0;
  for (glm::vec3 c : centres(distance)) {
    center = c;
    for (const Sample& x : surface(s, c)) e = std::max(e, angle_deg(glm::dvec3(normal(m, x.p, h_of(x.p))), x.n));
  }
  center = glm::vec3(0.0f);
  return e;
}

double worst_at(int s, double distance, Method m, float h) {
  return worst(s, distance, m, [h](glm::vec3) { return h; });
}

/// The library's offset: the hit threshold, pixel angle 1e-3 rad at t = 2 .. 10 (2e-3 .. 1e-2).
std::vector<float> footprint_offsets() {
  const MarchSettings m{256u, 1e-5f, 1e-3f, 1.0f, 1.0f};
  std::vector<float> out;
  for (int k = 0; k <= 16; ++k) out.push_back(march_epsilon(m, 2.0f + 0.5f * k));
  return out;
}

/// The worst error over the footprint offsets, each raised by floor(h, p).
template <class Floor>
double worst_footprint(int s, double distance, Method m, Floor&& floor) {
  double e = 0.0;
  for (float h : footprint_offsets()) e = std::max(e, worst(s, distance, m, [&](glm::vec3 p) { return floor(h, p); }));
  return e;
}

/// h raised to c float spacings at p: normal_offset's rule with the factor as a parameter.
auto spacing_floor(float c) {
  return [c](float h, glm::vec3 p) {
    return std::max(h, c * 1.1920928955078125e-7f * std::max(std::abs(p.x), std::max(std::abs(p.y), std::abs(p.z))));
  };
}

constexpr double rad = 180.0 / std::numbers::pi;

}  // namespace

TEST_CASE("central and tetrahedral normals match closed-form normals at the origin") {
  // h = 1e-3 on unit-sized shapes: central differences are within rounding (seen 0.003 degree),
  // the tetrahedron's O(h) term leaves 0.03 (sphere) to 0.09 (torus tube, radius 0.4) degree.
  for (int s : {sphere, torus, box}) {
    CAPTURE(s);
    CHECK(worst_at(s, 0.0, Method::central, 1e-3f) < 0.01);
    CHECK(worst_at(s, 0.0, Method::tetrahedral, 1e-3f) < 0.2);
  }
  // A zero offset gives a zero gradient: the same fallback as tetrahedral_normal.
  shape = sphere;
  const glm::vec3 n = shape_central_normal(glm::vec3(0.6f, 0.0f, 0.8f), 0.0f, {});
  CHECK(n.x == 0.0f);
  CHECK(n.y == 1.0f);
  CHECK(n.z == 0.0f);
}

TEST_CASE("normals by differences blur as h grows on curved shapes") {
  // On a sphere of radius r the leading error terms are, with n the unit normal:
  //   central      h^2 / (2 r^2) times the part of (n_x^3, n_y^3, n_z^3) across n (at most 0.281)
  //   tetrahedral  h / r times the part of (n_y n_z, n_x n_z, n_x n_y) across n (at most 0.5):
  //                the four samples are not symmetric about p, so the mixed second derivatives
  //                survive, where the six central ones cancel every even term.
  // Seen at h = 0.1: central 0.079 degree (0.14 (h/r)^2 = 0.080), tetrahedral 2.80 (0.5 h/r =
  // 2.86); the bounds below are those leading terms plus ~15 % for the higher-order ones.
  for (float h : {0.1f, 0.03f}) {
    CAPTURE(h);
    CHECK(worst_at(sphere, 0.0, Method::central, h) / rad <= 0.16 * h * h);
    CHECK(worst_at(sphere, 0.0, Method::tetrahedral, h) / rad <= 0.55 * h);
  }
  for (int s : {sphere, torus}) {
    CAPTURE(s);
    for (Method m : {Method::central, Method::tetrahedral}) {
      CHECK(worst_at(s, 0.0, m, 1e-1f) > 10.0 * worst_at(s, 0.0, m, 1e-3f));
    }
    // The order: from h = 0.03 to 0.1 (x 3.33) an O(h^2) error grows x 11.1, an O(h) one x 3.33;
    // seen 11.0 on both (central), 3.28 and 3.50 (tetrahedral) on the sphere and the torus.
    const double central = worst_at(s, 0.0, Method::central, 0.1f) / worst_at(s, 0.0, Method::central, 0.03f);
    const double tetra = worst_at(s, 0.0, Method::tetrahedral, 0.1f) / worst_at(s, 0.0, Method::tetrahedral, 0.03f);
    CHECK(central > 8.0);
    CHECK(central < 15.0);
    CHECK(tetra > 2.5);
    CHECK(tetra < 4.5);
  }
}

TEST_CASE("normals by differences cancel when h nears the float spacing at p") {
  // |p| ~ 1e4 (float spacing 1.2e-4 .. 9.8e-4 per component): p + 1e-5 == p, every difference is
  // 0 and both methods return their fallback (0, 1, 0), whatever the surface (seen 151 to 178
  // degrees off at worst).
  for (int s : {sphere, torus, box}) {
    shape = s;
    turn = box_turn();
    for (glm::vec3 c : centres(1e4)) {
      center = c;
      for (const Sample& x : surface(s, c)) {
        for (Method m : {Method::central, Method::tetrahedral}) {
          const glm::vec3 n = normal(m, x.p, 1e-5f);
          CHECK(n == glm::vec3(0.0f, 1.0f, 0.0f));
        }
      }
    }
    center = glm::vec3(0.0f);
    CAPTURE(s);
    CHECK(worst_at(s, 1e4, Method::central, 1e-5f) > 90.0);
  }
  // A few spacings are not enough either: the rounding of p + h is a large part of h. Seen
  // (worst over shapes and methods, least of them): 19.6 degrees at |p| = 0 with h = 1e-7,
  // 10.5 at 1e2 with h = 1e-5 (1.3 spacings), 8.2 at 1e3 with h = 1e-4 (1.6 spacings).
  struct Case {
    double distance;
    float h;
    double at_least;
  };
  for (const Case k : {Case{0.0, 1e-7f, 10.0}, Case{1e2, 1e-5f, 5.0}, Case{1e3, 1e-4f, 4.0}}) {
    for (int s : {sphere, torus, box}) {
      for (Method m : {Method::central, Method::tetrahedral}) {
        CAPTURE(k.distance);
        CAPTURE(s);
        CHECK(worst_at(s, k.distance, m, k.h) > k.at_least);
      }
    }
  }
}

TEST_CASE("footprint offsets raised by normal_offset keep normals accurate out to 1e4") {
  // h = march_epsilon (1e-3 rad x t, t = 2 .. 10), raised by normal_offset to 64 float spacings.
  // Central: worst seen 0.305 degree (torus at 1e4); bound 0.5. Tetrahedral: its O(h) blur at the
  // footprint alone is 0.28 (sphere) and 0.93 (torus) degree; worst seen 0.96 out to 1e3 (bound
  // 1.5) and 6.7 at 1e4 (torus), where the floor makes the offset ~0.06 (bound 10).
  const auto raised = [](float h, glm::vec3 p) { return normal_offset(h, p); };
  for (double distance : {0.0, 1e2, 1e3, 1e4}) {
    for (int s : {sphere, torus, box}) {
      CAPTURE(distance);
      CAPTURE(s);
      const double central = worst_footprint(s, distance, Method::central, raised);
      const double tetra = worst_footprint(s, distance, Method::tetrahedral, raised);
      CHECK(central < 0.5);
      CHECK(tetra < (distance < 1e4 ? 1.5 : 10.0));
      if (s == box) {
        // A flat face: no blur, the two have the same rounding error (seen ratio 0.99 .. 1.06).
        CHECK(tetra < 2.0 * central + 1e-3);
        CHECK(central < 2.0 * tetra + 1e-3);
      } else if (distance == 0.0 || distance == 1e4) {
        // Curved: at the footprint the tetrahedron's O(h) term dominates (seen 159 x the central
        // error at the origin, 13 and 22 x at 1e4). Comparable only at h ~ 1e-4, near the origin,
        // where rounding dominates both (0.026 and 0.046 degree on the sphere).
        CHECK(tetra > 3.0 * central);
      }
    }
  }
  // Without the floor the footprint offset is 2 .. 40 spacings at 1e4: seen 4.96 .. 5.26 degrees.
  const auto plain = [](float h, glm::vec3) { return h; };
  for (int s : {sphere, torus, box}) {
    CAPTURE(s);
    CHECK(worst_footprint(s, 1e4, Method::central, plain) > 2.0);
  }
}

TEST_CASE("normal_offset keeps 64 float spacings and that factor is the window at 1e4") {
  CHECK(normal_offset_spacings == 64.0f);
  CHECK(normal_offset(1e-3f, glm::vec3(0.0f)) == 1e-3f);
  CHECK(normal_offset(1e-3f, glm::vec3(0.5f, -1.0f, 0.25f)) == 1e-3f);
  CHECK(normal_offset(0.0f, glm::vec3(-8192.0f, 1.0f, 2.0f)) == 0.0625f);  // 2^6 * 2^-23 * 2^13
  CHECK(normal_offset(1.0f, glm::vec3(-8192.0f, 1.0f, 2.0f)) == 1.0f);
  // 2^-23 |x| is at least the spacing above |x|, so the floor is at least 64 of them.
  for (float x : {1.0f, 3.0f, 100.0f, 1e3f, 8191.0f, 1e4f, 3e4f}) {
    CAPTURE(x);
    const float spacing = std::nextafter(x, 2.0f * x) - x;
    CHECK(normal_offset(0.0f, glm::vec3(0.0f, -x, 0.5f * x)) >= 64.0f * spacing);
  }
  // Which factor c: at 1e4 central differences (max over the shapes) stay under 0.5 degree only
  // for c in [32, 64] (seen 0.42 and 0.305). Fewer spacings leave the per-axis rounding (0.89 at
  // c = 16), more blur the torus tube (0.99 at 128, 3.7 at 256). Nearer the origin any c up to
  // 256 does (worst 0.15 at 1e3); the blur shows from c = 512 there (0.16, 0.65 at 1024).
  const auto at_1e4 = [](float c) {
    double e = 0.0;
    for (int s : {sphere, torus, box}) e = std::max(e, worst_footprint(s, 1e4, Method::central, spacing_floor(c)));
    return e;
  };
  CHECK(at_1e4(16.0f) > 0.6);
  CHECK(at_1e4(64.0f) < 0.5);
  CHECK(at_1e4(256.0f) > 2.0);
}
