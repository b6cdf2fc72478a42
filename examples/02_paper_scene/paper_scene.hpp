// The report's figure 3 scene, host side: rays, objects (geometry, hit groups, records), the table.
//
//   paper::PaperScene scene;
//   proceduray::vk::Renderer renderer(ctx, scene, scene.renderer_options());
//
// SBT: 2 ray types (radiance 0, shadow 1), so each geometry takes 2 hit records per instance
// block; the Pac-men get one block each (their own materials), the rest share theirs.
#pragma once

#include "../common/paths.hpp"
#include "paper_types.hpp"

#include <string>

namespace paper {

inline constexpr pr::UniformSlot<SceneConstants> constants_slot{.binding = 2, .name = "constants"};

/// The scene: its entities and entries, each type from its category of paper::Interface.
struct PaperScene : pr::SceneOf<Interface> {
  /// `outputs`: per-pixel outputs besides colour (the accuracy tool asks for t, normal, steps, flags).
  explicit PaperScene(pr::OutputSet outputs = {}) {
    set_outputs(outputs);
    const auto radiance = add_ray<RadiancePayload>("radiance", {.miss = "radiance.rmiss"});
    add_ray<ShadowPayload>("shadow", {.miss = "shadow.rmiss"});
    const auto material = add_local_signature<MaterialRecord>("material");
    set_global_signature(pr::default_global_signature({constants_slot}));
    add_raygen("raygen.rgen");
    set_max_recursion_depth(max_depth_limit + 1);  // the deepest radiance hit still traces a shadow ray
    pr::add_object(*this, "plane", {.geometry = pr::GeometryDesc::triangles(pr::quad_xz(plane_min, plane_max)),
                                    .closest_hit = {{radiance, "plane.rchit"}}}, material, {plane_material});
    // Each marched object: its own intersection shader for both rays, shade.rchit for radiance.
    const auto procedural = [&](const std::string& id, pr::Aabb box, const std::vector<pr::Placement>& at,
                                const std::vector<MaterialRecord>& materials) {
      pr::add_object<ProceduralHit>(*this, id, {.geometry = pr::GeometryDesc::procedural({box}, pr::transforms(at)),
                                                .intersection = id + ".rint", .closest_hit = {{radiance, "shade.rchit"}}},
                                    material, materials);
    };
    procedural("pacman", pacman_aabb, pacman_placements, pacman_materials);
    procedural("julia", julia_aabb, {julia_placement}, {julia_material});
    procedural("mandelbulb", mandelbulb_aabb, {mandelbulb_placement}, {mandelbulb_material});
  }

  /// Shaders from this example's folder, compiled with the declarations the build wrote into
  /// PAPER_GLSL_DIR (glsl/generate.cpp, run with no device; defined by CMake and Meson for every
  /// target that includes this header), then the flags and the AABBs. The build writes the
  /// scene without outputs; with outputs the renderer derives the declarations at run time.
  pr::vk::RendererOptions renderer_options(std::filesystem::path cache = {}) const {
    pr::vk::RendererOptions o{.shader_dirs = {examples::examples_dir() / "02_paper_scene" / "shaders"},
                              .extra_declarations = extra_declarations + pr::glsl_aabb_consts(*this),
                              .pipeline_cache = std::move(cache)};
    if (outputs().empty()) o.declarations = pr::glsl_files(examples::generated_glsl_dir(PAPER_GLSL_DIR));
    return o;
  }
};

}  // namespace paper
