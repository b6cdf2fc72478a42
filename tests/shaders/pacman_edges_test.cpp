// Stability scenario 12 of ACCURACY.md: pacman.glsl's interval CSG in float on the rays where
// its arithmetic is most fragile: rays lying in a wedge face's plane (dot(n, d) = 0 in exact
// arithmetic, tiny and of either sign in float), rays along the hinge (both planes at once),
// rays through the hinge at grazing angles 1e-1 .. 1e-6 rad to a face, and axis-parallel rays.
// Why: a wrong sign of dot(n, d) flips which end of the wedge interval a plane bounds, and a
// near-zero divisor turns rounding into a huge t; either could report a hit on the wrong face
// or a NaN.
// Ground truth in double, not pacman.glsl's interval code: every candidate boundary (the two
// sphere roots from accuracy::intersect_sphere, the two plane crossings) is sorted, and the
// solid's membership (inside the sphere, not in both half-spaces) is tested between them; the
// first candidate where membership changes is the hit, its normal the piece's.
// Float resolution: float rounds o, d, n by ~2^-24 of their size, so a point's side of a face
// plane is known only when its distance from the plane exceeds k 2^-24 (|o| + t |d|).
#include <proceduray/shader/glsl_cpp.hpp>

namespace pacman_edges_test {
using namespace proceduray::glsl_cpp;
#include "primitives/pacman.glsl"
}  // namespace pacman_edges_test

#include <proceduray/accuracy/closed_form.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

namespace acc = proceduray::accuracy;
const float half_angle = 0.6f;  // the paper scene's mouth half-angle (pacman.rint)
const double unit_roundoff = std::ldexp(1.0, -24);

/// Resolution factor k: a ray whose hit lies within k 2^-24 (|o| + t |d| + 1) of a face plane
/// (or that runs within 16 2^-24 of parallel to one, closer to it than that) may be classified
/// either way. Measured: no misclassified resolved ray at k = 16 (g++ -O2 and clang++ -O2).
constexpr double resolution_k = 16.0;
/// t error bound where both hit and the class is resolved: C 2^-24 (|o| + t |d| + 1) / sin(incidence
/// on the hit piece), a length. Measured: worst error 0.049 of this bound at C = 16 (C ~ 0.8).
constexpr double t_error_c = 16.0;
/// Normal angle bound (radians) where both hit: measured 2.3e-7 at most; 1e-4 leaves margin and
/// still rules out the wrong piece (the faces' and the sphere's normals differ by > 0.1 rad there).
constexpr double normal_bound = 1.0e-4;

glm::dvec3 face_normal(int j) {  // n_j of pacman.glsl in double, from the float half-angle
  const double c = std::cos(double(half_angle)), s = std::sin(double(half_angle));
  return {0.0, j == 1 ? c : -c, -s};
}

bool solid(glm::dvec3 p) {
  return glm::dot(p, p) <= 1.0 && !(glm::dot(face_normal(1), p) <= 0.0 && glm::dot(face_normal(2), p) <= 0.0);
}

struct Truth {
  bool hit = false;
  double t = 0;
  glm::dvec3 normal{0.0};
  double plane_gap = 1e300;  ///< distance of the hit (or the nearest candidate) from a face plane
};

Truth truth(glm::dvec3 o, glm::dvec3 d) {
  std::vector<std::pair<double, int>> cand;  // t, piece (0 sphere, 1, 2 face)
  const acc::Result in = acc::intersect_sphere(o, d, glm::dvec3(0.0), 1.0, 0.0, 1e30);
  if (in.outcome != acc::Outcome::hit) return {};
  cand.push_back({in.t, 0});
  if (!in.starts_inside) {
    const acc::Result out = acc::intersect_sphere(o, d, glm::dvec3(0.0), 1.0, in.t * (1 + 1e-12) + 1e-12, 1e30);
    if (out.outcome == acc::Outcome::hit) cand.push_back({out.t, 0});
  }
  for (int j = 1; j <= 2; ++j) {
    const double dn = glm::dot(face_normal(j), d);
    if (dn != 0.0) cand.push_back({-glm::dot(face_normal(j), o) / dn, j});
  }
  std::sort(cand.begin(), cand.end());
  Truth r;
  for (std::size_t i = 0; i < cand.size(); ++i) {
    const double t = cand[i].first;
    if (t < 0.0) continue;
    const double before = i == 0 || cand[i - 1].first < 0.0 ? 0.0 : cand[i - 1].first;
    const double after = i + 1 < cand.size() ? cand[i + 1].first : t + 1.0;
    const bool a = solid(o + 0.5 * (before + t) * d), b = solid(o + 0.5 * (t + after) * d);
    if (a == b || (t == before && i > 0)) continue;
    r.hit = true;
    r.t = t;
    const glm::dvec3 p = o + t * d;
    r.normal = cand[i].second == 0 ? glm::normalize(p) : -face_normal(cand[i].second);
    r.plane_gap = std::min(std::abs(glm::dot(face_normal(1), p)), std::abs(glm::dot(face_normal(2), p)));
    return r;
  }
  return r;
}

