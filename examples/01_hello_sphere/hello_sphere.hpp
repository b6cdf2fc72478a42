// Two procedural spheres: one AABB BLAS, two instances of it, a colour per instance
// carried in its hit record, a background colour in the miss record.
//
//   proceduray::vk::Context ctx;
//   hello_sphere::HelloSphere scene(ctx);
//   std::vector<std::uint8_t> rgba = scene.render(640, 360);
//
// SBT, as compile() lays it out (one ray type, so record = instance offset + geometry index * 1 + 0):
//   raygen | miss: background | hit 0: red sphere | hit 1: blue sphere
//   instance 0 -> sbtOffset 0 -> hit 0;  instance 1 -> sbtOffset 1 -> hit 1
// The GPU objects are the thin layer's, built by hand (BLAS, TLAS, descriptor set, pipeline);
// the groups, records and SBT offsets come from the scene's plan, never numbered by hand.
#pragma once

#include <proceduray/proceduray.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <string>

#include <array>
#include <map>
#include <cmath>
#include <cstdint>
#include <vector>

namespace hello_sphere {

namespace pr = proceduray;
namespace vk = proceduray::vk;

// The data that crosses to the shaders, declared once here; the GLSL side is generated.
/// The radiance ray's payload.
struct Colour {
  glm::vec3 rgb;
};
PROCEDURAY_STRUCT(Colour, scalar, rgb);
/// What the intersection shader hands the closest-hit shader.
struct SphereHit {
  glm::vec3 object_normal;
};
PROCEDURAY_STRUCT(SphereHit, scalar, object_normal);
/// Hit root arguments: the instance's colour.
struct HitRecord {
  glm::vec4 albedo;
};
PROCEDURAY_STRUCT(HitRecord, scalar, albedo);
/// Miss root arguments: the background colour.
struct MissRecord {
  glm::vec4 background;
};
PROCEDURAY_STRUCT(MissRecord, scalar, background);

using Interface = pr::ShaderInterface<pr::Payload<Colour>, pr::RootComponent<pr::Camera>,
                                      pr::RootArguments<HitRecord, MissRecord>, pr::Attributes<SphereHit>>;

/// The camera, pushed as push constants (declared in every stage as `camera`).
inline constexpr pr::PushConstantSlot<pr::Camera> camera_slot{.name = "camera"};

// The shaders' text. Each stage compiles with the declarations compile() derived for it
// (PlannedStage::declarations: the interface's structs, `tlas`, `image`, `camera`, the payload,
// hit attributes and root arguments it uses), so none is written here.
inline const char* const raygen_glsl = R"(#version 460
void main() {
  vec2 uv = (vec2(gl_LaunchIDEXT.xy) + 0.5) / vec2(gl_LaunchSizeEXT.xy) * 2.0 - 1.0;
  vec3 direction = normalize(camera.forward.xyz + uv.x * camera.right.xyz - uv.y * camera.up.xyz);
  trace_radiance(camera.eye.xyz, 0.0, direction, 1e30);   // flags, offsets and location from the scene
  imageStore(image, ivec2(gl_LaunchIDEXT.xy), vec4(radiance.rgb, 1.0));
}
)";

inline const char* const miss_glsl = R"(#version 460
void main() { payload.rgb = arguments.background.rgb; }
)";

inline const char* const intersection_glsl = R"(#version 460
#include "primitives/sphere.glsl"
void main() {
  vec3 o = gl_ObjectRayOriginEXT;
  vec3 d = gl_ObjectRayDirectionEXT;
  float t0, t1;
  if (!ray_sphere(o, d, vec3(0.0), 1.0, t0, t1)) return;
  float t = t0 >= gl_RayTminEXT ? t0 : t1;
  if (t < gl_RayTminEXT || t > gl_RayTmaxEXT) return;
  hit.object_normal = o + t * d;
  reportIntersectionEXT(t, 0u);
}
)";

inline const char* const closest_hit_glsl = R"(#version 460
void main() {
  // Normals take the inverse transpose of the object-to-world transform.
  vec3 n = normalize(transpose(mat3(gl_WorldToObjectEXT)) * hit.object_normal);
  vec3 light = normalize(vec3(0.4, 0.8, 0.6));
  payload.rgb = arguments.albedo.rgb * (0.3 + 0.7 * max(dot(n, light), 0.0));
}
)";

/// The scene's fixed numbers, shared by the renderer and the tests that check its pixels.
struct Layout {
  static constexpr std::array<glm::vec3, 2> centres{glm::vec3(-1.2f, 0.0f, 0.0f), glm::vec3(1.3f, 0.0f, 0.0f)};
  static constexpr std::array<float, 2> radii{1.0f, 0.8f};
  static constexpr std::array<glm::vec4, 2> albedo{glm::vec4(0.9f, 0.15f, 0.1f, 1.0f), glm::vec4(0.1f, 0.3f, 0.9f, 1.0f)};
  static constexpr glm::vec4 background{0.1f, 0.12f, 0.16f, 1.0f};
  static constexpr glm::vec3 eye{0.0f, 0.6f, 6.0f};
  static constexpr float fov_y_degrees = 40.0f;
};

/// The camera: at Layout::eye, looking at the origin (pushed as push constants).
inline pr::Camera make_camera(std::uint32_t width, std::uint32_t height) {
  return pr::look_at(Layout::eye, glm::vec3(0.0f), Layout::fov_y_degrees, width, height);
}

