// The D3D12 sample's objects as ground truth, in double and independent of the shaders' marching
// loops: one ray against one object, world t along the ray and world normal. reference.hpp
// combines them into the nearest hit per camera ray.
//
//   const d3d12::SceneConstants constants = d3d12::default_constants(d3d12::sample_camera(48, 32), 2.0f);
//   const d3d12::ReferenceScene scene = d3d12::reference_scene(constants);   // default primitives, Layout::sample
//   const glm::dvec3 dir = glm::normalize(glm::dvec3(0.1, -0.4, -1.0));     // unit: t is a length
//   const d3d12::ObjectTrace cog = d3d12::trace_object(scene, d3d12::object_id(d3d12::cog), scene.eye, dir);
//   if (cog.result.outcome == proceduray::accuracy::Outcome::hit) { cog.result.t; cog.result.normal; }
//   double d = d3d12::glsl::d3d12_primitives<double>::sdf_distance(d3d12::cog, glm::dvec3(0.0), glm::dvec4(1.0));
//
// The scene: the ground (Layout::sample only) and each primitive at translate(placement(kind,
// layout)) with local AABB [-1, 1]^3, turned about its local y by angle = spin * time (double
// product of the record's spin and SceneConstants::time). As d3d12_primitives.glsl does, the ray
// is clipped to the unturned AABB (intersect_box: entry, then exit), then turned by -angle into
// the primitive's frame, p_frame = rotate_y(p - translation, -angle) with rotate_y(v, a) =
// (c v.x + s v.z, v.y, -s v.x + c v.z); both are isometries, so t stays the world t.
//   ground      closed form: y = 0 within |x|, |z| <= plane_half; normal +y (the triangles' own).
//   box         intersect_box in the primitive's frame, half sizes params.xyz; closed-form normal.
//   spheres     intersect_sphere per sphere of spheres.glsl (centres and radii the floats the GPU
//               holds, radius times params.x), the nearest; closed-form normal.
//   metaballs   lipschitz_search on threshold - F (metaballs.glsl's field in double, world space)
//               with L = metaball_lipschitz(R) = 3 * 1.875 / R, the balls' slopes summed; normal
//               -grad F by the analytic metaball_gradient, turned back.
//   SDF kinds   lipschitz_search on sdf_distance (sdf.glsl in double, world space) with L:
//               1 for the exact distances and their min / max / repetitions (sdf_lipschitz), and
//               for the twisted torus 1 + |k| sqrt(2) / s (twist k = params.y, scale s = params.x):
//               the twist's Jacobian is a rotation plus k rho in one column, and rho <= sqrt(2)
//               in the AABB is rho / s in the unscaled frame (sdf_lipschitz leaves out the / s: equal
//               at the default s = 1; sampled slopes, ~2.1 at k = 3 for any s, lie below both).
//               The fractal pyramid's distance is a lower bound that jumps at its fold seams, so
//               no L holds across a jump: a step may pass a seam into an inside run and out again
//               unsampled. The search brackets every sign change it samples; tests/accuracy checks
//               each hit by the sign around it and by dense samples in front of it.
//               Normal: gradient_normal at h = options.normal_step footprints at the hit (a hit
//               within h of an edge gets a blend of the faces: 1 pixel of 48x32 at the default).
// The marching loops are ground_truth.hpp's, never the shaders'; only the shapes' math is shared
// (one source: d3d12_primitives.glsl compiled as C++, d3d12::glsl::d3d12_primitives<T>, which
// tests reuse in float to run the shaders' own marches). Search floor: options.min_step
// footprints at the AABB entry; footprints nearer than 1 unit (the AABB's half size) count as
// at 1. A ray starting inside a shape (at the AABB entry: a surface on the AABB face, or the eye
// within it) gets Outcome::undetermined from that object, t = where the clipped ray starts, as
// paper::trace_object does. Evaluations count searches, box tests, sphere tests and normal
// differences.
#pragma once

#include <proceduray/shader/glsl_cpp.hpp>
#include "d3d12_types.hpp"

namespace d3d12::glsl {
using namespace proceduray::glsl_cpp;
/// The shaders' primitives (shapes, fields, distances, marches, the knobs' entry point
/// d3d12_intersect_knobs), in float (T = float) or double.
template <class T>
struct d3d12_primitives {
  PROCEDURAY_GLSL_CPP_SCALAR(T)
  using MarchKnobs = proceduray::MarchKnobs;
#include "primitives/d3d12_knobs.glsl"
};
}  // namespace d3d12::glsl

#include <proceduray/accuracy/closed_form.hpp>
#include <proceduray/accuracy/ground_truth.hpp>
#include <proceduray/error.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace d3d12 {

namespace acc = proceduray::accuracy;

