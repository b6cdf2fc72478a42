// The report's figure 3 scene, host side: rays, objects (geometry, hit groups, records), the table.
//
//   paper::PaperScene scene;                       // its constants declared on it (flags, depth limit)
//   proceduray::vk::Renderer renderer(ctx, scene, scene.renderer_options());
//   paper::set_frame(renderer, paper::default_constants(1024, 768, time));   // each frame: constants, pixel angle
//   paper::PaperScene portable({}, paper::Tracing::iterative);   // runs where maxRayRecursionDepth is 1
//
// Recursion: recursive tracing declares depth_limit + 1 (the deepest radiance hit traces a
// shadow ray); iterative tracing declares none, so the pipeline gets the derived minimum, 1:
// no stage but raygen traces (the renderer checks the SPIR-V and refuses a closest hit that
// does). Both honour SceneConstants::max_depth up to depth_limit.
//
// SBT: 2 ray types (radiance 0, shadow 1), so each geometry takes 2 hit records per instance
// block; the Pac-men get one block each (their own materials), the rest share theirs.
#pragma once

#include "../common/paths.hpp"
#include "paper_types.hpp"
#include "world.hpp"

#include <string>

namespace paper {

inline constexpr pr::UniformSlot<SceneConstants> constants_slot{.binding = 2, .name = "constants"};

/// The scene: its entities and entries, each type from its category of paper::Interface.
struct PaperScene : pr::Scene<Interface> {
  /// `outputs`: per-pixel outputs besides colour (the accuracy tool asks for t, normal, steps, flags).
  /// `world`: where the scene stands and the origin of its float coordinates (world.hpp); the
  /// frame's constants then go through World::place.
  explicit PaperScene(pr::OutputSet outputs = {}, Tracing tracing = Tracing::recursive,
                      std::uint32_t depth_limit = max_depth_limit, const World& world = {}) {
    if (depth_limit == 0 || depth_limit > max_depth_supported) {
      throw pr::UsageError("PaperScene: depth limit " + std::to_string(depth_limit) + " is out of range; give 1 to " +
                           std::to_string(max_depth_supported) + " radiance segments (primary included)");
    }
    set_outputs(outputs);
    const auto radiance = add_ray<RadiancePayload>("radiance", {.miss = "radiance.rmiss", .flags = pr::RayFlags::opaque});
    // Shadow rays accept any hit and run no closest hit: the miss shader clears `occluded`.
    add_ray<ShadowPayload>("shadow", {.miss = "shadow.rmiss", .flags = pr::RayFlags::terminate_on_first_hit |
                                                                       pr::RayFlags::skip_closest_hit | pr::RayFlags::opaque});
    const auto material = add_local_signature<MaterialRecord>("material");
    set_global_signature(pr::default_global_signature({constants_slot}));
    add_raygen("raygen.rgen");
    if (tracing == Tracing::recursive) set_max_recursion_depth(depth_limit + 1);  // + the deepest hit's shadow ray
    // What the shaders read beyond the derived declarations: the flag bits, the depth limit and,
    // when iterative, the switch that keeps the closest hit from tracing.
    PROCEDURAY_SCENE_CONSTANTS(*this, flag_shadows, flag_reflections, flag_object_ids);
    add_constant("max_depth_limit", depth_limit);
    if (tracing == Tracing::iterative) add_define("PAPER_ITERATIVE");
    const std::vector<pr::RayShader> shade{{radiance, "shade.rchit"}};
    const auto plane = pr::GeometryDesc::triangles(pr::quad_xz(plane_min, plane_max), {world.transform({})});
    pr::add_object(*this, "plane", {.geometry = plane, .closest_hit = {{radiance, "plane.rchit"}}}, material, {plane_material});
    const auto pacmen = pr::GeometryDesc::procedural({pacman_aabb}, world.transforms(pacman_placements));
    pr::add_object<pr::FieldHit>(*this, "pacman", {.geometry = pacmen, .intersection = "pacman.rint", .closest_hit = shade},
                                 material, pacman_materials);
    // The fractals are distance fields (shaders/fractals.glsl): the library marches them, with
    // their knobs. The time and the Julia set's cut planes are read per frame.
    const auto time = pr::field_parameter(constants_slot, &SceneConstants::time);
    const auto cuts = pr::field_parameter(constants_slot, &SceneConstants::julia_cuts);
    pr::add_distance_field(*this, "julia", {.glsl = "fractals.glsl", .function = "julia_field", .aabb = julia_aabb,
                                            .lipschitz = 1.0f, .iterations = julia_knobs.iterations, .parameters = {time, cuts},
                                            .knobs = julia_knobs, .normal = "julia_field_normal",
                                            .instances = {world.transform(julia_placement)}, .closest_hit = shade},
                           material, {julia_material});
    pr::add_distance_field(*this, "mandelbulb", {.glsl = "fractals.glsl", .function = "mandelbulb_field",
                                                 .aabb = mandelbulb_aabb, .lipschitz = 1.0f,
                                                 .iterations = mandelbulb_knobs.iterations, .parameters = {time},
                                                 .knobs = mandelbulb_knobs, .instances = {world.transform(mandelbulb_placement)},
                                                 .closest_hit = shade},
                           material, {mandelbulb_material});
  }

  /// Shaders from this example's folder (each compiled with its stage's declarations from the
  /// plan; the build writes the same text into PAPER_GLSL_DIR with glsl/generate.cpp).
  pr::vk::RendererOptions renderer_options(std::filesystem::path cache = {}) const {
    return {.shader_dirs = {examples::examples_dir() / "02_paper_scene" / "shaders"}, .pipeline_cache = std::move(cache)};
  }
};

/// Sets a frame's constants on `renderer` (a PaperScene's), and the view's pixel angle, which the
/// fractals' footprint thresholds scale with.
inline void set_frame(pr::vk::Renderer& renderer, const SceneConstants& c) {
  renderer.set(constants_slot, c);
  renderer.set_pixel_angle(c.camera.pixel_angle);
}

}  // namespace paper
