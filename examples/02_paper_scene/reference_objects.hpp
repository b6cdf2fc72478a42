// The paper scene's objects as ground truth, in double and independent of the sphere tracer:
// one ray against one object, world t along the ray and world normal. reference.hpp combines
// them into the nearest hit per camera ray.
//
//   const paper::ReferenceScene scene = paper::reference_scene(paper::default_constants(48, 32, 0.0f),
//                                                              {.spacing = 1.0e-2});
//   const glm::dvec3 dir = glm::normalize(glm::dvec3(0.25, -0.15, -1.0));  // unit: t is a length
//   const paper::ObjectTrace m = paper::trace_object(scene, paper::mandelbulb_id, scene.eye, dir);
//   if (m.result.outcome == proceduray::accuracy::Outcome::hit) { m.result.t; m.result.normal; }
//   bool in = paper::mandelbulb_inside(glm::dvec3(0.0, 0.5, 0.0), 8u);  // object space
//
// How each object is found (all in world space: membership and bounds take p_world, map it to
// object space by o = (p - translation) / scale, so t is the world t and needs no conversion; a
// uniform scale leaves normal directions alone, the inverse transpose being a multiple of 1):
//   plane       closed form: y = 0 within quad_xz(plane_min, plane_max); normal +y from either
//               side (the triangles' geometric normal; plane.rchit flips it only to shade).
//   Pac-man     lipschitz_search on max(|o| - 1, min(-n1.o, -n2.o)) * scale (1-Lipschitz in world
//               units), the unit sphere minus the wedge {n1.o <= 0, n2.o <= 0} written from
//               pacman.glsl's definition, not its interval code; min_step = options.min_step
//               footprints. Normal: the gradient of whichever piece is largest at the hit.
//   Julia       predicate_search on the escape test (|z|^2 > 16^2 within N steps of z <- z^2 + c,
//               julia.glsl's bailout) AND the kept side of the cut, dot(cut.xyz, o) <= cut.w.
//   Mandelbulb  predicate_search on the escape test (|z| > 2 within N steps of z <- z^8 + o,
//               White and Nylander's spherical power with pow and atan2, not the shader's products).
// Fractals are clipped to their AABB first (intersect_box), as the shaders clip to theirs: what
// lies outside it is invisible to both. Sample spacing: options.spacing pixel footprints at the
// AABB entry (the nearest, so the finest, footprint on the clipped ray). The default 1e-3 is what
// tests/accuracy/primitive_reference_test.cpp measured for a reference good to ~0.05 footprints
// (paper_reference_test at 48x32: within 0.042 footprints of spacing 1e-4, no class change; 1e-2
// moved hits by up to 1.1 footprints and changed 2 pixels). Runs of the set thinner than the
// spacing may be missed: filaments in front of the body, which move hits. Fractal normals:
// gradient_normal of the shader's own distance estimate compiled as C++ in double (one source of
// the primitive's math) at h = options.normal_step footprints at the hit, retried at 4h and 16h
// where every sample lies inside (zero differences); they describe the surface at that scale (at
// 48x32 the bulb is rough there: 5 of 56 face away from the camera, in crevices). The Julia cut
// face (within 1e-9 object units of the plane) gets the plane's normal, exact.
// Iterations (the knobs' count; all of it when the knobs take fewer by distance: the truth is
// the full set): julia max(iterations, 1) and mandelbulb_animated_iterations(mandelbulb_
// iterations, time), as the shaders at that time, times options.iteration_factor (2: the truncation
// reference, reported apart). Parameters that come from the time (c, the count) are computed in
// float by the shaders' own functions: the reference is of the object the GPU is asked to draw.
// A ray whose origin lies inside an object (never a camera ray here: the eye is outside every
// AABB) gets Outcome::undetermined from that object, t = where it starts: a primary ray from
// inside a solid sees nothing the shaders agree on. Evaluations count searches, box tests and
// normal differences.
#pragma once

#include <proceduray/march/primitives_glsl.hpp>
#include "frame.hpp"

#include <proceduray/accuracy/closed_form.hpp>
#include <proceduray/accuracy/ground_truth.hpp>
#include <proceduray/error.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>


