// The D3D12 procedural-geometry sample's scene, shader side: the structs that cross to the
// GLSL, the primitives and their host-checked parameters, placements and defaults.
//
//   d3d12::SceneConstants c = d3d12::default_constants(1024, 768, time);   // binding 2
//   d3d12::validate(d3d12::default_primitive(d3d12::cog));                 // throws on bad input
//
// Conventions the shaders in shaders/ (next to this file) rely on:
//   set 0: binding 0 TLAS; binding 1 rgba8 storage image; binding 2 uniform SceneConstants (scalar).
//   Rays:  radiance = 0 (miss radiance.rmiss), shadow = 1 (miss shadow.rmiss); shaders trace with
//          the generated trace_radiance / trace_shadow: the declared flags, sbtRecordOffset =
//          missIndex = ray index and sbtRecordStride = ray_count = 2.
//   Hit groups (radiance | shadow): the sample's for the plane, the analytic and the volumetric
//   primitives; each SDF is a distance field with its own (the library writes its intersection):
//          plane            triangles   plane.rchit                     | no shaders
//          analytic         procedural  shade.rchit + analytic.rint     | analytic.rint
//          volumetric       procedural  shade.rchit + volumetric.rint   | volumetric.rint
//          <sdf name>       distance field (sdf_fields.glsl <name>_field): shade.rchit | the generated intersection
//   Every hit record carries a PrimitiveRecord: the analytic and volumetric kinds' parameters
//   select the intersection function (shaders/primitives/d3d12_primitives.glsl); an SDF's
//   params and spin are its field's parameters. Each primitive is one AABB geometry [-1, 1]^3
//   with one instance; local space = object space.
#pragma once

#include "../common/tracing.hpp"

#include <proceduray/march/primitives.hpp>
#include <proceduray/scene/constants.hpp>
#include <proceduray/scene/field.hpp>
#include <proceduray/scene/geometry.hpp>
#include <proceduray/shader/shader.hpp>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace d3d12 {

namespace pr = proceduray;

/// SceneConstants::flags bits: shadows, reflections, and the debug view (r = object id,
/// g and b = marching steps of the primary hit (low and high byte), a = 0 where any value was
/// NaN or infinite, else 255). The evaluations of rays that miss are the steps output's
/// (pr::Output::steps), which counts every ray.
inline constexpr std::uint32_t flag_shadows = 1u, flag_reflections = 2u, flag_debug = 4u;
/// Radiance segments at most (primary + one reflection), and the recursion that allows (+ shadow).
inline constexpr std::uint32_t max_depth_limit = 2, max_recursion_depth = max_depth_limit + 1;

/// Primitive kinds, equal to the primitive_* and sdf_* consts of d3d12_primitives.glsl (a test checks).
enum PrimitiveKind : std::uint32_t {
  box, spheres, metaballs, mini_spheres, round_cube, square_torus, twisted_torus, cog, cylinder, fractal_pyramid,
  primitive_count
};
inline constexpr std::array<std::string_view, primitive_count> primitive_names{
    "box", "spheres", "metaballs", "mini_spheres", "round_cube", "square_torus", "twisted_torus", "cog", "cylinder",
    "fractal_pyramid"};
/// A primitive's hit group: the sample's analytic or volumetric one; an SDF's is its field's, by its name.
inline std::string_view hit_group_of(PrimitiveKind k) {
  return k <= spheres ? "analytic" : (k == metaballs ? "volumetric" : primitive_names[k]);
}
/// Object ids of the debug view: 0 sky, 1 plane, 2 + kind for primitives.
inline constexpr std::uint32_t sky_id = 0, plane_id = 1;
inline constexpr std::uint32_t object_id(PrimitiveKind k) { return 2u + k; }
/// Ids 0 .. object_id_count - 1 (sky_id, plane_id, object_id(kind)): the debug view's, the index
/// of SceneConstants::knobs and of ReferenceImage::costs.
inline constexpr std::uint32_t object_id_count = 2u + primitive_count;

