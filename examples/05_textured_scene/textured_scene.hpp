// Meshes that shade and textures that sample, beside procedural objects: a tiled ground from a
// PNG, a smooth-shaded torus from an OBJ file (its normals computed by the loader and read per
// vertex through a MeshRef), a mirror sphere, an environment cube map for the sky and every
// reflection, and beads that appear and disappear over frames (Renderer::add_instance,
// remove_instance). The assets in assets/ were made here (make_assets.py, CC0).
//
//   textured::TexturedScene scene;                                   // reads assets/torus.obj
//   proceduray::vk::Renderer renderer(ctx, scene, scene.renderer_options());
//   textured::set_textures(renderer);                                 // ground.png, the sky cube
//   renderer.set(textured::constants_slot, textured::default_constants(640, 360));
//   textured::Beads beads;
//   beads.step(renderer, scene.beads(), frame);                       // one appears, the oldest goes
//
// Debug views (Constants::flags): flag_ids puts the object id in red; flag_albedo shows the
// ground's texture unlit; flag_normals shows world normals as colour, flag_flat the torus's face
// normals instead of its interpolated ones (tests compare the two).
#pragma once

#include "../common/paths.hpp"

#include <proceduray/proceduray.hpp>
#include <proceduray/shader/lights.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <vector>