/// The scene: one ray type, the spheres' hit group, one geometry of two instances with a hit
/// record each, and the miss record; compile() derives the groups, records and SBT offsets.
inline pr::Scene<Interface> make_scene(std::array<glm::vec4, 2> albedo) {
  pr::Scene<Interface> scene;
  const auto radiance = scene.add_ray<Colour>("radiance", {.miss = "hello_sphere.rmiss", .flags = pr::RayFlags::opaque});
  const auto sphere = scene.add_hit_group<SphereHit>("sphere", {.kind = pr::HitGroupKind::procedural,
                                                               .closest_hit = "hello_sphere.rchit",
                                                               .intersection = "hello_sphere.rint"});
  std::vector<pr::InstanceTransform> placed;
  for (std::size_t i = 0; i < 2; ++i) {
    const glm::mat4 m = glm::scale(glm::translate(glm::mat4(1.0f), Layout::centres[i]), glm::vec3(Layout::radii[i]));
    placed.push_back(pr::instance_transform(m));
  }
  const auto spheres = scene.add_geometry("spheres", pr::GeometryDesc::procedural({pr::Aabb{}}, placed));
  const auto hit = scene.add_local_signature<HitRecord>("hit");
  scene.set_global_signature({.bindings = {{pr::BindingKind::acceleration_structure, 0, 0, 1, "tlas"},
                                           {pr::BindingKind::storage_image, 1, 0, 1, "image"}},
                              .push_constants = camera_slot});
  scene.add_raygen("hello_sphere.rgen");
  scene.add_miss(radiance, scene.add_local_signature<MissRecord>("miss"), MissRecord{Layout::background});
  for (std::uint32_t i = 0; i < 2; ++i) scene.add_hit(radiance, sphere, hit, HitRecord{albedo[i]}, spheres, i);
  return scene;
}

/// The GPU objects of the scene, built by hand with the thin layer from the scene's plan;
/// render() traces it at any size.
class HelloSphere {
 public:
  /// `albedo[i]` is instance i's colour, written into its hit record.
  explicit HelloSphere(const vk::Context& ctx, std::array<glm::vec4, 2> albedo = Layout::albedo)
      : m_ctx(&ctx),
        m_plan(pr::compile(make_scene(albedo))),
        m_blas(build_unit_sphere_blas(ctx)),
        m_tlas(vk::build_tlas(ctx, instances())),
        m_set(ctx, {{0, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR}, {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}}),
        m_pipeline(ctx, pipeline_desc(m_plan, m_set)),
        m_sbt(ctx, m_pipeline, m_plan, m_plan.layout(ctx.limits())) {
    m_set.write(0, m_tlas);
  }

  /// Traces one frame and returns its RGBA8 pixels.
  std::vector<std::uint8_t> render(std::uint32_t width, std::uint32_t height) {
    vk::check_trace_size(*m_ctx, width, height);
    vk::StorageImage image(*m_ctx, width, height);
    m_set.write(1, image.view());
    const pr::Camera camera = make_camera(width, height);
    vk::trace(*m_ctx, m_pipeline, m_set, m_sbt, width, height, vk::bytes_of(camera));
    return image.read();
  }

  const vk::SbtBuffer& sbt() const noexcept { return m_sbt; }
  const pr::Plan& plan() const noexcept { return m_plan; }

 private:
  static vk::AccelerationStructure build_unit_sphere_blas(const vk::Context& ctx) {
    const VkAabbPositionsKHR box{-1, -1, -1, 1, 1, 1};
    const vk::AabbGeometry geometry{{&box, 1}};
    return vk::build_blas(ctx, {&geometry, 1});
  }
  /// The plan's TLAS instances, each with the SBT offset compile() gave it.
  std::vector<vk::Instance> instances() const {
    std::vector<vk::Instance> out;
    const auto planned = m_plan.instances();
    for (std::uint32_t k = 0; k < planned.size(); ++k) {
      out.push_back({.blas = &m_blas, .transform = planned[k].transform, .custom_index = k,
                     .sbt_offset = planned[k].sbt_offset});
    }
    return out;
  }
  /// Compiles the plan's stages (in its order) and takes its groups.
  static vk::PipelineDesc pipeline_desc(const pr::Plan& plan, const vk::DescriptorSet& set) {
    const std::map<std::string, const char*> sources{{"hello_sphere.rgen", raygen_glsl},
                                                     {"hello_sphere.rmiss", miss_glsl},
                                                     {"hello_sphere.rchit", closest_hit_glsl},
                                                     {"hello_sphere.rint", intersection_glsl}};
    vk::PipelineDesc desc;
    for (const pr::PlannedStage& s : plan.pipeline().stages) {
      desc.add_shader(s.stage, vk::compile_glsl({.stage = s.stage, .name = s.shader, .code = sources.at(s.shader),
                                                 .preamble = s.declarations}));
    }
    desc.groups = vk::shader_groups(plan.pipeline());
    desc.set_layouts = {set.layout()};
    desc.push_constant_size = sizeof(pr::Camera);
    return desc;
  }

  const vk::Context* m_ctx;
  pr::Plan m_plan;
  vk::AccelerationStructure m_blas;
  vk::AccelerationStructure m_tlas;
  vk::DescriptorSet m_set;
  vk::Pipeline m_pipeline;
  vk::SbtBuffer m_sbt;
};

}  // namespace hello_sphere