/// Knobs of the reference, in pixel footprints (camera.pixel_angle * distance): one setting fits every size.
struct ReferenceOptions {
  double min_step = 1.0e-6;     ///< lipschitz_search floor (metaballs, SDFs), footprints at the AABB entry
  double normal_step = 1.0e-3;  ///< SDF gradient_normal step h, footprints at the hit
  std::uint64_t budget = std::uint64_t{1} << 24;  ///< evaluations per object and ray; beyond: undetermined
};

/// One primitive as placed in the world, in double.
struct PlacedPrimitive {
  PrimitiveKind kind = box;
  glm::dvec4 params{0.0};        ///< the record's params
  glm::dvec3 translation{0.0};   ///< placement(kind, layout): where the local origin lies
  double angle = 0.0;            ///< spin * time, radians about the local y axis
  double cosine = 1.0, sine = 0.0;

  /// rotate_y(v, -angle): world offsets and directions into the primitive's frame.
  glm::dvec3 turn_in(glm::dvec3 v) const { return {cosine * v.x - sine * v.z, v.y, sine * v.x + cosine * v.z}; }
  /// rotate_y(v, angle): the frame's normals back to the world.
  glm::dvec3 turn_out(glm::dvec3 v) const { return {cosine * v.x + sine * v.z, v.y, -sine * v.x + cosine * v.z}; }
  glm::dvec3 local(glm::dvec3 world) const { return turn_in(world - translation); }
};

/// What the reference needs from SceneConstants and the primitives, in double, and the options.
struct ReferenceScene {
  glm::dvec3 eye{0.0}, forward{0.0}, right{0.0}, up{0.0};  ///< the camera's vectors (camera.glsl scales)
  double pixel_angle = 0.0;                                ///< footprint per unit distance
  double time = 0.0;                                       ///< SceneConstants::time
  bool ground = true;                                      ///< Layout::sample has the ground plane
  std::vector<PlacedPrimitive> primitives;                 ///< one per kind at most, in the order given
  ReferenceOptions options{};
};

/// One object along one ray: the result, and whether the ray reached the object's bounds (a search ran).
struct ObjectTrace {
  acc::Result result{};
  bool entered = false;
};