/// Per-frame uniform (set 0, binding 2). The march knobs are per object (indexed by object id,
/// read by the marched primitives; the analytic ones and the plane ignore theirs), run-time values.
struct SceneConstants {
  pr::Camera camera;          ///< primary rays
  glm::vec3 light_position;   ///< point light, world space
  float ambient;              ///< ambient fraction of the albedo; default 0.2
  glm::vec3 light_colour;     ///< default white
  float time;                 ///< seconds: spins primitives and moves the metaballs (no AS work)
  glm::vec3 sky_colour;       ///< zenith colour
  std::uint32_t flags;        ///< flag_* bits; default shadows | reflections
  std::uint32_t max_depth;    ///< radiance segments, primary included; <= max_depth_limit
  pr::MarchKnobs knobs[object_id_count];  ///< per object id: method, threshold, steps, normal (capabilities())
};
PROCEDURAY_STRUCT(SceneConstants, scalar, camera, light_position, ambient, light_colour, time, sky_colour, flags,
                  max_depth, knobs);

/// How reflections and shadows are traced (examples/common/tracing.hpp).
using Tracing = examples::Tracing;

/// The radiance ray's payload (location 0). The fields after `nonfinite` carry a hit back to
/// raygen when tracing is iterative; recursive tracing leaves them unread.
struct RadiancePayload {
  glm::vec3 colour;         ///< linear RGB (iterative: the ambient part)
  std::uint32_t depth;      ///< 0 for primary rays
  std::uint32_t object_id;  ///< of the hit (sky_id on a miss)
  float steps;              ///< marching steps of the hit (0 for analytic surfaces)
  std::uint32_t nonfinite;  ///< 1 when a hit produced a NaN or infinity anywhere
  glm::vec3 direct;         ///< iterative: the light's term if nothing shadows it
  float fresnel;            ///< iterative: the reflection's share (0: none to trace)
  glm::vec3 next_origin;    ///< iterative: where secondary rays start
  float light_distance;     ///< iterative: from the hit to the light (0: facing away, no shadow ray)
  glm::vec3 next_direction;   ///< iterative: the reflection's direction
  glm::vec3 light_direction;  ///< iterative: unit, towards the light
};
PROCEDURAY_STRUCT(RadiancePayload, scalar, colour, depth, object_id, steps, nonfinite, direct, fresnel, next_origin,
                  light_distance, next_direction, light_direction);

/// The shadow ray's payload (location 1): preset to 1, the shadow miss sets 0.
struct ShadowPayload {
  std::uint32_t occluded;
};
PROCEDURAY_STRUCT(ShadowPayload, scalar, occluded);

/// Hit root arguments (the sample's local root arguments): which primitive, its parameters, its material.
struct PrimitiveRecord {
  glm::vec3 albedo;         ///< base colour
  float reflectance;        ///< Schlick F0; 0 = no reflection
  glm::vec4 params;         ///< per kind, see validate()
  std::uint32_t kind;       ///< PrimitiveKind (unused by the plane)
  std::uint32_t object_id;  ///< for the debug view
  float spin;               ///< radians per second about the local y axis
  float checker;            ///< plane: checker square size; 0 = plain
};
PROCEDURAY_STRUCT(PrimitiveRecord, scalar, albedo, reflectance, params, kind, object_id, spin, checker);

using Interface = pr::ShaderInterface<pr::Payload<RadiancePayload, ShadowPayload>, pr::RootComponent<SceneConstants>,
                                      pr::RootArguments<PrimitiveRecord>, pr::Attributes<pr::FieldHit>>;

