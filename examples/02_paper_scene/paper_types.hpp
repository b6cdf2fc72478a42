// The report's figure 3 scene, shader side: every struct that crosses to the GLSL, and the
// scene's fixed numbers (AABBs, placements, materials, the fractals' starting knobs).
//
//   paper::SceneConstants constants = paper::default_constants(1024, 768, time);   // binding 2
//   // each shader compiles with glsl_for(plan, stage, name): the AABBs (pacman_aabb_min, ...) and
//   // the flag_* constants PaperScene declares on itself
//
// Conventions the shaders in shaders/ (next to this file) rely on:
//   set 0: binding 0 TLAS (raygen, closest hit); binding 1 rgba8 storage image (raygen);
//          binding 2 uniform SceneConstants, scalar layout (raygen, miss, closest hit, intersection).
//   Rays:  radiance = 0 (miss "radiance.rmiss"), shadow = 1 (miss "shadow.rmiss"); shaders trace
//          with the generated trace_radiance / trace_shadow (glsl_for), which fill the flags the
//          scene declares, sbtRecordOffset = missIndex = <ray>_ray and sbtRecordStride = ray_count.
//   Hit groups (radiance | shadow):
//          Plane      triangles   closest hit plane.rchit         | no shaders
//          Pacman     procedural  shade.rchit + pacman.rint       | pacman.rint
//          Julia      distance field (fractals.glsl julia_field): shade.rchit + the generated intersection
//          Mandelbulb distance field (fractals.glsl mandelbulb_field): likewise
//   Hit records carry a MaterialRecord (radiance; shadow records carry one too, unread).
//   Raygen and miss records carry no data. Geometry: one AABB per procedural BLAS (the
//   *_aabb below, in local space), instances placed by the *_placement(s) below; the plane is
//   proceduray::quad_xz(plane_min, plane_max): two triangles at y = 0, normal +y.
#pragma once

#include "../common/tracing.hpp"

#include <proceduray/proceduray.hpp>

#include <vector>

