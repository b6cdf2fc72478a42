// The report's figure 3 scene, shader side: every struct that crosses to the GLSL, its
// generated declarations per shader, and the scene's fixed numbers (AABBs, placements).
//
//   paper::SceneConstants constants = paper::default_constants(1024, 768, time);   // binding 2
//   // each shader compiles with glsl_for(table, stage, name) + paper::extra_declarations()
//
// Conventions the shaders in shaders/ (next to this file) rely on:
//   set 0: binding 0 TLAS (raygen, closest hit); binding 1 rgba8 storage image (raygen);
//          binding 2 uniform SceneConstants, scalar layout (raygen, miss, closest hit, intersection).
//   Rays:  radiance = 0 (miss "radiance.rmiss"), shadow = 1 (miss "shadow.rmiss"); traceRayEXT
//          uses sbtRecordOffset = missIndex = ray index and sbtRecordStride = ray_count = 2.
//   Hit groups (radiance | shadow):
//          Plane      triangles   closest hit plane.rchit         | no shaders
//          Pacman     procedural  shade.rchit + pacman.rint        | pacman.rint
//          Julia      procedural  shade.rchit + julia.rint         | julia.rint
//          Mandelbulb procedural  shade.rchit + mandelbulb.rint    | mandelbulb.rint
//   Hit records carry a MaterialRecord (radiance; shadow records may carry one too, unread).
//   Raygen and miss records carry no data. Geometry: one AABB per procedural BLAS (the
//   *_aabb below, in local space), instances placed by the *_placement below; the plane is
//   two triangles at y = 0 spanning plane_min..plane_max in x and z.
#pragma once

#include <proceduray/scene/geometry.hpp>
#include <proceduray/shader/shader.hpp>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace paper {

namespace pr = proceduray;

/// Ray indices (sbtRecordOffset and missIndex) and their count (sbtRecordStride).
inline constexpr std::uint32_t radiance_ray = 0, shadow_ray = 1, ray_count = 2;
/// SceneConstants::flags bits: shadows, reflections, and the object-id view (r = id / 255,
/// g = marching steps of the primary hit / 255, for tests).
inline constexpr std::uint32_t flag_shadows = 1u, flag_reflections = 2u, flag_object_ids = 4u;
/// MaterialRecord::object_id of each object; 0 is the sky.
enum ObjectId : std::uint32_t { sky_id = 0, plane_id = 1, pacman0_id = 2, pacman1_id = 3, julia_id = 4, mandelbulb_id = 5 };
/// Largest SceneConstants::max_depth the shaders honour (radiance segments, primary included).
inline constexpr std::uint32_t max_depth_limit = 3;
/// maxPipelineRayRecursionDepth: the deepest radiance hit still traces a shadow ray.
inline constexpr std::uint32_t max_recursion_depth = max_depth_limit + 1;

/// Per-frame uniform (set 0, binding 2). Knobs are run-time values: a sweep rewrites them.
struct SceneConstants {
  pr::Camera camera;             ///< primary rays; camera.pixel_angle sets the footprint
  glm::vec3 light_position;      ///< point light, world space
  float ambient;                 ///< ambient fraction of the albedo; default 0.15
  glm::vec3 light_colour;        ///< default white
  float time;                    ///< seconds: animates the Julia constant and the Mandelbulb iterations
  glm::vec3 sky_colour;          ///< zenith colour; the horizon is lighter
  std::uint32_t max_steps;       ///< sphere-tracing steps at most (a miss when exhausted); default 256
  float epsilon;                 ///< absolute hit threshold (world units); default 1e-4
  float footprint_scale;         ///< hit threshold in pixel footprints, max(epsilon, k * pixel_angle * t); default 0.5
  float step_scale;              ///< step = step_scale * distance estimate (1 / Lipschitz, or a fudge); default 1
  float over_relaxation;         ///< w in [1, 2), 1 = plain sphere tracing; default 1
  std::uint32_t julia_iterations;       ///< default 10
  std::uint32_t mandelbulb_iterations;  ///< maximum of the animated count; default 8
  std::uint32_t max_depth;       ///< radiance segments, primary included (3: two reflections); <= max_depth_limit
  std::uint32_t flags;           ///< flag_* bits; default shadows | reflections
  float min_weight;              ///< reflections that would add less than this to the pixel are not traced; default 0.05
};
PROCEDURAY_STRUCT(SceneConstants, scalar, camera, light_position, ambient, light_colour, time, sky_colour, max_steps,
                  epsilon, footprint_scale, step_scale, over_relaxation, julia_iterations, mandelbulb_iterations,
                  max_depth, flags, min_weight);

/// The radiance ray's payload (location 0).
struct RadiancePayload {
  glm::vec3 colour;         ///< linear RGB returned by the hit or miss
  std::uint32_t depth;      ///< 0 for primary rays
  std::uint32_t object_id;  ///< ObjectId of the hit (sky_id on a miss)
  float steps;              ///< marching steps of the hit (0 for analytic surfaces)
  float weight;             ///< how much this ray's colour counts in the pixel (1 for primary rays)
};
PROCEDURAY_STRUCT(RadiancePayload, scalar, colour, depth, object_id, steps, weight);

/// The shadow ray's payload (location 1): preset to 1, the shadow miss sets 0.
struct ShadowPayload {
  std::uint32_t occluded;
};
PROCEDURAY_STRUCT(ShadowPayload, scalar, occluded);

/// What every procedural intersection shader reports (16 bytes).
struct ProceduralHit {
  glm::vec3 normal;  ///< object space, outward
  float steps;       ///< marching steps taken (0 for Pac-man)
};
PROCEDURAY_STRUCT(ProceduralHit, scalar, normal, steps);