/// A primitive the host asks for: kind, parameters, material, spin.
struct Primitive {
  PrimitiveKind kind = box;
  glm::vec4 params{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 albedo{0.8f};
  float reflectance = 0.1f;
  float spin = 0.0f;
};

/// A host parameter that cannot make a primitive: names the operation, the value and the fix.
struct PrimitiveError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// Farthest reach of the primitive from the local y axis (for spin: it must stay in its AABB).
inline float xz_reach(const Primitive& p) {
  switch (p.kind) {
    case box: return std::sqrt(p.params.x * p.params.x + p.params.z * p.params.z);
    case spheres: return 0.3f * std::sqrt(2.0f) + 0.6f * p.params.x;
    case metaballs: return 0.45f + p.params.x;
    case mini_spheres: case cylinder: case fractal_pyramid: return std::sqrt(2.0f) * p.params.x;
    case round_cube: return 0.98f * p.params.x;
    case square_torus: return 0.9f * p.params.x;
    case twisted_torus: case cog: return 0.92f * p.params.x;
    case primitive_count: break;
  }
  return 0.0f;
}

/// Throws PrimitiveError unless `p` describes a primitive inside its AABB [-1, 1]^3. params:
/// box: xyz half sizes in (0, 1]; spheres and SDFs: x scale in (0, 1]; metaballs: x influence
/// radius in (0, 1], y threshold in (0, 1); twisted torus: y twist in [-8, 8] rad per unit;
/// fractal pyramid: y iterations, a whole number in [0, 8]. spin: finite, and 0 unless the
/// primitive's reach from the y axis is within 1.
inline void validate(const Primitive& p) {
  if (p.kind >= primitive_count) {
    throw PrimitiveError("d3d12 primitive: kind " + std::to_string(p.kind) + " is not a PrimitiveKind; use one below " +
                         std::to_string(primitive_count));
  }
  const std::string what = "d3d12 primitive '" + std::string(primitive_names[p.kind]) + "': ";
  auto in = [](float v, float lo, float hi) { return std::isfinite(v) && v > lo && v <= hi; };
  if (p.kind == box) {
    for (int i = 0; i < 3; ++i) {
      if (!in(p.params[i], 0.0f, 1.0f)) {
        throw PrimitiveError(what + "half size " + std::to_string(p.params[i]) + " (params[" + std::to_string(i) +
                             "]) must be in (0, 1]; a box needs positive sizes that fit its AABB [-1, 1]^3");
      }
    }
  } else if (p.kind == metaballs) {
    if (!in(p.params.x, 0.0f, 1.0f)) {
      throw PrimitiveError(what + "influence radius " + std::to_string(p.params.x) +
                           " (params.x) must be in (0, 1]; with 0 no source has any field");
    }
    if (!(std::isfinite(p.params.y) && p.params.y > 0.0f && p.params.y < 1.0f)) {
      throw PrimitiveError(what + "threshold " + std::to_string(p.params.y) +
                           " (params.y) must be in (0, 1): each source's potential is 1 at its centre");
    }
  } else if (!in(p.params.x, 0.0f, 1.0f)) {
    throw PrimitiveError(what + (p.kind == spheres ? "radius scale " : "scale ") + std::to_string(p.params.x) +
                         " (params.x) must be in (0, 1]; zero or negative sizes make no surface");
  }
  if (p.kind == twisted_torus && !(std::isfinite(p.params.y) && std::abs(p.params.y) <= 8.0f)) {
    throw PrimitiveError(what + "twist " + std::to_string(p.params.y) +
                         " (params.y) must be in [-8, 8] radians per unit height (its Lipschitz bound grows with it)");
  }
  if (p.kind == fractal_pyramid && !(p.params.y >= 0.0f && p.params.y <= 8.0f && p.params.y == std::floor(p.params.y))) {
    throw PrimitiveError(what + "iterations " + std::to_string(p.params.y) + " (params.y) must be a whole number in [0, 8]");
  }
  if (!std::isfinite(p.spin)) throw PrimitiveError(what + "spin " + std::to_string(p.spin) + " must be finite");
  if (p.spin != 0.0f && xz_reach(p) > 1.0f) {
    throw PrimitiveError(what + "spin " + std::to_string(p.spin) + " turns a shape reaching " +
                         std::to_string(xz_reach(p)) + " from its axis out of its AABB; use spin 0 or a smaller scale");
  }
}

/// The sample-like defaults of each kind: parameters, colour, spin.
inline Primitive default_primitive(PrimitiveKind k) {
  static constexpr std::array<glm::vec3, primitive_count> colours{
      glm::vec3{0.9f, 0.4f, 0.3f}, {0.3f, 0.6f, 0.95f}, {0.95f, 0.8f, 0.2f}, {0.5f, 0.85f, 0.5f}, {0.85f, 0.5f, 0.85f},
      {0.3f, 0.85f, 0.85f}, {0.95f, 0.6f, 0.3f}, {0.7f, 0.7f, 0.75f}, {0.55f, 0.45f, 0.9f}, {0.9f, 0.75f, 0.55f}};
  Primitive p{.kind = k, .albedo = colours[k]};
  if (k == box) p.params = {0.6f, 0.6f, 0.6f, 0.0f};
  if (k == metaballs) p.params = {0.6f, 0.25f, 0.0f, 0.0f};
  if (k == twisted_torus) p.params = {1.0f, 3.0f, 0.0f, 0.0f};
  // 0.95: a surface lying on the AABB face (y = -1 at scale 1) hangs on the clip's rounding;
  // on an H100 a row of base pixels missed that lavapipe and the CPU hit.
  if (k == fractal_pyramid) p.params = {0.95f, 4.0f, 0.0f, 0.0f};
  if (k == square_torus || k == cog) p.spin = 0.6f;
  if (k == twisted_torus) p.spin = 0.8f;
  return p;
}

/// The whole sample set, in kind order.
inline std::array<Primitive, primitive_count> default_primitives() {
  std::array<Primitive, primitive_count> all;
  for (std::uint32_t k = 0; k < primitive_count; ++k) all[k] = default_primitive(static_cast<PrimitiveKind>(k));
  return all;
}

/// The hit record of a primitive.
inline PrimitiveRecord record_of(const Primitive& p) {
  return {p.albedo, p.reflectance, p.params, p.kind, object_id(p.kind), p.spin, 0.0f};
}
/// The ground's record: a reflective checker.
inline constexpr PrimitiveRecord plane_record{{0.85f, 0.85f, 0.85f}, 0.25f, {}, 0, plane_id, 0.0f, 1.0f};
/// The ground: y = 0, x and z within +-plane_half (world space).
inline constexpr float plane_half = 14.0f;

/// Where the scene puts primitive `k`: the sample's grid (two rows of five on the ground), or
/// `isolated`, 100 units apart with no ground, so a camera sees one alone (tests, gallery, benchmark).
enum class Layout { sample, isolated };
inline glm::vec3 placement(PrimitiveKind k, Layout layout) {
  if (layout == Layout::isolated) return {100.0f * static_cast<float>(k), 0.0f, 0.0f};
  const float column = static_cast<float>(k % 5) - 2.0f, row = k < 5 ? 1.0f : -1.0f;
  return {2.6f * column, 1.0f, 1.4f * row};
}

/// Camera on the whole sample grid.
inline pr::Camera sample_camera(std::uint32_t width, std::uint32_t height) {
  return pr::look_at({0.0f, 6.0f, 13.5f}, {0.0f, 0.5f, 0.0f}, 45.0f, width, height);
}
/// Camera on primitive k alone (Layout::isolated): from the front, a little above.
inline pr::Camera isolated_camera(PrimitiveKind k, std::uint32_t width, std::uint32_t height) {
  const glm::vec3 c = placement(k, Layout::isolated);
  return pr::look_at(c + glm::vec3(0.0f, 1.8f, 4.2f), c, 40.0f, width, height);
}

/// The knobs primitive kind k accepts (analytic kinds: no methods), with its defaults: its own
/// pick from the shipped calibration tables, the cheapest setting at 1920x1080 that meets
/// ErrorBudget{}, a picture that cannot be told from exact, there and at 640x360
/// (tests/examples/march_defaults_test.cpp checks each against the tables). At 2 footprints the
/// fractal pyramid steps over thin parts at 640x360 (0.95% of its pixels on a surface behind),
/// and at half a footprint it misses 0.17% there: a quarter footprint meets both.
/// Where plain and Lipschitz-scaled steps cost the same (a bound of 1), the Lipschitz ones: they
/// stay safe if the shape's bound grows.
inline const pr::MarchCapabilities& capabilities(PrimitiveKind k) {
  static const pr::MarchCapabilities analytic{"analytic", {}, {pr::MarchNormal::analytic}, 0, pr::march_base_knobs};
  static const std::array<pr::MarchCapabilities, primitive_count> marched = [] {
    std::array<pr::MarchCapabilities, primitive_count> c;
    auto lipschitz = [](float threshold, bool refine, pr::MarchNormal normal) {
      pr::MarchCapabilities caps = pr::sdf_capabilities();
      caps.defaults.method = pr::MarchMethod::lipschitz;
      caps.defaults.relaxation = 1.0f;
      std::erase(caps.methods, pr::MarchMethod::lipschitz);  // the default first
      caps.methods.insert(caps.methods.begin(), pr::MarchMethod::lipschitz);
      caps.defaults.threshold = threshold;
      caps.defaults.refine = refine ? 1u : 0u;
      caps.defaults.normal = normal;
      return caps;
    };
    c[metaballs] = pr::metaball_capabilities();                                      // segment, 2 footprints: 22.6
    c[mini_spheres] = lipschitz(0.5f, true, pr::MarchNormal::tetrahedral);           // 21.3
    c[round_cube] = lipschitz(0.5f, true, pr::MarchNormal::tetrahedral);             // 17.4
    c[square_torus] = lipschitz(0.5f, false, pr::MarchNormal::central);              // 19.7
    c[twisted_torus] = pr::sdf_capabilities();                                       // relaxed 1.5, 2 footprints: 34.2
    c[twisted_torus].defaults.threshold = 2.0f;
    // Its bound is above 1 (1 + |twist| sqrt(2): 5.2 at the default twist): its field refuses
    // plain sphere steps, which would overshoot (conservative at twist 0).
    std::erase(c[twisted_torus].methods, pr::MarchMethod::sphere);
    c[cog] = lipschitz(0.5f, false, pr::MarchNormal::central);                       // 20.2
    c[cylinder] = lipschitz(2.0f, true, pr::MarchNormal::central);                   // 19.0
    c[fractal_pyramid] = lipschitz(0.25f, true, pr::MarchNormal::central);           // 27.3
    return c;
  }();
  return k <= spheres ? analytic : marched[k];
}

/// An SDF primitive's Lipschitz bound at its params: its field's. sdf.glsl's sdf_lipschitz,
/// here so the scene needs no GLSL compiled as C++ (d3d12_scene_test checks the two agree).
inline float lipschitz(const Primitive& p) {
  return p.kind == twisted_torus ? 1.0f + std::abs(p.params.y) * 1.4142136f : 1.0f;
}

/// The SceneConstants::knobs entry of kind k: the metaballs' are read from the uniform, an SDF's
/// are handed to its field by set_frame (d3d12_scene.hpp).
inline pr::MarchKnobs& knobs(SceneConstants& c, PrimitiveKind k) { return c.knobs[object_id(k)]; }

/// Throws UsageError unless every marched kind's knobs are valid (march/knobs.hpp's validate).
inline void validate_knobs(const SceneConstants& c) {
  for (std::uint32_t k = metaballs; k < primitive_count; ++k) {
    pr::validate(c.knobs[object_id(static_cast<PrimitiveKind>(k))], capabilities(static_cast<PrimitiveKind>(k)),
                 primitive_names[k]);
  }
}

/// Default knobs and light for `camera`, at `time` seconds.
inline SceneConstants default_constants(const pr::Camera& camera, float time) {
  const glm::vec3 eye(camera.eye);
  SceneConstants c{camera, eye + glm::vec3(-6.0f, 9.0f, 2.0f), 0.2f, glm::vec3(1.0f), time, {0.45f, 0.62f, 0.9f},
                   flag_shadows | flag_reflections, max_depth_limit, {}};
  for (pr::MarchKnobs& k : c.knobs) k = pr::march_base_knobs;  // ids no primitive has (the ground): unread, valid
  for (std::uint32_t k = 0; k < primitive_count; ++k) {
    c.knobs[object_id(static_cast<PrimitiveKind>(k))] = capabilities(static_cast<PrimitiveKind>(k)).defaults;
  }
  return c;
}

/// Declares on `scene` the C++ constants above that the shaders read.
template <class AnyScene>
void add_constants(AnyScene& scene) {
  PROCEDURAY_SCENE_CONSTANTS(scene, flag_shadows, flag_reflections, flag_debug,
                             max_depth_limit);
}

}  // namespace d3d12
