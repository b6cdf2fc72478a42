// The D3D12 procedural-geometry sample's scene, host side: a triangle ground plane and one AABB
// geometry per primitive, the sample's analytic and volumetric hit groups, each SDF a distance
// field (its own hit groups, its intersection written by the library), radiance and shadow rays.
//
//   d3d12::D3d12Scene scene;                                  // the sample's grid on the ground
//   proceduray::vk::Renderer renderer(ctx, scene, d3d12::renderer_options());
//   d3d12::set_frame(renderer, d3d12::default_constants(d3d12::sample_camera(w, h), time));
//
// Hit-group table: 2 ray types, so 2 records per geometry (11 geometries: 22 records, the
// sample's count). Geometry g's records are at 2g (radiance) and 2g + 1 (shadow):
//
//   hit region  | plane | plane_shadow | analytic | analytic_shadow | ... | fractal_pyramid | fractal_pyramid_shadow |
//   geometry    |   ground (0)         |  box (1)                   | ... |  fractal_pyramid (10)                    |
//
// Animation needs no acceleration-structure work: primitives spin and the metaballs move in
// local space as SceneConstants::time advances; the AABBs and instances never change.
#pragma once

#include "../common/paths.hpp"
#include "d3d12_types.hpp"

#include <proceduray/proceduray.hpp>

#include <span>
#include <vector>

namespace d3d12 {

inline constexpr pr::UniformSlot<SceneConstants> constants_slot{.binding = 2, .name = "constants"};

/// Shaders from this example's folder (each compiled with its stage's declarations from the plan).
inline pr::vk::RendererOptions renderer_options(std::filesystem::path cache = {}) {
  return {.shader_dirs = {examples::examples_dir() / "03_d3d12_scene" / "shaders"}, .pipeline_cache = std::move(cache)};
}

/// The sample's scene, declared from Interface's categories, and its primitives.
class D3d12Scene : public pr::Scene<Interface> {
 public:
  /// The given primitives (each validated: throws PrimitiveError) placed by `layout`; the
  /// ground only with Layout::sample; per-pixel `outputs` of the camera rays (none: no cost).
  /// `tracing`: Tracing::iterative traces shadows and reflections from raygen (recursion depth 1,
  /// derived: none declared); renderer_options() then compiles the shaders for it.
  explicit D3d12Scene(std::span<const Primitive> primitives, Layout layout = Layout::sample, pr::OutputSet outputs = {},
                      Tracing tracing = Tracing::recursive)
      : m_tracing(tracing) {
    for (const Primitive& p : primitives) validate(p);
    set_outputs(outputs);
    m_primitives.assign(primitives.begin(), primitives.end());
    m_radiance = add_ray<RadiancePayload>("radiance", {.miss = "radiance.rmiss", .flags = pr::RayFlags::opaque});
    // The sample's shadow flags: accept the first hit, skip closest hit, cull back faces.
    m_shadow = add_ray<ShadowPayload>("shadow", {.miss = "shadow.rmiss",
                                                 .flags = pr::RayFlags::terminate_on_first_hit |
                                                          pr::RayFlags::skip_closest_hit | pr::RayFlags::opaque |
                                                          pr::RayFlags::cull_back_facing});
    m_record = add_local_signature<PrimitiveRecord>("primitive");
    add_raygen("raygen.rgen");
    if (tracing == Tracing::recursive) set_max_recursion_depth(d3d12::max_recursion_depth);
    add_constants(*this);  // the flags and limits the shaders read
    if (tracing == Tracing::iterative) add_define("D3D12_ITERATIVE");  // shadows and reflections from raygen
    set_global_signature({.bindings = {{pr::BindingKind::acceleration_structure, 0, 0, 1, "tlas"},
                                       {pr::BindingKind::storage_image, 1, 0, 1, "image"}, constants_slot}});
    if (layout == Layout::sample) {
      add_hit_group("plane", {.kind = pr::HitGroupKind::triangles, .closest_hit = "plane.rchit"});
      add_hit_group("plane_shadow", {.kind = pr::HitGroupKind::triangles});
      const float h = plane_half;
      const pr::TriangleMesh quad{{{-h, 0, -h}, {h, 0, -h}, {h, 0, h}, {-h, 0, h}}, {0, 2, 1, 0, 3, 2}};
      bind("plane", add_geometry("ground", pr::GeometryDesc::triangles(quad)), plane_record);
    }
    for (const std::string group : {"analytic", "volumetric"}) {
      add_hit_group<pr::FieldHit>(group, {.kind = pr::HitGroupKind::procedural, .closest_hit = "shade.rchit",
                                          .intersection = group + ".rint"});
      add_hit_group<pr::FieldHit>(group + "_shadow", {.kind = pr::HitGroupKind::procedural, .intersection = group + ".rint"});
    }
    const pr::Aabb local{glm::vec3(-1.0f), glm::vec3(1.0f)};
    for (const Primitive& p : m_primitives) {
      const pr::InstanceTransform at = pr::instance_transform(glm::translate(glm::mat4(1.0f), placement(p.kind, layout)));
      const std::string name(primitive_names[p.kind]);
      if (p.kind > metaballs) {
        add_sdf(p, name, at);
        continue;
      }
      bind(std::string(hit_group_of(p.kind)), add_geometry(name, pr::GeometryDesc::procedural({local}, {at})), record_of(p));
    }
  }
  D3d12Scene() : D3d12Scene(default_primitives()) {}
  /// The sample's primitives and layout with per-pixel outputs.
  explicit D3d12Scene(pr::OutputSet outputs) : D3d12Scene(default_primitives(), Layout::sample, outputs) {}