struct Tally {
  std::size_t rays = 0, not_finite = 0, resolved = 0, wrong_class = 0, unresolved = 0, t_over = 0, n_over = 0,
              off_band = 0;
  double worst_t = 0, worst_n = 0;
};

void check_ray(Tally& tally, glm::vec3 o, glm::vec3 d) {
  ++tally.rays;
  float t = 0.0f;
  glm::vec3 n(0.0f);
  const bool hit = pacman_edges_test::pacman_intersect(o, d, half_angle, 0.0f, 1.0e30f, t, n);
  tally.not_finite += !(std::isfinite(t) && std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
  const glm::dvec3 od(o), dd(d);
  const Truth tr = truth(od, dd);
  const double len = glm::length(dd);
  // Unresolved: the ray's truth hit, or any face crossing, lies within the float resolution of a
  // face plane, measured along the normal, scaled by the size of the values float rounds.
  double scale = glm::length(od) + (tr.hit ? tr.t : 0.0) * len + 1.0;
  double gap = tr.hit ? tr.plane_gap : 1e300;
  for (int j = 1; j <= 2; ++j) {  // the whole ray's approach to each plane and to the hinge
    const double dn = glm::dot(face_normal(j), dd) / len;
    if (std::abs(dn) < resolution_k * unit_roundoff) gap = std::min(gap, std::abs(glm::dot(face_normal(j), od)));
  }
  const bool resolved = gap > resolution_k * unit_roundoff * scale;
  if (!resolved) {
    // Either class is allowed, but a hit must lie on the sphere's chord (the solid's closure is
    // inside it) and carry a unit normal.
    ++tally.unresolved;
    const acc::Result s0 = acc::intersect_sphere(od, dd, glm::dvec3(0.0), 1.0, -1e30, 1e30);
    if (hit) {
      const double slack = t_error_c * unit_roundoff * scale / len;
      const acc::Result s1 = acc::intersect_sphere(od, dd, glm::dvec3(0.0), 1.0, s0.t * (1 + 1e-12) + 1e-12, 1e30);
      const double hi = s1.outcome == acc::Outcome::hit ? s1.t : s0.t;
      tally.off_band += s0.outcome != acc::Outcome::hit || double(t) < s0.t - slack || double(t) > hi + slack ||
                        std::abs(glm::length(glm::dvec3(n)) - 1.0) > 1e-5;
    }
    return;
  }
  ++tally.resolved;
  if (hit != tr.hit) {
    ++tally.wrong_class;
    MESSAGE("class differs: o " << o.x << " " << o.y << " " << o.z << " d " << d.x << " " << d.y << " " << d.z);
    return;
  }
  if (!hit) return;
  const double sin_graze = std::max(std::abs(glm::dot(tr.normal, dd)) / len, 1e-300);
  const double err = std::abs(double(t) - tr.t) * len;
  const double bound = t_error_c * unit_roundoff * scale / sin_graze;
  tally.worst_t = std::max(tally.worst_t, err / bound);
  tally.t_over += err > bound;
  const double ang = std::acos(std::clamp(glm::dot(glm::normalize(glm::dvec3(n)), tr.normal), -1.0, 1.0));
  tally.worst_n = std::max(tally.worst_n, ang);
  tally.n_over += ang > normal_bound;
}

void report(const Tally& t, const std::string& name, bool expect_resolved = true) {
  MESSAGE(name << ": rays " << t.rays << ", resolved " << t.resolved << " (wrong class " << t.wrong_class
               << "), unresolved " << t.unresolved << "; worst t err / bound " << t.worst_t << ", worst normal angle "
               << t.worst_n << " rad; not finite " << t.not_finite << ", unresolved hits off the chord " << t.off_band);
  CHECK(t.off_band == 0u);
  CHECK(t.not_finite == 0u);
  CHECK(t.wrong_class == 0u);
  CHECK(t.t_over == 0u);
  CHECK(t.n_over == 0u);
  if (expect_resolved) CHECK(t.resolved > 0u);
}

/// A unit vector in face j's plane: along the hinge (x) at angle psi towards the face's radial
/// direction (the direction in the plane perpendicular to x, pointing out of the hinge).
glm::dvec3 in_face(int j, double psi) {
  const glm::dvec3 radial = glm::normalize(glm::cross(face_normal(j), glm::dvec3(1, 0, 0))) *
                            (j == 1 ? 1.0 : -1.0);
  return std::cos(psi) * glm::dvec3(1, 0, 0) + std::sin(psi) * radial;
}

}  // namespace