namespace detail {

using glsl_double = glsl::d3d12_primitives<double>;

[[noreturn]] inline void refuse(const std::string& what, const std::string& fix) {
  throw proceduray::UsageError("d3d12::reference_scene: " + what + "; " + fix);
}

inline void check_positive(const char* name, double v, const char* fix) {
  if (!(std::isfinite(v) && v > 0.0)) {
    refuse(std::string(name) + " = " + acc::detail::show(v) + " is not positive", fix);
  }
}

inline void check_constants(const SceneConstants& k) {
  const proceduray::Camera& c = k.camera;
  const auto vec = [](glm::vec4 v) { return glm::dvec3(v.x, v.y, v.z); };
  const glm::dvec3 parts[] = {vec(c.eye), vec(c.forward), vec(c.right), vec(c.up)};
  const char* names[] = {"camera.eye", "camera.forward", "camera.right", "camera.up"};
  for (int i = 0; i < 4; ++i) {
    if (!acc::detail::finite(parts[i]) || (i > 0 && glm::dot(parts[i], parts[i]) == 0.0)) {
      refuse(std::string(names[i]) + " " + acc::detail::show(parts[i]) + " is not finite (or is zero)",
             "pass a camera from proceduray::look_at, e.g. d3d12::sample_camera(width, height)");
    }
  }
  check_positive("camera.pixel_angle", c.pixel_angle, "pass the camera's pixel angle (proceduray::look_at sets it)");
  if (!std::isfinite(k.time)) {
    refuse("time = " + acc::detail::show(k.time) + " is not finite", "pass the frame's time in seconds, e.g. 0");
  }
}

inline void check_options(const ReferenceOptions& o) {
  check_positive("options.min_step", o.min_step, "pass the search floor in footprints, e.g. 1e-6");
  check_positive("options.normal_step", o.normal_step, "pass the SDF normal difference step in footprints, e.g. 1e-3");
  if (o.budget == 0) refuse("options.budget = 0", "allow evaluations per object and ray, e.g. 2^24");
}

/// The primitive placed, turned and checked (validate(); one per kind, so object ids name one each).
inline PlacedPrimitive place(const Primitive& p, std::size_t index, Layout layout, double time,
                             const std::vector<PlacedPrimitive>& so_far) {
  const std::string which = "primitives[" + std::to_string(index) + "]";
  try {
    validate(p);
  } catch (const PrimitiveError& e) {
    refuse(which + ": " + e.what(), "fix the primitive as D3d12Scene would require");
  }
  for (const PlacedPrimitive& q : so_far) {
    if (q.kind == p.kind) {
      refuse(which + " repeats kind '" + std::string(primitive_names[p.kind]) + "'",
             "pass each kind once: the debug view's object ids (and the reference's) name one primitive each");
    }
  }
  PlacedPrimitive out;
  out.kind = p.kind;
  out.params = glm::dvec4(p.params);
  out.translation = glm::dvec3(placement(p.kind, layout));
  out.angle = static_cast<double>(p.spin) * time;
  out.cosine = std::cos(out.angle);
  out.sine = std::sin(out.angle);
  return out;
}

/// [lo, hi] of the ray inside the primitive's world AABB (translation + [-1, 1]^3), by
/// intersect_box: the entry, then (from just past it) the exit. False when the ray misses it.
inline bool clip(const PlacedPrimitive& p, glm::dvec3 o, glm::dvec3 d, double& lo, double& hi,
                 std::uint64_t& evaluations) {
  constexpr double far = 1.0e30;
  const glm::dvec3 box_min = p.translation - 1.0, box_max = p.translation + 1.0;
  const acc::Result in = acc::intersect_box(o, d, box_min, box_max, 0.0, far);
  evaluations += 1;
  if (in.outcome != acc::Outcome::hit) return false;
  if (in.starts_inside) {
    lo = 0.0;
    hi = in.t;
    return true;
  }
  lo = in.t;
  const acc::Result out = acc::intersect_box(o, d, box_min, box_max, lo + 1.0e-9 * (1.0 + lo), far);
  evaluations += 1;
  hi = out.outcome == acc::Outcome::hit && out.starts_inside ? out.t : lo;  // a corner graze: empty
  return true;
}

/// The footprint the knobs scale with at distance t: at one object size (1 unit) for nearer points.
inline double footprint(const ReferenceScene& s, double t) { return s.pixel_angle * std::max(t, 1.0); }

/// The ground: y = 0 within the quad, t > 0; normal +y.
inline acc::Result ground_hit(glm::dvec3 o, glm::dvec3 d) {
  acc::Result r;
  r.evaluations = 1;
  if (d.y == 0.0) return r;  // parallel: the plane has no thickness to hit
  const double t = -o.y / d.y;
  const glm::dvec3 p = o + t * d;
  const double h = plane_half;
  if (!(t > 0.0) || !(std::abs(p.x) <= h && std::abs(p.z) <= h)) return r;
  r.outcome = acc::Outcome::hit;
  r.t = t;
  r.normal = glm::dvec3(0.0, 1.0, 0.0);
  return r;
}

/// Box and spheres: closed forms in the primitive's frame, normals turned back.
inline acc::Result analytic_hit(const PlacedPrimitive& p, glm::dvec3 o, glm::dvec3 d, double lo, double hi) {
  const glm::dvec3 ro = p.local(o), rd = p.turn_in(d);
  if (p.kind == box) {
    const glm::dvec3 half(p.params.x, p.params.y, p.params.z);
    acc::Result r = acc::intersect_box(ro, rd, -half, half, lo, hi);
    r.normal = p.turn_out(r.normal);
    return r;
  }
  acc::Result best;
  std::uint64_t spent = 0;
  for (std::uint32_t i = 0; i < glsl_double::spheres_count; ++i) {
    const glm::dvec4 c(glsl::d3d12_primitives<float>::spheres_centre_radius(i));  // the floats the GPU holds
    const acc::Result r = acc::intersect_sphere(ro, rd, glm::dvec3(c.x, c.y, c.z), c.w * p.params.x, lo, hi);
    spent += r.evaluations;
    if (r.starts_inside) {  // undetermined (trace_object): no other sphere can say more
      best = r;
      break;
    }
    if (r.outcome == acc::Outcome::hit && (best.outcome != acc::Outcome::hit || r.t < best.t)) best = r;
  }
  best.evaluations = spent;
  best.normal = p.turn_out(best.normal);
  return best;
}

/// Metaballs: lipschitz_search on threshold - F; normal -grad F, analytic.
inline acc::Result metaball_hit(const ReferenceScene& s, const PlacedPrimitive& p, glm::dvec3 o, glm::dvec3 d,
                                double lo, double hi) {
  const double radius = p.params.x, threshold = p.params.y, time = s.time;
  auto outside = [&](glm::dvec3 q) { return threshold - glsl_double::metaball_field(p.local(q), radius, time); };
  const acc::SearchOptions so{.min_step = s.options.min_step * footprint(s, lo), .budget = s.options.budget};
  acc::Result r = acc::lipschitz_search(outside, glsl_double::metaball_lipschitz(radius), o, d, lo, hi, so);
  if (r.outcome != acc::Outcome::hit || r.starts_inside) return r;
  const glm::dvec3 g = glsl_double::metaball_gradient(p.local(o + r.t * d), radius, time);
  r.evaluations += 1;
  if (glm::dot(g, g) > 0.0) r.normal = p.turn_out(-glm::normalize(g));
  return r;
}

}  // namespace detail