namespace paper {

namespace acc = proceduray::accuracy;

/// The Pac-men's mouth half angle (radians): paper::pacman_mouth, the float the GPU holds
/// (default_constants puts it in SceneConstants::pacman_mouth).
inline constexpr double pacman_mouth_half_angle = static_cast<double>(pacman_mouth);
/// The plane cutting the Julia set (keeps dot(xyz, p) <= w, object space): paper::julia_cut, the
/// floats the GPU holds (default_constants puts them in SceneConstants::julia_cuts).
inline const glm::dvec4 julia_cut_plane{julia_cut};

/// Knobs of the reference; lengths are in pixel footprints (pixel_angle * t) so one setting fits every size.
struct ReferenceOptions {
  double spacing = 1.0e-3;             ///< fractal sample spacing, footprints at the AABB entry (tests: 1e-2)
  double normal_step = 0.1;            ///< fractal normal difference step h, footprints at the hit
  double min_step = 1.0e-6;            ///< Pac-man lipschitz_search floor, footprints at the AABB entry
  std::uint32_t iteration_factor = 1;  ///< fractal iterations times this; 2: the truncation reference
  std::uint64_t budget = std::uint64_t{1} << 24;  ///< evaluations per object and ray; beyond: undetermined
};

/// What the reference needs from the Frame, in double, and the options.
struct ReferenceScene {
  glm::dvec3 eye{0.0}, forward{0.0}, right{0.0}, up{0.0};  ///< the camera's vectors (camera.glsl scales)
  double pixel_angle = 0.0;                                ///< footprint per unit distance
  glm::dvec4 julia_c{0.0};                                 ///< julia_animated_c(time)
  std::uint32_t julia_iterations = 1;                      ///< membership count, factor included
  std::uint32_t mandelbulb_iterations = 1;                 ///< membership count, factor included
  ReferenceOptions options{};
};

/// One object along one ray: the result, and whether the ray reached the object's bounds (a search ran).
struct ObjectTrace {
  acc::Result result{};
  bool entered = false;
};

namespace detail {

[[noreturn]] inline void refuse(const std::string& what, const std::string& fix) {
  throw proceduray::UsageError("paper::reference_scene: " + what + "; " + fix);
}

inline void check_positive(const char* name, double v, const char* fix) {
  if (!(std::isfinite(v) && v > 0.0)) refuse(std::string(name) + " = " + acc::detail::show(v) + " is not positive", fix);
}

inline void check_camera(const proceduray::Camera& c) {
  const auto vec = [](glm::vec4 v) { return glm::dvec3(v.x, v.y, v.z); };
  const glm::dvec3 parts[] = {vec(c.eye), vec(c.forward), vec(c.right), vec(c.up)};
  const char* names[] = {"camera.eye", "camera.forward", "camera.right", "camera.up"};
  for (int i = 0; i < 4; ++i) {
    if (!acc::detail::finite(parts[i]) || (i > 0 && glm::dot(parts[i], parts[i]) == 0.0)) {
      refuse(std::string(names[i]) + " " + acc::detail::show(parts[i]) + " is not finite (or is zero)",
             "pass a camera from proceduray::look_at, e.g. paper::default_constants(width, height, time).camera");
    }
  }
  check_positive("camera.pixel_angle", c.pixel_angle, "pass the camera's pixel angle (proceduray::look_at sets it)");
}

inline void check_options(const ReferenceOptions& o) {
  check_positive("options.spacing", o.spacing, "pass the fractal sample spacing in pixel footprints, e.g. 1e-3");
  check_positive("options.normal_step", o.normal_step, "pass the normal difference step in footprints, e.g. 0.1");
  check_positive("options.min_step", o.min_step, "pass the Pac-man search floor in footprints, e.g. 1e-6");
  if (o.iteration_factor == 0 || o.iteration_factor > 64) {
    refuse("options.iteration_factor = " + std::to_string(o.iteration_factor) + " is outside 1..64",
           "pass 1 (the shaders' count) or 2 (the truncation reference)");
  }
  if (o.budget == 0) refuse("options.budget = 0", "allow evaluations per object and ray, e.g. 2^24");
}

/// A placed object's world frame and world AABB. The reference models translation and uniform scale.
struct Placed {
  glm::dvec3 translation{0.0};
  double scale = 1.0;
  glm::dvec3 box_min{0.0}, box_max{0.0};
  glm::dvec3 local(glm::dvec3 world) const { return (world - translation) / scale; }
};

inline Placed placed(const proceduray::Placement& at, const proceduray::Aabb& box) {
  if (at.degrees != 0.0f || !(at.scale > 0.0f)) {
    throw proceduray::UsageError("paper::trace_object: a placement with rotation " + std::to_string(at.degrees) +
                                 " degrees and scale " + std::to_string(at.scale) + " is outside the reference's model; "
                                 "keep paper_types.hpp's placements unrotated with a positive scale, or extend it");
  }
  const glm::dvec3 t(at.translation);
  const double s = at.scale;
  return {t, s, t + s * glm::dvec3(box.min), t + s * glm::dvec3(box.max)};
}

/// [lo, hi] of the ray inside the world box, by intersect_box: the entry, then (from just past it,
/// now inside) the exit. False when the ray misses it; `evaluations` counts the box tests.
inline bool clip(const Placed& p, glm::dvec3 o, glm::dvec3 d, double& lo, double& hi, std::uint64_t& evaluations) {
  constexpr double far = 1.0e30;
  const acc::Result in = acc::intersect_box(o, d, p.box_min, p.box_max, 0.0, far);
  evaluations += 1;
  if (in.outcome != acc::Outcome::hit) return false;
  if (in.starts_inside) {
    lo = 0.0;
    hi = in.t;
    return true;
  }
  lo = in.t;
  const acc::Result out = acc::intersect_box(o, d, p.box_min, p.box_max, lo + 1.0e-9 * (1.0 + lo), far);
  evaluations += 1;
  hi = out.outcome == acc::Outcome::hit && out.starts_inside ? out.t : lo;  // a corner graze: empty
  return true;
}

/// The footprint the search knobs scale with: at the entry, or at one object size for rays from within.
inline double footprint(const ReferenceScene& s, const Placed& p, double t_lo) {
  return s.pixel_angle * std::max(t_lo, p.scale);
}

}  // namespace detail

/// Inside the power-8 Mandelbulb truncated after n steps (object space): |z| <= 2 throughout.
/// The map is mandelbulb.glsl's trigonometry-free z^8, in double (tests/shaders/mandelbulb_test
/// checks it against the angle form).
inline bool mandelbulb_inside(glm::dvec3 p, std::uint32_t n) {
  glm::dvec3 z = p;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (glm::length(z) > 2.0) return false;
    z = proceduray::glsl::mandelbulb<double>::mandelbulb_power8(z) + p;
  }
  return glm::length(z) <= 2.0;
}