/// Hit record data: one material per object, read by plane.rchit and shade.rchit.
struct MaterialRecord {
  glm::vec3 albedo;         ///< base colour
  float reflectance;        ///< Schlick F0 of the mirror reflection; 0 = none
  glm::vec3 albedo_alt;     ///< second checker colour (plane)
  float checker_size;       ///< checker square size in world units; 0 = plain albedo
  float diffuse;            ///< Phong diffuse weight
  float specular;           ///< Phong specular weight
  float shininess;          ///< Phong exponent (>= 1)
  std::uint32_t object_id;  ///< ObjectId, for the object-id view
};
PROCEDURAY_STRUCT(MaterialRecord, scalar, albedo, reflectance, albedo_alt, checker_size, diffuse, specular, shininess,
                  object_id);

using Interface = pr::ShaderInterface<pr::Payload<RadiancePayload, ShadowPayload>, pr::RootComponent<SceneConstants>,
                                      pr::RootArguments<MaterialRecord>, pr::Attributes<ProceduralHit>>;

/// Translation and uniform scale of an instance (local AABB -> world).
struct Placement {
  glm::vec3 translation;
  float scale;
};
/// The instance's object-to-world matrix.
inline glm::mat4 placement_matrix(Placement p) {
  return glm::scale(glm::translate(glm::mat4(1.0f), p.translation), glm::vec3(p.scale));
}

/// Local AABBs: Pac-man is the unit sphere; the Julia set (c near (-0.2, 0.6, 0.2, 0.2), within
/// about 1.2 of the origin, lowest y about -1.02) and the Mandelbulb (within about 1.07) fit in
/// theirs with a margin (checked in tests/shaders). Placements put each object's lowest point on y = 0.
inline constexpr pr::Aabb pacman_aabb{glm::vec3(-1.0f), glm::vec3(1.0f)};
inline constexpr pr::Aabb julia_aabb{glm::vec3(-1.5f), glm::vec3(1.5f)};
inline constexpr pr::Aabb mandelbulb_aabb{glm::vec3(-1.25f), glm::vec3(1.25f)};
/// Side by side on the plane, left to right: Pac-man 0, Julia, Mandelbulb, Pac-man 1.
inline constexpr std::array<Placement, 2> pacman_placements{Placement{{-3.75f, 0.9f, 0.0f}, 0.9f},
                                                            Placement{{3.75f, 0.9f, 0.0f}, 0.9f}};
inline constexpr Placement julia_placement{{-1.25f, 0.87f, 0.0f}, 0.85f};
inline constexpr Placement mandelbulb_placement{{1.25f, 1.02f, 0.0f}, 0.95f};
/// The ground: y = 0, x and z from plane_min to plane_max (world space).
inline constexpr glm::vec2 plane_min{-12.0f, -10.0f}, plane_max{12.0f, 10.0f};

/// Materials (hit record data) of each object.
inline constexpr MaterialRecord plane_material{{0.85f, 0.85f, 0.85f}, 0.15f, {0.3f, 0.3f, 0.35f}, 1.0f, 0.9f, 0.1f, 20.0f, plane_id};
inline constexpr std::array<MaterialRecord, 2> pacman_materials{
    MaterialRecord{{1.0f, 0.8f, 0.1f}, 0.1f, {}, 0.0f, 0.9f, 0.5f, 40.0f, pacman0_id},
    MaterialRecord{{0.2f, 0.6f, 1.0f}, 0.1f, {}, 0.0f, 0.9f, 0.5f, 40.0f, pacman1_id}};
inline constexpr MaterialRecord julia_material{{0.9f, 0.3f, 0.25f}, 0.2f, {}, 0.0f, 0.9f, 0.6f, 60.0f, julia_id};
inline constexpr MaterialRecord mandelbulb_material{{0.35f, 0.85f, 0.45f}, 0.2f, {}, 0.0f, 0.9f, 0.6f, 60.0f, mandelbulb_id};

/// Camera framing all four objects, default light and knobs, at `time` seconds.
inline SceneConstants default_constants(std::uint32_t width, std::uint32_t height, float time) {
  return {pr::look_at({0.0f, 2.5f, 8.0f}, {0.0f, 0.9f, 0.0f}, 50.0f, width, height),
          {-6.0f, 8.0f, 5.0f}, 0.15f, glm::vec3(1.0f), time, {0.45f, 0.62f, 0.9f},
          256, 1e-4f, 0.5f, 1.0f, 1.0f, 10, 8, 3, flag_shadows | flag_reflections, 0.05f};
}

/// What the shaders need beyond the declarations the scene derives (glsl_for): the C++
/// constants above as GLSL consts (flag bits, depth limit, local AABBs).
inline std::string extra_declarations() {
  std::string out = pr::glsl_const("flag_shadows", flag_shadows) + pr::glsl_const("flag_reflections", flag_reflections) +
                    pr::glsl_const("flag_object_ids", flag_object_ids) + pr::glsl_const("max_depth_limit", max_depth_limit);
  const std::pair<std::string, pr::Aabb> boxes[] = {{"pacman", pacman_aabb}, {"julia", julia_aabb}, {"mandelbulb", mandelbulb_aabb}};
  for (const auto& [name, box] : boxes) out += pr::glsl_const(name + "_aabb_min", box.min) + pr::glsl_const(name + "_aabb_max", box.max);
  return out;
}

/// The example's shader files (in examples/02_paper_scene/shaders/).
inline constexpr std::array<std::string_view, 8> shader_files{"raygen.rgen",  "radiance.rmiss", "shadow.rmiss",
                                                              "plane.rchit",  "shade.rchit",    "pacman.rint",
                                                              "julia.rint",   "mandelbulb.rint"};

}  // namespace paper
