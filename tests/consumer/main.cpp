// A user's program built against the installed library: one procedural sphere, checked by pixels.
//   consumer OUT.png   -> exit 0 when the sphere is hit at the centre and the corner is background
#include <proceduray/proceduray.hpp>

#include <cstdint>
#include <cstdio>
#include <exception>
#include <map>
#include <string>

namespace pr = proceduray;
namespace vk = proceduray::vk;

namespace consumer {
// What crosses to the shaders, declared once in C++; the GLSL side is generated from it.
/// The ray's payload: the colour it brings back.
struct Colour {
  glm::vec3 rgb;
};
PROCEDURAY_STRUCT(Colour, scalar, rgb);
/// Hit root arguments: the sphere's colour.
struct HitRecord {
  glm::vec4 colour;
};
PROCEDURAY_STRUCT(HitRecord, scalar, colour);
using Interface = pr::ShaderInterface<pr::Payload<Colour>, pr::RootComponent<>, pr::RootArguments<HitRecord>,
                                      pr::Attributes<>>;
}  // namespace consumer

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: consumer OUT.png\n");
    return 2;
  }
  try {
    using consumer::Colour;
    using consumer::HitRecord;
    // The scene, declared from its interface: compile() derives the groups, records and each
    // stage's declarations (payload, root arguments, tlas, image).
    pr::Scene<consumer::Interface> scene;
    const auto ray = scene.add_ray<Colour>("primary", {.miss = "consumer.rmiss", .flags = pr::RayFlags::opaque});
    const auto group = scene.add_hit_group("sphere", {.kind = pr::HitGroupKind::procedural,
                                                      .closest_hit = "consumer.rchit", .intersection = "consumer.rint"});
    const auto sphere = scene.add_geometry("sphere", pr::GeometryDesc::procedural({pr::Aabb{}}));
    const auto record = scene.add_local_signature<HitRecord>("record");
    scene.set_global_signature(pr::default_global_signature());
    scene.add_raygen("consumer.rgen");
    scene.add_hit(ray, group, record, HitRecord{glm::vec4(0.0f, 1.0f, 0.0f, 1.0f)}, sphere);
    const pr::Plan plan = pr::compile(scene);

    // The thin layer by hand: one BLAS, the plan's instance, a descriptor set, the pipeline, the SBT.
    vk::Context ctx({.validation = true});
    const VkAabbPositionsKHR box{-1, -1, -1, 1, 1, 1};
    const vk::AabbGeometry geometry{{&box, 1}};
    const auto blas = vk::build_blas(ctx, {&geometry, 1});
    const vk::Instance instance{.blas = &blas, .sbt_offset = plan.instances()[0].sbt_offset};
    const auto tlas = vk::build_tlas(ctx, {&instance, 1});
    vk::StorageImage image(ctx, 64, 64);
    vk::DescriptorSet set(ctx, {{pr::default_tlas_binding, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR},
                                {pr::default_image_binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}});
    set.write(pr::default_tlas_binding, tlas);
    set.write(pr::default_image_binding, image.view());

    const std::map<std::string, std::string> code{
        {"consumer.rgen",
         "#version 460\n"
         "void main() {\n"
         "  vec2 p = (vec2(gl_LaunchIDEXT.xy) + 0.5) / vec2(gl_LaunchSizeEXT.xy) * 4.0 - 2.0;\n"
         "  trace_primary(vec3(p, 5.0), 0.0, vec3(0, 0, -1), 100.0);\n"
         "  imageStore(image, ivec2(gl_LaunchIDEXT.xy), vec4(primary.rgb, 1));\n"
         "}\n"},
        {"consumer.rmiss", "#version 460\nvoid main() { payload.rgb = vec3(0); }\n"},
        {"consumer.rchit", "#version 460\nvoid main() { payload.rgb = arguments.colour.rgb; }\n"},
        {"consumer.rint",
         "#version 460\n#include \"primitives/sphere.glsl\"\n"
         "void main() { float a, b; if (ray_sphere(gl_ObjectRayOriginEXT, gl_ObjectRayDirectionEXT, vec3(0), 1.0, a, b))"
         " reportIntersectionEXT(a, 0u); }\n"}};
    vk::PipelineDesc desc;
    for (const pr::PlannedStage& s : plan.pipeline().stages) {
      desc.add_shader(s.stage, vk::compile_glsl({.stage = s.stage, .name = s.shader, .code = code.at(s.shader),
                                                 .preamble = s.declarations}));
    }
    desc.groups = vk::shader_groups(plan.pipeline());
    desc.set_layouts = {set.layout()};
    const vk::Pipeline pipeline(ctx, desc);
    const vk::SbtBuffer sbt(ctx, pipeline, plan, plan.layout(ctx.limits()));
    vk::trace(ctx, pipeline, set, sbt, 64, 64);
    const auto rgba = image.read();
    pr::write_png(argv[1], 64, 64, rgba);

    const std::size_t centre = (32 * 64 + 32) * 4;
    const bool hit_centre = rgba[centre + 1] == 255 && rgba[centre] == 0;
    const bool miss_corner = rgba[1] == 0;
    const bool clean = ctx.validation_messages().empty();
    std::printf("consumer: %s, centre %s, corner %s, validation %s\n", ctx.name().c_str(),
                hit_centre ? "hit" : "MISSED", miss_corner ? "background" : "NOT BACKGROUND",
                clean ? "clean" : "REPORTED MESSAGES");
    return hit_centre && miss_corner && clean ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 1;
  }
}