/// Inside the quaternion Julia set of c truncated after n steps (object space, w = 0 slice):
/// |z|^2 <= 256 after every step of z <- z^2 + c, julia.glsl's bailout of 16.
inline bool julia_inside(glm::dvec3 p, glm::dvec4 c, std::uint32_t n) {
  double a = p.x, b = p.y, e = p.z, f = 0.0;  // z = a + b i + e j + f k
  for (std::uint32_t i = 0; i < n; ++i) {
    // (a + v)^2 = a^2 - |v|^2 + 2 a v for the vector part v = (b, e, f).
    const double next_a = a * a - b * b - e * e - f * f + c.x;
    b = 2.0 * a * b + c.y;
    e = 2.0 * a * e + c.z;
    f = 2.0 * a * f + c.w;
    a = next_a;
    if (a * a + b * b + e * e + f * f > 256.0) return false;
  }
  return true;
}

/// julia_inside on the side of the cut that the Julia field keeps (shaders/fractals.glsl).
inline bool julia_cut_inside(glm::dvec3 p, glm::dvec4 c, std::uint32_t n) {
  return glm::dot(glm::dvec3(julia_cut_plane), p) <= julia_cut_plane.w && julia_inside(p, c, n);
}

/// The prepared scene for `constants` (camera, time, iteration counts). Throws UsageError naming a
/// non-finite or zero camera vector, a non-positive pixel angle or an out-of-range option.
inline ReferenceScene reference_scene(const Frame& constants, const ReferenceOptions& options = {}) {
  detail::check_camera(constants.camera);
  detail::check_options(options);
  const proceduray::Camera& c = constants.camera;
  ReferenceScene s;
  s.eye = glm::dvec3(c.eye.x, c.eye.y, c.eye.z);
  s.forward = glm::dvec3(c.forward.x, c.forward.y, c.forward.z);
  s.right = glm::dvec3(c.right.x, c.right.y, c.right.z);
  s.up = glm::dvec3(c.up.x, c.up.y, c.up.z);
  s.pixel_angle = c.pixel_angle;
  s.julia_c = glm::dvec4(proceduray::glsl::julia<float>::julia_animated_c(constants.time));
  const std::uint64_t julia = std::max(constants.knobs[julia_id].iterations, 1u),
                      bulb = proceduray::glsl::mandelbulb<float>::mandelbulb_animated_iterations(constants.knobs[mandelbulb_id].iterations,
                                                                               constants.time);
  if (std::max(julia, bulb) * options.iteration_factor > 1'000'000) {
    detail::refuse("iterations " + std::to_string(julia) + " (Julia), " + std::to_string(bulb) + " (Mandelbulb) times " +
                       std::to_string(options.iteration_factor) + " exceed 10^6",
                   "pass the shaders' counts (defaults 10 and 8)");
  }
  s.julia_iterations = static_cast<std::uint32_t>(julia * options.iteration_factor);
  s.mandelbulb_iterations = static_cast<std::uint32_t>(bulb * options.iteration_factor);
  s.options = options;
  return s;
}

