// The CIS 565 ray-tracing project's scene, as a newcomer writes it from the README: a ground,
// three spheres of different materials, an animated metaball blob, Phong with hard shadows and
// reflections to a chosen depth. Everything the shaders know comes from here: the structs, the
// lights (proceduray::Lights), the blob (proceduray::Metaballs, data, not GLSL), its box
// (metaballs_bounds), the trace functions (glsl_for); shading is the library's shading/lights.glsl.
//
//   cis565::Cis565Scene scene(5);                               // reflections up to depth 5
//   proceduray::vk::Renderer renderer(ctx, scene, scene.renderer_options());
//   renderer.set(cis565::constants_slot, cis565::default_constants(640, 360, 0.0f, 3));   // depth 3 this frame
//
// Object ids (flag_ids: the image's red channel): 0 sky, 1 ground, 2-4 spheres, 5 blob.
#pragma once

#include "../common/paths.hpp"

#include <proceduray/march/metaballs.hpp>
#include <proceduray/proceduray.hpp>
#include <proceduray/shader/lights.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace cis565 {

namespace pr = proceduray;

/// The radiance ray's payload: its colour, its depth (1 = the camera ray) and its share of the pixel.
struct Radiance {
  glm::vec3 colour;
  std::uint32_t depth;
  float weight;
  std::uint32_t id;  ///< object hit, for flag_ids
};
PROCEDURAY_STRUCT(Radiance, scalar, colour, depth, weight, id);
struct Shadow {
  std::uint32_t occluded;
};
PROCEDURAY_STRUCT(Shadow, scalar, occluded);
/// What the intersection shaders hand the closest-hit shader: the object-space normal.
struct SurfaceHit {
  glm::vec3 normal;
};
PROCEDURAY_STRUCT(SurfaceHit, scalar, normal);
/// Hit record: the material (shading/whitted.glsl's WhittedMaterial, plus the id).
struct Material {
  glm::vec3 albedo;
  float diffuse;
  float specular;
  float shininess;
  float reflectance;
  std::uint32_t id;
};
PROCEDURAY_STRUCT(Material, scalar, albedo, diffuse, specular, shininess, reflectance, id);

inline constexpr std::uint32_t flag_shadows = 1u, flag_ids = 2u;

/// The uniform every stage reads (binding 2).
struct Constants {
  pr::Camera camera;
  pr::Lights lights;
  pr::Metaballs blob;
  glm::vec4 ambient;
  glm::vec4 sky;
  float time;
  std::uint32_t max_depth;  ///< radiance rays per path this frame, 1..the scene's depth limit
  float min_weight;         ///< a reflection adding less to the pixel is not traced
  std::uint32_t flags;      ///< flag_shadows, flag_ids
};
PROCEDURAY_STRUCT(Constants, scalar, camera, lights, blob, ambient, sky, time, max_depth, min_weight, flags);

inline constexpr pr::UniformSlot<Constants> constants_slot{.binding = 2, .name = "constants"};

/// The shader compatibility layer: each struct in its category (std::variant alternatives).
using Interface = pr::ShaderInterface<pr::Payload<Radiance, Shadow>, pr::RootComponent<Constants>,
                                      pr::RootArguments<Material>, pr::Attributes<SurfaceHit>>;

enum ObjectId : std::uint32_t { sky_id = 0, ground_id = 1, sphere0_id = 2, blob_id = 5 };

/// The spheres: centre, radius, material.
struct SphereSpec {
  glm::vec3 centre;
  float radius;
  Material material;
};
inline const std::array<SphereSpec, 3> spheres{{
    {{-2.2f, 1.0f, 0.0f}, 1.0f, {{0.85f, 0.2f, 0.15f}, 0.9f, 0.3f, 30.0f, 0.0f, sphere0_id}},        // matte red
    {{0.0f, 1.0f, -1.2f}, 1.0f, {{0.9f, 0.9f, 0.92f}, 0.2f, 0.8f, 120.0f, 0.85f, sphere0_id + 1}},  // mirror
    {{2.2f, 0.8f, 0.4f}, 0.8f, {{0.2f, 0.4f, 0.9f}, 0.8f, 0.6f, 60.0f, 0.25f, sphere0_id + 2}},     // glossy blue
}};
inline const Material ground_material{{0.75f, 0.75f, 0.7f}, 0.9f, 0.1f, 10.0f, 0.15f, ground_id};
inline const Material blob_material{{0.3f, 0.85f, 0.35f}, 0.8f, 0.5f, 40.0f, 0.1f, blob_id};
/// Where the blob's local origin sits in the world.
inline const glm::vec3 blob_position{0.6f, 1.1f, 2.0f};