TEST_CASE("pacman rays coplanar with a wedge face") {
  Tally tally;
  for (int j = 1; j <= 2; ++j) {
    for (double psi = 0.0; psi < 6.28; psi += 0.3) {
      const glm::dvec3 d = in_face(j, psi);
      // Origins in the face plane outside the sphere, through the mouth's side, and through the
      // body (the plane's other half beyond the hinge), each backed off along -d.
      for (double r : {-0.9, -0.5, 0.3, 0.7, 1.2}) {
        const glm::dvec3 on = in_face(j, psi + 1.5707963267948966) * r;
        check_ray(tally, glm::vec3(on - 3.0 * d), glm::vec3(d));
      }
    }
  }
  report(tally, "coplanar", false);  // in a face plane: never resolved, by construction
}

TEST_CASE("pacman rays along the hinge and through it at grazing angles") {
  Tally tally;
  // Along the hinge line (x axis) and parallel to it just off it.
  for (double off : {0.0, 1e-7, -1e-7, 1e-3, -1e-3}) {
    for (double sign : {1.0, -1.0}) {
      check_ray(tally, glm::vec3(float(-3.0 * sign), 0.0f, float(off)), glm::vec3(float(sign), 0.0f, 0.0f));
      check_ray(tally, glm::vec3(float(-3.0 * sign), float(off), 0.0f), glm::vec3(float(sign), 0.0f, 0.0f));
    }
  }
  // Through a point of the hinge at angle g to face j, tilted out of or into the wedge.
  for (int j = 1; j <= 2; ++j) {
    for (double g : {1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6}) {
      for (double side : {1.0, -1.0}) {
        for (double psi : {0.2, 1.0, 1.5707963267948966}) {
          for (double x0 : {0.0, 0.4}) {
            const glm::dvec3 d = std::cos(g) * in_face(j, psi) + side * std::sin(g) * face_normal(j);
            check_ray(tally, glm::vec3(glm::dvec3(x0, 0, 0) - 3.0 * d), glm::vec3(d));
            check_ray(tally, glm::vec3(glm::dvec3(x0, 0, 0) + 3.0 * d), glm::vec3(-d));
          }
        }
      }
    }
  }
  report(tally, "hinge and grazing");
}

TEST_CASE("pacman axis-parallel rays") {
  Tally tally;
  for (int axis = 0; axis < 3; ++axis) {
    for (double sign : {1.0, -1.0}) {
      for (double a = -1.05; a <= 1.05; a += 0.15) {
        for (double b = -1.05; b <= 1.05; b += 0.15) {
          glm::dvec3 o(0.0), d(0.0);
          o[axis] = -3.0 * sign;
          o[(axis + 1) % 3] = a;
          o[(axis + 2) % 3] = b;
          d[axis] = sign;
          check_ray(tally, glm::vec3(o), glm::vec3(d));
        }
      }
    }
  }
  report(tally, "axis-parallel");
}