namespace detail {

/// The ground: y = 0 inside the quad's rectangle, t > 0; normal +y.
inline acc::Result plane_hit(glm::dvec3 o, glm::dvec3 d) {
  acc::Result r;
  r.evaluations = 1;
  if (d.y == 0.0) return r;  // parallel: the plane has no thickness to hit
  const double t = -o.y / d.y;
  const glm::dvec3 p = o + t * d;
  const bool within = p.x >= plane_min.x && p.x <= plane_max.x && p.z >= plane_min.y && p.z <= plane_max.y;
  if (!(t > 0.0) || !within) return r;
  r.outcome = acc::Outcome::hit;
  r.t = t;
  r.normal = glm::dvec3(0.0, 1.0, 0.0);
  return r;
}

/// Pac-man's wedge normals n1, n2 (pacman.glsl: the wedge is {n1.o <= 0 and n2.o <= 0}).
inline glm::dvec3 pacman_n(int j) {
  const double c = std::cos(pacman_mouth_half_angle), s = std::sin(pacman_mouth_half_angle);
  return {0.0, j == 1 ? c : -c, -s};
}

/// Its 1-Lipschitz bound in object space: sphere minus wedge = max(sphere, -wedge), wedge = max(n1.o, n2.o).
inline double pacman_bound(glm::dvec3 o) {
  return std::max(glm::length(o) - 1.0, std::min(-glm::dot(pacman_n(1), o), -glm::dot(pacman_n(2), o)));
}

inline acc::Result pacman_hit(const ReferenceScene& s, const Placed& at, glm::dvec3 o, glm::dvec3 d, double lo,
                              double hi) {
  // scale * bound(local(p)) is 1-Lipschitz in world units: local() shrinks lengths by 1 / scale.
  auto bound = [&](glm::dvec3 p) { return at.scale * pacman_bound(at.local(p)); };
  const acc::SearchOptions so{.min_step = s.options.min_step * footprint(s, at, lo), .budget = s.options.budget};
  acc::Result r = acc::lipschitz_search(bound, 1.0, o, d, lo, hi, so);
  if (r.outcome != acc::Outcome::hit) return r;
  const glm::dvec3 p = at.local(o + r.t * d);
  const double sphere = glm::length(p) - 1.0, face1 = -glm::dot(pacman_n(1), p), face2 = -glm::dot(pacman_n(2), p);
  // The gradient of the piece that is the bound at p: the sphere's p / |p|, or face j's -n_j.
  r.normal = sphere >= std::min(face1, face2) ? glm::normalize(p) : face1 <= face2 ? -pacman_n(1) : -pacman_n(2);
  return r;
}

/// gradient_normal of a distance estimate at h, 4h, 16h: the first that is not flat (all samples inside).
template <class Estimate>
glm::dvec3 fractal_normal(Estimate&& estimate, glm::dvec3 p, double h, std::uint64_t& evaluations) {
  for (int k = 0; k < 3; ++k, h *= 4.0) {
    evaluations += 6;
    const glm::dvec3 n = acc::gradient_normal(estimate, p, h);
    if (n != glm::dvec3(0.0)) return n;
  }
  return glm::dvec3(0.0);  // none: metrics leave the ray out of the normal errors
}

/// predicate_search of `inside` (object space) along the clipped ray, sampled every options.spacing footprints.
template <class Inside>
acc::Result fractal_search(const ReferenceScene& s, const Placed& at, Inside&& inside, glm::dvec3 o, glm::dvec3 d,
                           double lo, double hi) {
  auto in_world = [&](glm::dvec3 p) { return inside(at.local(p)); };
  const double spacing = s.options.spacing * footprint(s, at, lo);
  return acc::predicate_search(in_world, o, d, lo, hi, spacing, {.budget = s.options.budget});
}

inline acc::Result mandelbulb_hit(const ReferenceScene& s, const Placed& at, glm::dvec3 o, glm::dvec3 d, double lo,
                                  double hi) {
  const std::uint32_t n = s.mandelbulb_iterations;
  acc::Result r = fractal_search(s, at, [n](glm::dvec3 p) { return mandelbulb_inside(p, n); }, o, d, lo, hi);
  if (r.outcome != acc::Outcome::hit || r.starts_inside) return r;
  const double h = s.options.normal_step * s.pixel_angle * r.t / at.scale;  // object units
  auto estimate = [n](glm::dvec3 p) { return proceduray::glsl::mandelbulb<double>::mandelbulb_distance(p, n); };
  r.normal = fractal_normal(estimate, at.local(o + r.t * d), h, r.evaluations);
  return r;
}

inline acc::Result julia_hit(const ReferenceScene& s, const Placed& at, glm::dvec3 o, glm::dvec3 d, double lo,
                             double hi) {
  const std::uint32_t n = s.julia_iterations;
  const glm::dvec4 c = s.julia_c;
  acc::Result r = fractal_search(s, at, [n, c](glm::dvec3 p) { return julia_cut_inside(p, c, n); }, o, d, lo, hi);
  if (r.outcome != acc::Outcome::hit || r.starts_inside) return r;
  const glm::dvec3 p = at.local(o + r.t * d), cut(julia_cut_plane);
  // On the cut face (the bracket is ~1e-13 t, so 1e-9 is safely above it): the plane's normal, exact.
  if (std::abs(glm::dot(cut, p) - julia_cut_plane.w) <= 1.0e-9) {
    r.normal = glm::normalize(cut);
    return r;
  }
  const double h = s.options.normal_step * s.pixel_angle * r.t / at.scale;
  auto estimate = [n, c](glm::dvec3 q) { return proceduray::glsl::julia<double>::julia_distance(q, c, n); };
  r.normal = fractal_normal(estimate, p, h, r.evaluations);
  return r;
}

}  // namespace detail