/// The blob: three sources on slow paths (data: change them here, no GLSL to edit).
inline pr::Metaballs default_blob() {
  return pr::make_metaballs({pr::metaball({-0.3f, 0.0f, 0.0f}, 0.55f, {0.25f, 0.1f, 0.0f}, {1.1f, 0.7f, 0.0f}),
                             pr::metaball({0.3f, 0.0f, 0.1f}, 0.5f, {0.0f, 0.25f, 0.1f}, {0.0f, 0.9f, 1.3f}),
                             pr::metaball({0.0f, 0.3f, -0.1f}, 0.45f, {0.2f, 0.0f, 0.2f}, {0.7f, 0.0f, 1.1f}, {1.0f, 0.0f, 0.0f})},
                            0.3f);
}

/// The frame's constants at `time` seconds, `depth` radiance rays per path.
inline Constants default_constants(std::uint32_t width, std::uint32_t height, float time, std::uint32_t depth,
                                   std::uint32_t flags = flag_shadows) {
  Constants c{};
  c.camera = pr::look_at({0.0f, 3.0f, 9.0f}, {0.0f, 0.8f, 0.0f}, 40.0f, width, height);
  c.lights = pr::make_lights({pr::point_light({-4.0f, 8.0f, 5.0f}, glm::vec3(0.9f)),
                              pr::directional_light({1.0f, 2.0f, 1.5f}, glm::vec3(0.25f))});
  c.blob = default_blob();
  c.ambient = glm::vec4(0.08f, 0.08f, 0.1f, 0.0f);
  c.sky = glm::vec4(0.45f, 0.6f, 0.85f, 1.0f);
  c.time = time;
  c.max_depth = depth;
  c.min_weight = 0.01f;
  c.flags = flags;
  return c;
}

/// The scene, with recursion for reflections up to `depth_limit` radiance rays per path.
class Cis565Scene : public pr::Scene<Interface> {
 public:
  explicit Cis565Scene(std::uint32_t depth_limit = 5) : m_depth_limit(depth_limit) {
    if (depth_limit < 1 || depth_limit > 8) {
      throw pr::UsageError("Cis565Scene: depth limit " + std::to_string(depth_limit) + " is outside 1..8; a path "
                           "needs its camera ray (1) and each level of reflection adds one");
    }
    const auto radiance = add_ray<Radiance>("radiance", {.miss = "radiance.rmiss", .flags = pr::RayFlags::opaque});
    add_ray<Shadow>("shadow", {.miss = "shadow.rmiss",
                               .flags = pr::RayFlags::terminate_on_first_hit | pr::RayFlags::skip_closest_hit |
                                        pr::RayFlags::opaque});
    set_global_signature(pr::default_global_signature({constants_slot}));
    add_constant("max_depth_limit", m_depth_limit);
    PROCEDURAY_SCENE_CONSTANTS(*this, flag_shadows, flag_ids);
    add_raygen("raygen.rgen");
    // Each reflection nests a radiance ray in a closest hit, and the deepest hit traces shadow rays.
    set_max_recursion_depth(depth_limit + 1);
    const auto material = add_local_signature<Material>("material");
    pr::add_object(*this, "ground", {.geometry = pr::GeometryDesc::triangles(pr::quad_xz({-20.0f, -20.0f}, {20.0f, 20.0f})),
                                     .closest_hit = {{radiance, "ground.rchit"}}},
                   material, {ground_material});
    std::vector<pr::InstanceTransform> at;
    std::vector<Material> materials;
    for (const SphereSpec& s : spheres) {
      at.push_back(pr::instance_transform(glm::scale(glm::translate(glm::mat4(1.0f), s.centre), glm::vec3(s.radius))));
      materials.push_back(s.material);
    }
    pr::add_object<SurfaceHit>(*this, "spheres", {.geometry = pr::GeometryDesc::procedural({pr::Aabb{}}, at),
                                                  .intersection = "sphere.rint", .closest_hit = {{radiance, "shade.rchit"}}},
                               material, materials);
    pr::add_object<SurfaceHit>(
        *this, "blob",
        {.geometry = pr::GeometryDesc::procedural({pr::metaballs_bounds(default_blob())},
                                                  {pr::instance_transform(glm::translate(glm::mat4(1.0f), blob_position))}),
         .intersection = "blob.rint", .closest_hit = {{radiance, "shade.rchit"}}},
        material, {blob_material});
  }

  std::uint32_t depth_limit() const noexcept { return m_depth_limit; }

  /// Shaders from this example's folder.
  pr::vk::RendererOptions renderer_options(std::filesystem::path cache = {}) const {
    return {.shader_dirs = {examples::examples_dir() / "04_cis565_scene" / "shaders"}, .pipeline_cache = std::move(cache)};
  }

 private:
  std::uint32_t m_depth_limit;
};

}  // namespace cis565
