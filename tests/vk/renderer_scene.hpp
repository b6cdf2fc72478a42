// A small scene for renderer tests: a triangle floor and two procedural balls (one BLAS,
// two instances, a colour each from its own hit record), under a sky from a uniform.
//
//   RendererScene s;                                   // scene + entries + built table (balls Static)
//   proceduray::vk::Renderer r(ctx, s.table(ctx), s.options());
//   r.set(renderer_scene::constants_slot, renderer_scene::constants(w, h, sky));
#pragma once

#include "test_paths.hpp"

#include <proceduray/proceduray.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <memory>
#include <optional>

namespace renderer_scene {

namespace pr = proceduray;

struct Constants {
  pr::Camera camera;
  glm::vec4 sky;
};
PROCEDURAY_STRUCT(Constants, scalar, camera, sky);
struct Colour {
  glm::vec3 rgb;
};
PROCEDURAY_STRUCT(Colour, scalar, rgb);
struct BallHit {
  glm::vec3 normal;
};
PROCEDURAY_STRUCT(BallHit, scalar, normal);
struct Paint {
  glm::vec4 rgb;
};
PROCEDURAY_STRUCT(Paint, scalar, rgb);
/// Per-instance multiplier of the ball colour, from a storage buffer indexed by instance.
struct Tint {
  glm::vec4 rgb;
};
PROCEDURAY_STRUCT(Tint, scalar, rgb);
using SceneInterface = proceduray::ShaderInterface<proceduray::Payload<Colour>, proceduray::RootComponent<Constants, Tint>, proceduray::RootArguments<Paint>,
                                   proceduray::Attributes<BallHit>>;
using Scene = proceduray::Scene<SceneInterface>;

constexpr pr::UniformSlot<Constants> constants_slot{.binding = 2, .name = "constants"};
constexpr pr::StorageSlot<Tint> tints_slot{.binding = 3, .name = "tints"};

inline const glm::vec3 ball_centres[2] = {{-1.2f, 0.0f, 0.0f}, {1.2f, 0.0f, 0.0f}};
inline const glm::vec4 ball_colours[2] = {{1, 0, 0, 1}, {0, 0, 1, 1}};
inline const glm::vec4 floor_colour{0.5f, 0.5f, 0.5f, 1.0f};

inline Constants constants(std::uint32_t width, std::uint32_t height, glm::vec4 sky = {0.2f, 0.4f, 0.8f, 1.0f}) {
  return {pr::look_at({0.0f, 1.0f, 6.0f}, {0.0f, 0.0f, 0.0f}, 45.0f, width, height), sky};
}

/// Gives every uniform and storage buffer a value: the default constants and white tints.
inline void prepare(pr::vk::Renderer& renderer, std::uint32_t width, std::uint32_t height) {
  renderer.set(constants_slot, constants(width, height));
  const Tint white[] = {{glm::vec4(1.0f)}, {glm::vec4(1.0f)}, {glm::vec4(1.0f)}, {glm::vec4(1.0f)}};
  renderer.set_storage(tints_slot, std::span<const Tint>(white));
}

/// The scene and its shader table, built for a context's limits.
class RendererScene {
 public:
  explicit RendererScene(pr::UpdatePolicy ball_update = pr::UpdatePolicy::Static,
                         pr::UpdatePolicy floor_update = pr::UpdatePolicy::Static) {
    m_scene.add_ray<Colour>("primary", {.miss = "sky.rmiss"});
    m_scene.add_hit_group<BallHit>("ball", {.kind = pr::HitGroupKind::procedural, .closest_hit = "ball.rchit",
                                            .intersection = "ball.rint"});
    m_scene.add_hit_group("floor", {.kind = pr::HitGroupKind::triangles, .closest_hit = "floor.rchit"});
    pr::TriangleMesh quad{{{-6, -1, -6}, {6, -1, -6}, {6, -1, 6}, {-6, -1, 6}}, {0, 2, 1, 0, 3, 2}};
    pr::GeometryDesc floor = pr::GeometryDesc::triangles(quad);
    floor.update = floor_update;
    m_floor = m_scene.add_geometry("floor", floor);
    std::vector<pr::InstanceTransform> balls;
    for (const glm::vec3& c : ball_centres) balls.push_back(pr::instance_transform(glm::translate(glm::mat4(1), c)));
    pr::GeometryDesc ball = pr::GeometryDesc::procedural({pr::Aabb{}}, balls);
    ball.update = ball_update;
    m_ball = m_scene.add_geometry("ball", ball);
    m_scene.add_global_signature("global", {.bindings = {{pr::BindingKind::acceleration_structure, 0, 0, 1, "tlas"},
                                                         {pr::BindingKind::storage_image, 1, 0, 1, "image"},
                                                         constants_slot, tints_slot}});
    m_paint = m_scene.add_local_signature<Paint>("paint");
  }

  const Scene& scene() const { return m_scene; }
  pr::GeometryId ball() const { return m_ball; }

  /// The scene with its entries; `with_ball_entries = false` leaves the balls unbound.
  const Scene& table(const pr::vk::Context&, bool with_ball_entries = true) {
    m_entries = m_scene;
    m_entries.add_raygen("scene.rgen");
    m_entries.set_global_signature(m_scene.global_signature_id("global"));
    const auto primary = m_scene.ray_id<Colour>("primary");
    m_entries.add_hit(primary, m_scene.hit_group_id("floor"), m_paint, Paint{floor_colour}, m_floor);
    if (with_ball_entries) {
      for (std::uint32_t i = 0; i < 2; ++i) {
        m_entries.add_hit(primary, m_scene.hit_group_id("ball"), m_paint, Paint{ball_colours[i]}, m_ball, i);
      }
    }
    return m_entries;
  }

  static pr::vk::RendererOptions options(std::filesystem::path cache = {}) {
    return {.shader_dirs = {test_source_dir() / "vk" / "shaders"}, .pipeline_cache = std::move(cache)};
  }

 private:
  Scene m_scene;
  pr::GeometryId m_floor;
  pr::GeometryId m_ball;
  pr::LocalSignatureId<Paint> m_paint;
  Scene m_entries;  // m_scene and the entries of the last table() call
};

}  // namespace renderer_scene