/// One object (plane_id, pacman0_id, pacman1_id, julia_id or mandelbulb_id) along origin + t dir,
/// t > 0, dir unit length: the first entry with world t and world normal. Throws UsageError for
/// sky_id or another id, and for a non-finite ray (from the searchers).
inline ObjectTrace trace_object(const ReferenceScene& s, ObjectId id, glm::dvec3 origin, glm::dvec3 dir) {
  if (id == plane_id) return {detail::plane_hit(origin, dir), true};
  detail::Placed at;
  if (id == pacman0_id || id == pacman1_id) at = detail::placed(pacman_placements.at(id - pacman0_id), pacman_aabb);
  else if (id == julia_id) at = detail::placed(julia_placement, julia_aabb);
  else if (id == mandelbulb_id) at = detail::placed(mandelbulb_placement, mandelbulb_aabb);
  else throw proceduray::UsageError("paper::trace_object: object id " + std::to_string(id) + " has no geometry; pass "
                                    "plane_id, pacman0_id, pacman1_id, julia_id or mandelbulb_id");
  ObjectTrace out;
  std::uint64_t box_tests = 0;
  double lo = 0.0, hi = 0.0;
  out.entered = detail::clip(at, origin, dir, lo, hi, box_tests);
  if (out.entered) {
    out.result = id == julia_id        ? detail::julia_hit(s, at, origin, dir, lo, hi)
                 : id == mandelbulb_id ? detail::mandelbulb_hit(s, at, origin, dir, lo, hi)
                                       : detail::pacman_hit(s, at, origin, dir, lo, hi);
  }
  out.result.evaluations += box_tests;
  if (out.result.starts_inside) {  // see the header: defined, never a guess
    out.result.outcome = acc::Outcome::undetermined;
    out.result.t = lo;
  }
  return out;
}

}  // namespace paper