  std::span<const Primitive> primitives() const { return m_primitives; }
  Tracing tracing() const noexcept { return m_tracing; }

  /// Shaders from this example's folder.
  pr::vk::RendererOptions renderer_options(std::filesystem::path cache = {}) const {
    return d3d12::renderer_options(std::move(cache));
  }

 private:
  /// An SDF as a distance field of sdf_fields.glsl: its record's params and spin and the frame's
  /// time are its parameters, its bound its params' (d3d12::lipschitz), its starting knobs its kind's.
  void add_sdf(const Primitive& p, const std::string& name, pr::InstanceTransform at) {
    const std::vector<pr::FieldParameter> parameters{pr::field_parameter(m_record, &PrimitiveRecord::params),
                                                     pr::field_parameter(m_record, &PrimitiveRecord::spin),
                                                     pr::field_parameter(constants_slot, &SceneConstants::time)};
    pr::add_distance_field(*this, name, {.glsl = "sdf_fields.glsl", .function = name + "_field",
                                         .aabb = {glm::vec3(-1.0f), glm::vec3(1.0f)}, .lipschitz = lipschitz(p),
                                         .parameters = parameters, .knobs = capabilities(p.kind).defaults,
                                         .instances = {at}, .closest_hit = {{m_radiance, "shade.rchit"}}},
                           m_record, {record_of(p)});
  }

  /// Both rays' records for geometry `g`: group `group` for radiance, `<group>_shadow` for shadow.
  void bind(const std::string& group, pr::GeometryId g, const PrimitiveRecord& r) {
    add_hit(m_radiance, hit_group_id(group), m_record, r, g);
    add_hit(m_shadow, hit_group_id(group + "_shadow"), m_record, r, g);
  }

  Tracing m_tracing;
  std::vector<Primitive> m_primitives;
  pr::RayId<RadiancePayload> m_radiance;
  pr::RayId<ShadowPayload> m_shadow;
  pr::LocalSignatureId<PrimitiveRecord> m_record;
};

/// Sets a frame's constants on `renderer` (a D3d12Scene's), the view's pixel angle, and hands
/// each SDF's knobs (SceneConstants::knobs, what a sweep rewrites) to its field: the library
/// marches the SDFs, the volumetric shader reads the metaballs' from the uniform. Throws
/// UsageError for knobs a field does not accept (naming it).
inline void set_frame(pr::vk::Renderer& renderer, const SceneConstants& c) {
  renderer.set(constants_slot, c);
  renderer.set_pixel_angle(c.camera.pixel_angle);
  for (const pr::PlannedField& f : renderer.plan().fields()) {
    for (std::uint32_t k = metaballs + 1; k < primitive_count; ++k) {
      if (f.field.id == primitive_names[k]) renderer.set_field_knobs(f.geometry, c.knobs[object_id(static_cast<PrimitiveKind>(k))]);
    }
  }
}

}  // namespace d3d12
