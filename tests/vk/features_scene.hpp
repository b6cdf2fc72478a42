// A scene for the renderer's engine features: layers and masks, update policies, an any-hit
// cut-out and a callable. Flat colours, so pixels classify by colour alone:
//
//   A red ball     visible | casts_shadow, DynamicTransform (moves)
//   B blue ball    casts_shadow only (hidden from the camera, still shadows) unless show_b
//   C green ball   visible only: casts no shadow
//   D yellow ball  cut-out: not opaque, any-hit shaders ignore hits on its stripes
//   slab magenta   DynamicGeometry box, its AABBs set at run time
//   floor          grey, coloured by the "tint" callable, darkened where shadow rays hit
//                  (0.35 behind opaque objects, 0.5 where D's shadow any-hit terminated the ray)
//
//   FeaturesScene s({.show_b = true});
//   proceduray::vk::Renderer r(ctx, s.table(ctx), features_scene::options());
//   features_scene::prepare(r, w, h);
#pragma once

#include "test_paths.hpp"

#include <proceduray/proceduray.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <memory>
#include <optional>
#include <vector>

namespace features_scene {

namespace pr = proceduray;

struct Constants {
  pr::Camera camera;
  glm::vec4 sky;
  glm::vec4 light;  ///< direction toward the light
};
PROCEDURAY_STRUCT(Constants, scalar, camera, sky, light);
struct Probe {
  glm::vec3 rgb;
};
PROCEDURAY_STRUCT(Probe, scalar, rgb);
struct Shadow {
  std::uint32_t occluded;
};
PROCEDURAY_STRUCT(Shadow, scalar, occluded);
struct BallHit {
  glm::vec3 position;  ///< object space
};
PROCEDURAY_STRUCT(BallHit, scalar, position);
struct Paint {
  glm::vec4 rgb;
};
PROCEDURAY_STRUCT(Paint, scalar, rgb);
struct TintCall {
  glm::vec3 colour;
};
PROCEDURAY_STRUCT(TintCall, scalar, colour);
struct TintArgs {
  glm::vec4 factor;
};
PROCEDURAY_STRUCT(TintArgs, scalar, factor);
struct Box {
  glm::vec4 lo;
  glm::vec4 hi;
};
PROCEDURAY_STRUCT(Box, scalar, lo, hi);
using SceneInterface = proceduray::ShaderInterface<proceduray::Payload<Probe, Shadow, TintCall>, proceduray::RootComponent<Constants, Box>, proceduray::RootArguments<Paint, TintArgs>,
                                   proceduray::Attributes<BallHit>>;
using Scene = proceduray::Scene<SceneInterface>;

constexpr pr::UniformSlot<Constants> constants_slot{.binding = 2, .name = "constants"};
constexpr pr::StorageSlot<Box> boxes_slot{.binding = 3, .name = "boxes"};

inline constexpr float radius = 0.6f;
inline const std::array<glm::vec3, 4> centres{{{-3.0f, radius, 0.0f}, {-1.0f, radius, 0.0f}, {1.0f, radius, 0.0f},
                                               {3.0f, radius, 0.0f}}};
inline const std::array<glm::vec4, 4> colours{{{1, 0, 0, 1}, {0, 0, 1, 1}, {0, 1, 0, 1}, {1, 1, 0, 1}}};
inline const glm::vec4 floor_colour{0.8f, 0.8f, 0.8f, 1.0f};
inline const glm::vec4 slab_colour{1.0f, 0.0f, 1.0f, 1.0f};
inline const glm::vec4 sky_colour{0.2f, 0.4f, 0.9f, 1.0f};
/// Toward the light: up and back, so shadows fall toward the camera where it sees them.
inline const glm::vec3 light_direction = glm::normalize(glm::vec3(0.0f, 1.0f, -1.0f));
/// The slab's box on the left and on the right of the balls.
inline const pr::Aabb left_box{{-2.2f, 0.0f, 1.9f}, {-1.8f, 0.4f, 2.3f}};
inline const pr::Aabb right_box{{1.8f, 0.0f, 1.9f}, {2.2f, 0.4f, 2.3f}};

inline Constants constants(std::uint32_t width, std::uint32_t height) {
  return {pr::look_at({0.0f, 4.0f, 7.0f}, {0.0f, 0.0f, 0.5f}, 50.0f, width, height), sky_colour,
          glm::vec4(light_direction, 0.0f)};
}

inline Box box_of(const pr::Aabb& a) { return {glm::vec4(a.min, 0.0f), glm::vec4(a.max, 0.0f)}; }

/// Sets the constants and the slab's boxes buffer to `boxes`.
inline void prepare(pr::vk::Renderer& renderer, std::uint32_t width, std::uint32_t height,
                    std::vector<pr::Aabb> boxes = {left_box}) {
  renderer.set(constants_slot, constants(width, height));
  std::vector<Box> data;
  for (const pr::Aabb& a : boxes) data.push_back(box_of(a));
  renderer.set_storage(boxes_slot, std::span<const Box>(data));
}

/// What varies between fixtures.
struct Config {
  bool show_b = false;                       ///< B on the "visible" layer too
  bool cutout_opaque = false;                ///< D opaque: its any-hit shaders are skipped
  glm::vec4 tint{1.0f, 0.5f, 0.25f, 0.0f};  ///< the callable's record: floor colour factor
  std::uint32_t recursion_depth = 2;         ///< floor.rchit traces shadow rays; 0: depth not declared
};

class FeaturesScene {
 public:
  explicit FeaturesScene(Config config = {}) : m_config(config) {
    const std::uint8_t visible = m_scene.add_layer("visible");
    const std::uint8_t casts_shadow = m_scene.add_layer("casts_shadow");
    m_primary = m_scene.add_ray<Probe>("primary", {.miss = "sky.rmiss", .cull_mask = visible});
    m_shadow = m_scene.add_ray<Shadow>("shadow", {.miss = "shadow.rmiss",
                                                  .flags = pr::RayFlags::terminate_on_first_hit | pr::RayFlags::skip_closest_hit,
                                                  .cull_mask = casts_shadow});
    using pr::HitGroupKind;
    m_scene.add_hit_group("floor", {.kind = HitGroupKind::triangles, .closest_hit = "floor.rchit"});
    m_scene.add_hit_group("floor_shadow", {.kind = HitGroupKind::triangles});
    m_scene.add_hit_group<BallHit>("ball", {.kind = HitGroupKind::procedural, .closest_hit = "flat.rchit",
                                            .intersection = "ball.rint"});
    m_scene.add_hit_group<BallHit>("ball_shadow", {.kind = HitGroupKind::procedural, .intersection = "ball.rint"});
    m_scene.add_hit_group<BallHit>("cutout", {.kind = HitGroupKind::procedural, .closest_hit = "flat.rchit",
                                              .any_hit = "cutout.rahit", .intersection = "ball.rint"});
    m_scene.add_hit_group<BallHit>("cutout_shadow", {.kind = HitGroupKind::procedural,
                                                     .any_hit = "cutout_shadow.rahit", .intersection = "ball.rint"});
    m_scene.add_hit_group<BallHit>("slab", {.kind = HitGroupKind::procedural, .closest_hit = "flat.rchit",
                                            .intersection = "slab.rint"});
    m_scene.add_hit_group<BallHit>("slab_shadow", {.kind = HitGroupKind::procedural, .intersection = "slab.rint"});

    pr::GeometryDesc floor = pr::GeometryDesc::triangles(
        {{{-8, 0, -6}, {8, 0, -6}, {8, 0, 6}, {-8, 0, 6}}, {0, 2, 1, 0, 3, 2}});
    floor.mask = visible;
    m_floor = m_scene.add_geometry("floor", floor);
    const std::array<std::uint8_t, 4> masks{static_cast<std::uint8_t>(visible | casts_shadow),
                                            config.show_b ? static_cast<std::uint8_t>(visible | casts_shadow) : casts_shadow,
                                            visible, static_cast<std::uint8_t>(visible | casts_shadow)};
    const char* names[] = {"a", "b", "c", "d"};
    for (std::size_t i = 0; i < 4; ++i) {
      const glm::mat4 m = glm::scale(glm::translate(glm::mat4(1.0f), centres[i]), glm::vec3(radius));
      pr::GeometryDesc ball = pr::GeometryDesc::procedural({pr::Aabb{}}, {pr::instance_transform(m)});
      ball.mask = masks[i];
      if (i == 0) ball.update = pr::UpdatePolicy::DynamicTransform;
      if (i == 3) ball.opaque = config.cutout_opaque;
      m_balls[i] = m_scene.add_geometry(names[i], ball);
    }
    pr::GeometryDesc slab = pr::GeometryDesc::procedural({left_box});
    slab.mask = static_cast<std::uint8_t>(visible | casts_shadow);
    slab.update = pr::UpdatePolicy::DynamicGeometry;
    m_slab = m_scene.add_geometry("slab", slab);
    m_tint = m_scene.add_callable<TintCall>("tint", {.shader = "tint.rcall"});
    m_scene.add_global_signature("global", {.bindings = {{pr::BindingKind::acceleration_structure, 0, 0, 1, "tlas"},
                                                         {pr::BindingKind::storage_image, 1, 0, 1, "image"},
                                                         constants_slot, boxes_slot}});
    m_paint = m_scene.add_local_signature<Paint>("paint");
    m_tint_args = m_scene.add_local_signature<TintArgs>("tint_args");
  }