namespace paper {

namespace pr = proceduray;

/// SceneConstants::flags bits: shadows, reflections, and the object-id view (r = id / 255,
/// g = marching steps of the primary hit / 255, for tests).
inline constexpr std::uint32_t flag_shadows = 1u, flag_reflections = 2u, flag_object_ids = 4u;
/// MaterialRecord::object_id of each object; 0 is the sky.
enum ObjectId : std::uint32_t { sky_id = 0, plane_id = 1, pacman0_id = 2, pacman1_id = 3, julia_id = 4, mandelbulb_id = 5 };
/// Largest SceneConstants::max_depth a PaperScene honours by default (radiance segments, primary
/// included); a scene may be built for up to max_depth_supported.
inline constexpr std::uint32_t max_depth_limit = 3;
inline constexpr std::uint32_t max_depth_supported = 16;
/// How reflections and shadows are traced (examples/common/tracing.hpp).
using Tracing = examples::Tracing;

/// Per-frame uniform (set 0, binding 2). The fractals' march knobs are not here: the library
/// owns them (Renderer::set_field_knobs) and reports each hit's threshold (FieldHit).
PROCEDURAY_DEFINE_STRUCT(SceneConstants, scalar,
    (pr::Camera, camera),                ///< primary rays; camera.pixel_angle sets the footprint
    (glm::vec3, light_position),         ///< point light, world space
    (float, ambient),                    ///< ambient fraction of the albedo; default 0.15
    (glm::vec3, light_colour),           ///< default white
    (float, time),                       ///< seconds: animates the Julia constant and the Mandelbulb iterations (a field parameter)
    (glm::vec3, sky_colour),             ///< zenith colour; the horizon is lighter
    (std::uint32_t, max_depth),          ///< radiance segments, primary included (3: two reflections), <= max_depth_limit
    (std::uint32_t, flags),              ///< flag_* bits; default shadows | reflections
    (float, min_weight),                 ///< reflections adding less than this to the pixel are not traced; default 0.05
    (pr::CutPlanes, julia_cuts),         ///< the planes cutting the Julia set (a field parameter); default julia_cut
    (float, pacman_mouth));              ///< the Pac-men's mouth half angle, radians (pacman.rint); default pacman_mouth

/// The radiance ray's payload (location 0). The fields after `weight` carry a hit back to
/// raygen when tracing is iterative (Tracing::iterative); recursive tracing leaves them unread.
PROCEDURAY_DEFINE_STRUCT(RadiancePayload, scalar,
    (glm::vec3, colour),                 ///< linear RGB returned by the hit or miss (iterative: the ambient part)
    (std::uint32_t, depth),              ///< 0 for primary rays
    (std::uint32_t, object_id),          ///< ObjectId of the hit (sky_id on a miss)
    (float, steps),                      ///< marching steps of the hit (0 for analytic surfaces)
    (float, weight),                     ///< how much this ray's colour counts in the pixel (1 for primary rays)
    (glm::vec3, direct),                 ///< iterative: the point light's term if nothing shadows it
    (float, fresnel),                    ///< iterative: the reflection's share (0: none to trace)
    (glm::vec3, next_origin),            ///< iterative: where secondary rays start (offset off the surface)
    (float, hit_t),                      ///< iterative: the hit's t, the path length from the eye
    (glm::vec3, next_direction),         ///< iterative: the reflection's direction
    (float, light_distance),             ///< iterative: from the hit to the light (0: facing away, no shadow ray)
    (glm::vec3, light_direction));       ///< iterative: unit, towards the light

/// The shadow ray's payload (location 1): preset to 1, the shadow miss sets 0.
PROCEDURAY_DEFINE_STRUCT(ShadowPayload, scalar, (std::uint32_t, occluded));

/// Hit root arguments: one material per object, read by plane.rchit and shade.rchit.
PROCEDURAY_DEFINE_STRUCT(MaterialRecord, scalar,
    (glm::vec3, albedo),                 ///< base colour
    (float, reflectance),                ///< Schlick F0 of the mirror reflection; 0 = none
    (glm::vec3, albedo_alt),             ///< second checker colour (plane)
    (float, checker_size),               ///< checker square size in world units; 0 = plain albedo
    (float, diffuse),                    ///< Phong diffuse weight
    (float, specular),                   ///< Phong specular weight
    (float, shininess),                  ///< Phong exponent (>= 1)
    (std::uint32_t, object_id));         ///< ObjectId, for the object-id view

/// The shader compatibility layer: each struct in its category (std::variant alternatives). Every
/// procedural object reports pr::FieldHit (object-space normal, evaluations): the fractals' generated
/// intersections and pacman.rint alike, so one shade.rchit shades them all.
using Interface = pr::ShaderInterface<pr::Payload<RadiancePayload, ShadowPayload>, pr::RootComponent<SceneConstants>,
                                      pr::RootArguments<MaterialRecord>, pr::Attributes<pr::FieldHit>>;

/// Local AABBs: Pac-man is the unit sphere; the Julia set (c near (-0.2, 0.6, 0.2, 0.2), within
/// about 1.2 of the origin, lowest y about -1.02) and the Mandelbulb (within about 1.07) fit in
/// theirs with a margin (checked in tests/shaders). Placements put each object's lowest point on y = 0.
inline constexpr pr::Aabb pacman_aabb{glm::vec3(-1.0f), glm::vec3(1.0f)};
inline constexpr pr::Aabb julia_aabb{glm::vec3(-1.5f), glm::vec3(1.5f)};
inline constexpr pr::Aabb mandelbulb_aabb{glm::vec3(-1.25f), glm::vec3(1.25f)};
/// Side by side on the plane, left to right: Pac-man 0, Julia, Mandelbulb, Pac-man 1.
inline const std::vector<pr::Placement> pacman_placements{{{-3.75f, 0.9f, 0.0f}, 0.9f}, {{3.75f, 0.9f, 0.0f}, 0.9f}};
inline constexpr pr::Placement julia_placement{{-1.25f, 0.87f, 0.0f}, 0.85f};
inline constexpr pr::Placement mandelbulb_placement{{1.25f, 1.02f, 0.0f}, 0.95f};
/// The ground: y = 0, x and z from plane_min to plane_max (world space).
inline constexpr glm::vec2 plane_min{-12.0f, -10.0f}, plane_max{12.0f, 10.0f};

/// Materials (hit root arguments) of each object.
inline constexpr MaterialRecord plane_material{{0.85f, 0.85f, 0.85f}, 0.15f, {0.3f, 0.3f, 0.35f}, 1.0f, 0.9f, 0.1f, 20.0f,
                                               plane_id};
inline const std::vector<MaterialRecord> pacman_materials{{{1.0f, 0.8f, 0.1f}, 0.1f, {}, 0.0f, 0.9f, 0.5f, 40.0f, pacman0_id},
                                                          {{0.2f, 0.6f, 1.0f}, 0.1f, {}, 0.0f, 0.9f, 0.5f, 40.0f, pacman1_id}};
inline constexpr MaterialRecord julia_material{{0.9f, 0.3f, 0.25f}, 0.2f, {}, 0.0f, 0.9f, 0.6f, 60.0f, julia_id};
inline constexpr MaterialRecord mandelbulb_material{{0.35f, 0.85f, 0.45f}, 0.2f, {}, 0.0f, 0.9f, 0.6f, 60.0f, mandelbulb_id};

/// The fractals' starting knobs (iterations: Julia 10, Mandelbulb 8; the Mandelbulb's are the
/// animation's maximum): each its own pick from the shipped calibration tables, the cheapest
/// setting at 1920x1080 that meets ErrorBudget{} there and at 640x360
/// (tests/examples/march_defaults_test.cpp checks). The Julia set's: half a footprint without the
/// bisection (11.4 evaluations per ray); the Mandelbulb's: the library's, a quarter footprint (52.4).
inline const pr::MarchKnobs julia_knobs = [] {
  pr::MarchKnobs k = pr::fractal_capabilities(10).defaults;
  k.threshold = 0.5f;
  k.refine = 0;
  return k;
}();
inline const pr::MarchKnobs mandelbulb_knobs = pr::fractal_capabilities(8).defaults;

/// The plane cutting the Julia set (object space; keeps dot(xyz, p) <= w): normalize(0.3, 0.3, 1)
/// to five digits, removing the front so the camera looks at the slice through the set. Data:
/// the Julia field reads SceneConstants::julia_cuts, and the reference (reference_objects.hpp) this.
inline const glm::vec4 julia_cut{0.27617f, 0.27617f, 0.92057f, 0.1f};
/// The Pac-men's mouth half angle (radians, about 34 degrees): data as well (pacman.rint reads
/// SceneConstants::pacman_mouth).
inline constexpr float pacman_mouth = 0.6f;

/// Where default_constants' camera stands (world.hpp takes its origin there).
inline constexpr glm::vec3 default_eye{0.0f, 2.5f, 8.0f};

/// Camera framing all four objects, default light, at `time` seconds.
inline SceneConstants default_constants(std::uint32_t width, std::uint32_t height, float time) {
  SceneConstants c{pr::look_at(default_eye, {0.0f, 0.9f, 0.0f}, 50.0f, width, height),
                   {-6.0f, 8.0f, 5.0f}, 0.15f, glm::vec3(1.0f), time, {0.45f, 0.62f, 0.9f},
                   3, flag_shadows | flag_reflections, 0.05f, {}, pacman_mouth};
  c.julia_cuts = pr::make_cut_planes({julia_cut});
  return c;
}

}  // namespace paper
