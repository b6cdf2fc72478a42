// The report's figure 3 scene, host side: entities, instances and shader-table entries.
//
//   paper::PaperScene scene;
//   proceduray::vk::Renderer renderer(ctx, scene.build(ctx.limits()), paper::renderer_options());
//
// SBT: 2 ray types (radiance 0, shadow 1), so each geometry takes 2 hit records per instance
// block; the Pac-men get one block each (their own materials), the rest share theirs.
#pragma once

#include "../common/cli.hpp"
#include "paper_types.hpp"

#include <proceduray/proceduray.hpp>

#include <optional>

namespace paper {

inline constexpr pr::UniformSlot<SceneConstants> constants_slot{.binding = 2, .name = "constants"};

class PaperScene {
 public:
  PaperScene() {
    using pr::HitGroupKind;
    m_radiance = m_scene.add_ray<RadiancePayload>("radiance", {.miss = "radiance.rmiss"});
    m_shadow = m_scene.add_ray<ShadowPayload>("shadow", {.miss = "shadow.rmiss"});
    m_material = m_scene.add_local_signature<MaterialRecord>("material");
    m_scene.add_hit_group("plane", {.kind = HitGroupKind::triangles, .closest_hit = "plane.rchit"});
    m_scene.add_hit_group("plane_shadow", {.kind = HitGroupKind::triangles});
    const pr::TriangleMesh quad{{{plane_min.x, 0, plane_min.y}, {plane_max.x, 0, plane_min.y},
                                 {plane_max.x, 0, plane_max.y}, {plane_min.x, 0, plane_max.y}}, {0, 2, 1, 0, 3, 2}};
    m_plane = m_scene.add_geometry("plane", pr::GeometryDesc::triangles(quad));
    const std::vector<Placement> pacmen(pacman_placements.begin(), pacman_placements.end());
    m_pacman = add_procedural("pacman", pacman_aabb, pacmen);
    m_julia = add_procedural("julia", julia_aabb, {julia_placement});
    m_mandelbulb = add_procedural("mandelbulb", mandelbulb_aabb, {mandelbulb_placement});
    m_scene.add_global_signature("global", {.bindings = {{pr::BindingKind::acceleration_structure, 0, 0, 1, "tlas"},
                                                         {pr::BindingKind::storage_image, 1, 0, 1, "image"},
                                                         constants_slot}});
  }

  /// Pass one (entries) and two (the table), for a device's limits.
  const pr::ShaderBindingTable& build(const pr::DeviceLimits& limits) {
    m_table.emplace(m_scene);
    m_table->add_raygen("raygen.rgen");
    m_table->set_global_signature(m_scene.global_signature_id("global"));
    m_table->set_max_recursion_depth(max_recursion_depth);
    bind("plane", m_plane, plane_material);
    for (std::uint32_t i = 0; i < 2; ++i) bind("pacman", m_pacman, pacman_materials[i], i);
    bind("julia", m_julia, julia_material);
    bind("mandelbulb", m_mandelbulb, mandelbulb_material);
    m_sbt.emplace(m_table->build(limits));
    return *m_sbt;
  }

  const pr::Scene& scene() const { return m_scene; }
  pr::GeometryId julia() const { return m_julia; }

 private:
  pr::GeometryId add_procedural(const std::string& id, pr::Aabb box, const std::vector<Placement>& placements) {
    m_scene.add_hit_group<ProceduralHit>(id, {.kind = pr::HitGroupKind::procedural, .closest_hit = "shade.rchit",
                                              .intersection = id + ".rint"});
    m_scene.add_hit_group<ProceduralHit>(id + "_shadow",
                                         {.kind = pr::HitGroupKind::procedural, .intersection = id + ".rint"});
    std::vector<pr::InstanceTransform> instances;
    for (const Placement& p : placements) instances.push_back(pr::instance_transform(placement_matrix(p)));
    return m_scene.add_geometry(id, pr::GeometryDesc::procedural({box}, instances));
  }
  void bind(const std::string& id, pr::GeometryId g, const MaterialRecord& m,
            std::uint32_t instance = pr::ShaderTable::all_instances) {
    m_table->add_hit(m_radiance, m_scene.hit_group_id(id), m_material, m, g, instance);
    m_table->add_hit(m_shadow, m_scene.hit_group_id(id + "_shadow"), m_material, m, g, instance);
  }

  pr::Scene m_scene;
  pr::RayId<RadiancePayload> m_radiance;
  pr::RayId<ShadowPayload> m_shadow;
  pr::LocalSignatureId<MaterialRecord> m_material;
  pr::GeometryId m_plane, m_pacman, m_julia, m_mandelbulb;
  std::optional<pr::ShaderTable> m_table;
  std::optional<pr::ShaderBindingTable> m_sbt;
};

/// Shaders from this example's folder, with the scene's constants after the derived declarations.
inline pr::vk::RendererOptions renderer_options(std::filesystem::path cache = {}) {
  return {.shader_dirs = {examples::examples_dir() / "02_paper_scene" / "shaders"},
          .extra_declarations = extra_declarations(), .pipeline_cache = std::move(cache)};
}

}  // namespace paper