  const Scene& scene() const { return m_scene; }
  pr::GeometryId ball(std::size_t i) const { return m_balls.at(i); }
  pr::GeometryId slab() const { return m_slab; }
  pr::GeometryId floor() const { return m_floor; }

  /// The scene with its entries.
  const Scene& table(const pr::vk::Context&) {
    m_entries = m_scene;
    Scene& t = m_entries;
    t.add_raygen("scene.rgen");
    t.set_global_signature(m_scene.global_signature_id("global"));
    if (m_config.recursion_depth != 0) t.set_max_recursion_depth(m_config.recursion_depth);
    t.add_hit(m_primary, m_scene.hit_group_id("floor"), m_paint, Paint{floor_colour}, m_floor);
    t.add_hit(m_shadow, m_scene.hit_group_id("floor_shadow"), m_floor);
    for (std::size_t i = 0; i < 4; ++i) {
      const bool cut = i == 3;
      t.add_hit(m_primary, m_scene.hit_group_id(cut ? "cutout" : "ball"), m_paint, Paint{colours[i]}, m_balls[i]);
      t.add_hit(m_shadow, m_scene.hit_group_id(cut ? "cutout_shadow" : "ball_shadow"), m_balls[i]);
    }
    t.add_hit(m_primary, m_scene.hit_group_id("slab"), m_paint, Paint{slab_colour}, m_slab);
    t.add_hit(m_shadow, m_scene.hit_group_id("slab_shadow"), m_slab);
    t.add_callable_record(m_tint, m_tint_args, TintArgs{m_config.tint});
    return m_entries;
  }

  static pr::vk::RendererOptions options() {
    return {.shader_dirs = {test_source_dir() / "vk" / "shaders" / "features"}};
  }

 private:
  Config m_config;
  Scene m_scene;
  pr::RayId<Probe> m_primary;
  pr::RayId<Shadow> m_shadow;
  pr::GeometryId m_floor, m_slab;
  std::array<pr::GeometryId, 4> m_balls;
  pr::CallableId<TintCall> m_tint;
  pr::LocalSignatureId<Paint> m_paint;
  pr::LocalSignatureId<TintArgs> m_tint_args;
  Scene m_entries;  // m_scene and the entries of the last table() call
};

}  // namespace features_scene