/// The Lipschitz bound the reference divides sdf_distance(kind, ., params) by (see the header).
inline double sdf_bound(PrimitiveKind kind, glm::dvec4 params) {
  const double scale = params.x > 0.0 ? params.x : 1.0;  // sdf_distance's own guard
  if (kind == twisted_torus) return 1.0 + std::abs(params.y) * std::sqrt(2.0) / scale;
  return detail::glsl_double::sdf_lipschitz(kind, params);
}

namespace detail {

/// SDF kinds: lipschitz_search on sdf_distance in world space; normal by gradient_normal.
inline acc::Result sdf_hit(const ReferenceScene& s, const PlacedPrimitive& p, glm::dvec3 o, glm::dvec3 d, double lo,
                           double hi) {
  auto distance = [&](glm::dvec3 q) { return glsl_double::sdf_distance(p.kind, p.local(q), p.params); };
  const acc::SearchOptions so{.min_step = s.options.min_step * footprint(s, lo), .budget = s.options.budget};
  acc::Result r = acc::lipschitz_search(distance, sdf_bound(p.kind, p.params), o, d, lo, hi, so);
  if (r.outcome != acc::Outcome::hit || r.starts_inside) return r;
  r.evaluations += 6;
  r.normal = acc::gradient_normal(distance, o + r.t * d, s.options.normal_step * footprint(s, r.t));
  return r;
}

}  // namespace detail

/// The prepared scene: `constants` (camera, time) and `primitives` placed by `layout` (the ground
/// only with Layout::sample). Throws UsageError naming a non-finite or zero camera vector, a
/// non-positive pixel angle, a non-finite time, an invalid or repeated primitive or a bad option.
inline ReferenceScene reference_scene(const SceneConstants& constants, std::span<const Primitive> primitives,
                                      Layout layout, const ReferenceOptions& options = {}) {
  detail::check_constants(constants);
  detail::check_options(options);
  const proceduray::Camera& c = constants.camera;
  ReferenceScene s;
  s.eye = glm::dvec3(c.eye.x, c.eye.y, c.eye.z);
  s.forward = glm::dvec3(c.forward.x, c.forward.y, c.forward.z);
  s.right = glm::dvec3(c.right.x, c.right.y, c.right.z);
  s.up = glm::dvec3(c.up.x, c.up.y, c.up.z);
  s.pixel_angle = c.pixel_angle;
  s.time = constants.time;
  s.ground = layout == Layout::sample;
  for (std::size_t i = 0; i < primitives.size(); ++i) {
    s.primitives.push_back(detail::place(primitives[i], i, layout, s.time, s.primitives));
  }
  s.options = options;
  return s;
}

/// The sample's scene: default_primitives() on the ground (Layout::sample).
inline ReferenceScene reference_scene(const SceneConstants& constants, const ReferenceOptions& options = {}) {
  const std::array<Primitive, primitive_count> all = default_primitives();
  return reference_scene(constants, all, Layout::sample, options);
}

/// One object (plane_id, or object_id(kind) of a primitive in the scene) along origin + t dir,
/// t > 0, dir unit length: the first entry with world t and world normal. Throws UsageError for
/// another id, and for a non-finite ray (from the searchers).
inline ObjectTrace trace_object(const ReferenceScene& s, std::uint32_t id, glm::dvec3 origin, glm::dvec3 dir) {
  if (id == plane_id && s.ground) return {detail::ground_hit(origin, dir), true};
  const auto found = std::find_if(s.primitives.begin(), s.primitives.end(),
                                  [id](const PlacedPrimitive& p) { return object_id(p.kind) == id; });
  if (found == s.primitives.end()) {
    throw proceduray::UsageError("d3d12::trace_object: object id " + std::to_string(id) +
                                 " is not in the scene; pass " + (s.ground ? "plane_id or " : "") +
                                 "object_id(kind) of one of its primitives");
  }
  const PlacedPrimitive& p = *found;
  ObjectTrace out;
  std::uint64_t box_tests = 0;
  double lo = 0.0, hi = 0.0;
  out.entered = detail::clip(p, origin, dir, lo, hi, box_tests);
  if (out.entered) {
    out.result = p.kind <= spheres     ? detail::analytic_hit(p, origin, dir, lo, hi)
                 : p.kind == metaballs ? detail::metaball_hit(s, p, origin, dir, lo, hi)
                                       : detail::sdf_hit(s, p, origin, dir, lo, hi);
  }
  out.result.evaluations += box_tests;
  if (out.result.starts_inside) {  // see the header: defined, never a guess
    out.result.outcome = acc::Outcome::undetermined;
    out.result.t = lo;
    out.result.normal = glm::dvec3(0.0);
  }
  return out;
}

}  // namespace d3d12