namespace textured {

namespace pr = proceduray;

struct Radiance {
  glm::vec3 colour;
  std::uint32_t depth;  ///< 1 = the camera ray
  float weight;         ///< its share of the pixel
  std::uint32_t id;     ///< object hit, for flag_ids
};
PROCEDURAY_STRUCT(Radiance, scalar, colour, depth, weight, id);
struct Shadow {
  std::uint32_t occluded;
};
PROCEDURAY_STRUCT(Shadow, scalar, occluded);
struct SurfaceHit {
  glm::vec3 normal;  ///< object space
};
PROCEDURAY_STRUCT(SurfaceHit, scalar, normal);
/// shading/lights.glsl's WhittedMaterial, plus the object id.
struct Material {
  glm::vec3 albedo;
  float diffuse;
  float specular;
  float shininess;
  float reflectance;
  std::uint32_t id;
};
PROCEDURAY_STRUCT(Material, scalar, albedo, diffuse, specular, shininess, reflectance, id);
/// The torus's record: its mesh (filled by the renderer) and its material.
struct MeshMaterial {
  pr::MeshRef<pr::ObjVertex> mesh;
  Material material;
};
PROCEDURAY_STRUCT(MeshMaterial, scalar, mesh, material);

inline constexpr std::uint32_t flag_shadows = 1u, flag_ids = 2u, flag_albedo = 4u, flag_normals = 8u, flag_flat = 16u;

struct Constants {
  pr::Camera camera;
  pr::Lights lights;
  glm::vec4 ambient;
  std::uint32_t max_depth;  ///< radiance rays per path, 1..max_depth_limit
  float min_weight;         ///< a reflection adding less to the pixel is not traced
  float ground_scale;       ///< ground texture copies per world unit
  std::uint32_t flags;
};
PROCEDURAY_STRUCT(Constants, scalar, camera, lights, ambient, max_depth, min_weight, ground_scale, flags);

inline constexpr pr::UniformSlot<Constants> constants_slot{.binding = 2, .name = "constants"};

/// The shader compatibility layer: each struct in its category (std::variant alternatives).
using Interface = pr::ShaderInterface<pr::Payload<Radiance, Shadow>, pr::RootComponent<Constants>,
                                      pr::RootArguments<Material, MeshMaterial>, pr::Attributes<SurfaceHit>>;
inline constexpr pr::TextureSlot ground_slot{.binding = 3, .name = "ground"};
inline constexpr pr::TextureSlot sky_slot{.binding = 4, .name = "sky", .cube = true};
inline constexpr std::uint32_t max_depth_limit = 3;

enum ObjectId : std::uint32_t { sky_id = 0, ground_id = 1, torus_id = 2, mirror_id = 3, bead_id = 4 };

inline const glm::vec3 torus_position{-1.6f, 0.6f, 0.5f};
inline const glm::vec3 mirror_centre{1.6f, 1.0f, -0.4f};
inline constexpr float mirror_radius = 1.0f;
inline constexpr float bead_radius = 0.3f;
inline constexpr std::uint32_t bead_slots = 8;
/// Where bead slot k sits: a ring in front of the objects.
inline glm::vec3 bead_centre(std::uint32_t k) {
  const float a = 6.2831853f * static_cast<float>(k) / bead_slots;
  return {3.2f * std::cos(a), bead_radius, 2.6f + 1.0f * std::sin(a)};
}


inline Constants default_constants(std::uint32_t width, std::uint32_t height, std::uint32_t flags = flag_shadows) {
  Constants c{};
  c.camera = pr::look_at({0.0f, 3.2f, 8.5f}, {0.0f, 0.6f, 0.0f}, 45.0f, width, height);
  c.lights = pr::make_lights({pr::point_light({-3.0f, 7.0f, 6.0f}, glm::vec3(0.9f)),
                              pr::directional_light({1.0f, 2.0f, 1.0f}, glm::vec3(0.2f))});
  c.ambient = glm::vec4(0.12f, 0.12f, 0.14f, 0.0f);
  c.max_depth = max_depth_limit;
  c.min_weight = 0.01f;
  c.ground_scale = 0.25f;  // one 64-texel texture per 4 x 4 world units: a tile is half a unit
  c.flags = flags;
  return c;
}

/// The sun's share in direction d (unit): a sharp glow around one direction.
inline float sun_glow(glm::vec3 d) {
  return std::pow(std::max(glm::dot(d, glm::normalize(glm::vec3(-0.4f, 0.5f, -0.75f))), 0.0f), 200.0f);
}

/// The sky in direction d (unit): from a pale horizon to a blue zenith, a warm sun, a darker ground
/// below, blended smoothly (a cube map's texels hold it well). Linear RGB, HDR: the sun passes 1.
inline glm::vec3 sky_colour(glm::vec3 d) {
  const float up = std::clamp(d.y, -1.0f, 1.0f);
  const glm::vec3 above = glm::mix(glm::vec3(0.85f, 0.9f, 1.0f), glm::vec3(0.25f, 0.45f, 0.85f), std::max(up, 0.0f));
  const float s = std::clamp((up + 0.15f) / 0.25f, 0.0f, 1.0f);  // below to above over -0.15..0.1
  const glm::vec3 c = glm::mix(glm::vec3(0.35f, 0.32f, 0.28f), above, s * s * (3.0f - 2.0f * s));
  return c + sun_glow(d) * glm::vec3(8.0f, 6.0f, 4.0f);
}

/// The direction through texel (x, y) of cube face f (+X, -X, +Y, -Y, +Z, -Z), as Vulkan lays faces out.
inline glm::vec3 cube_direction(std::uint32_t f, float s, float t) {
  const float u = 2.0f * s - 1.0f, v = 2.0f * t - 1.0f;  // s, t in 0..1, t down the face
  switch (f) {
    case 0: return glm::normalize(glm::vec3(1.0f, -v, -u));
    case 1: return glm::normalize(glm::vec3(-1.0f, -v, u));
    case 2: return glm::normalize(glm::vec3(u, 1.0f, v));
    case 3: return glm::normalize(glm::vec3(u, -1.0f, -v));
    case 4: return glm::normalize(glm::vec3(u, -v, 1.0f));
    default: return glm::normalize(glm::vec3(-u, -v, -1.0f));
  }
}

/// The environment cube map of sky_colour, `size` texels a side, 32-bit float.
inline pr::TextureData sky_cube(std::uint32_t size = 128) {
  std::vector<pr::TextureData> faces;
  for (std::uint32_t f = 0; f < 6; ++f) {
    std::vector<float> rgb;
    for (std::uint32_t y = 0; y < size; ++y) {
      for (std::uint32_t x = 0; x < size; ++x) {
        const glm::vec3 c = sky_colour(cube_direction(f, (x + 0.5f) / size, (y + 0.5f) / size));
        rgb.insert(rgb.end(), {c.r, c.g, c.b});
      }
    }
    faces.push_back(pr::TextureData::from_pixels(size, size, 3, std::span<const float>(rgb)));
  }
  return pr::make_cube(faces);
}

inline std::filesystem::path assets_dir() { return examples::examples_dir() / "05_textured_scene" / "assets"; }

/// The scene: ground, torus, mirror sphere, and the beads' geometry (no instance until added).
class TexturedScene : public pr::Scene<Interface> {
 public:
  TexturedScene() : m_torus(pr::load_obj(assets_dir() / "torus.obj")) {
    const auto radiance = add_ray<Radiance>("radiance", {.miss = "radiance.rmiss", .flags = pr::RayFlags::opaque});
    add_ray<Shadow>("shadow", {.miss = "shadow.rmiss",
                               .flags = pr::RayFlags::terminate_on_first_hit | pr::RayFlags::skip_closest_hit |
                                        pr::RayFlags::opaque});
    set_global_signature(pr::default_global_signature({constants_slot, ground_slot, sky_slot}));
    PROCEDURAY_SCENE_CONSTANTS(*this, max_depth_limit, flag_shadows, flag_ids, flag_albedo, flag_normals, flag_flat,
                               bead_slots);
    add_raygen("raygen.rgen");
    set_max_recursion_depth(max_depth_limit + 1);  // each reflection nests; the deepest hit traces shadows
    const auto material = add_local_signature<Material>("material");
    pr::add_object(*this, "ground", {.geometry = pr::GeometryDesc::triangles(pr::quad_xz({-30.0f, -30.0f}, {30.0f, 30.0f})),
                                     .closest_hit = {{radiance, "ground.rchit"}}},
                   material, {{{1.0f, 1.0f, 1.0f}, 0.9f, 0.1f, 10.0f, 0.0f, ground_id}});
    pr::GeometryDesc torus = pr::GeometryDesc::triangles(
        m_torus.triangles(), {pr::instance_transform(glm::translate(glm::mat4(1.0f), torus_position))});
    torus.vertex_data = m_torus.vertex_data();
    pr::add_object(*this, "torus", {.geometry = torus, .closest_hit = {{radiance, "mesh.rchit"}}},
                   add_local_signature<MeshMaterial>("mesh"),
                   {MeshMaterial{{}, {{0.85f, 0.55f, 0.25f}, 0.8f, 0.7f, 60.0f, 0.2f, torus_id}}});
    pr::add_object<SurfaceHit>(
        *this, "mirror",
        {.geometry = pr::GeometryDesc::procedural(
             {pr::Aabb{}}, {pr::instance_transform(glm::scale(glm::translate(glm::mat4(1.0f), mirror_centre),
                                                              glm::vec3(mirror_radius)))}),
         .intersection = "sphere.rint", .closest_hit = {{radiance, "shade.rchit"}}},
        material, {{{0.95f, 0.95f, 0.95f}, 0.05f, 0.9f, 200.0f, 0.9f, mirror_id}});
    pr::GeometryDesc beads = pr::GeometryDesc::procedural({pr::Aabb{}}, {});
    beads.may_add_instances = true;  // none declared: every bead is added at run time
    m_beads = pr::add_object<SurfaceHit>(*this, "beads",
                                         {.geometry = beads, .intersection = "sphere.rint",
                                          .closest_hit = {{radiance, "bead.rchit"}}},
                                         material, {{{1.0f, 1.0f, 1.0f}, 0.85f, 0.5f, 40.0f, 0.0f, bead_id}});
  }

  pr::GeometryId beads() const noexcept { return m_beads; }
  const pr::ObjMesh& torus() const noexcept { return m_torus; }

  /// Shaders from this example's folder.
  pr::vk::RendererOptions renderer_options(std::filesystem::path cache = {}) const {
    return {.shader_dirs = {examples::examples_dir() / "05_textured_scene" / "shaders"}, .pipeline_cache = std::move(cache)};
  }

 private:
  pr::ObjMesh m_torus;
  pr::GeometryId m_beads;
};

/// The ground texture (tiles, from assets/ground.png: mipmapped, repeating) and the sky cube.
inline void set_textures(pr::vk::Renderer& renderer) {
  renderer.set_texture(ground_slot, pr::load_texture(assets_dir() / "ground.png"));
  renderer.set_texture(sky_slot, sky_cube(), {.wrap = pr::TextureWrap::clamp});
}

/// The beads over frames: frame f adds one at slot f % bead_slots (bead.rchit colours it by its
/// place on the ring), and past four the oldest goes.
class Beads {
 public:
  void step(pr::vk::Renderer& renderer, pr::GeometryId beads, std::uint32_t frame) {
    const std::uint32_t slot = frame % bead_slots;
    const glm::mat4 at = glm::scale(glm::translate(glm::mat4(1.0f), bead_centre(slot)), glm::vec3(bead_radius));
    m_live.push_back({renderer.add_instance(beads, at), slot});
    if (m_live.size() > 4) {
      renderer.remove_instance(beads, m_live.front().instance);
      m_live.pop_front();
    }
  }
  /// The slots that hold a bead now, oldest first.
  std::vector<std::uint32_t> slots() const {
    std::vector<std::uint32_t> out;
    for (const Live& l : m_live) out.push_back(l.slot);
    return out;
  }

 private:
  struct Live {
    std::uint32_t instance;
    std::uint32_t slot;
  };
  std::deque<Live> m_live;
};

}  // namespace textured
