// A user's program built against the installed library: one procedural sphere, checked by pixels.
//   consumer OUT.png   -> exit 0 when the sphere is hit at the centre and the corner is background
#include <proceduray/proceduray.hpp>

#include <cstdint>
#include <cstdio>
#include <exception>
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
    vk::Context ctx({.validation = true});
    const VkAabbPositionsKHR box{-1, -1, -1, 1, 1, 1};
    const vk::AabbGeometry geometry{{&box, 1}};
    const auto blas = vk::build_blas(ctx, {&geometry, 1});
    const vk::Instance instance{.blas = &blas};
    const auto tlas = vk::build_tlas(ctx, {&instance, 1});
    vk::StorageImage image(ctx, 64, 64);
    vk::DescriptorSet set(ctx, {{0, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR}, {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}});
    set.write(0, tlas);
    set.write(1, image.view());

    using consumer::Colour;
    using consumer::HitRecord;
    using consumer::Interface;
    const std::string declarations = pr::glsl_declarations<Interface>();
    const std::string rgen =
        "#version 460\n"
        "layout(binding = 0) uniform accelerationStructureEXT tlas;\n"
        "layout(binding = 1, rgba8) uniform writeonly image2D image;\n"
        "void main() {\n"
        "  vec2 p = (vec2(gl_LaunchIDEXT.xy) + 0.5) / vec2(gl_LaunchSizeEXT.xy) * 4.0 - 2.0;\n"
        "  traceRayEXT(tlas, gl_RayFlagsOpaqueEXT, 0xFF, 0, 1, 0, vec3(p, 5.0), 0.0, vec3(0, 0, -1), 100.0, 0);\n"
        "  imageStore(image, ivec2(gl_LaunchIDEXT.xy), vec4(payload.rgb, 1));\n"
        "}\n";
    const std::string miss = "#version 460\nvoid main() { payload.rgb = vec3(0); }\n";
    const std::string hit = "#version 460\nvoid main() { payload.rgb = arguments.colour.rgb; }\n";
    const std::string isect = "#version 460\n#include \"primitives/sphere.glsl\"\n"
        "void main() { float a, b; if (ray_sphere(gl_ObjectRayOriginEXT, gl_ObjectRayDirectionEXT, vec3(0), 1.0, a, b))"
        " reportIntersectionEXT(a, 0u); }\n";
    vk::PipelineDesc desc;
    auto add = [&](vk::ShaderStage s, const std::string& code, const std::string& stage_declarations) {
      return desc.add_shader(s, vk::compile_glsl({.stage = s, .name = "consumer", .code = code,
                                                  .preamble = declarations + stage_declarations}));
    };
    const auto r = add(vk::ShaderStage::raygen, rgen, pr::glsl_ray_payload<Interface, Colour>("payload"));
    const auto m = add(vk::ShaderStage::miss, miss, pr::glsl_ray_payload_in<Interface, Colour>("payload"));
    const auto h = add(vk::ShaderStage::closest_hit, hit,
                       pr::glsl_ray_payload_in<Interface, Colour>("payload") +
                           pr::glsl_root_arguments<Interface, HitRecord>("arguments"));
    const auto i = add(vk::ShaderStage::intersection, isect, "");
    desc.groups = {vk::ShaderGroup::general_shader(r), vk::ShaderGroup::general_shader(m),
                   vk::ShaderGroup::procedural(h, i)};
    desc.set_layouts = {set.layout()};
    const vk::Pipeline pipeline(ctx, desc);

    const HitRecord green{glm::vec4(0.0f, 1.0f, 0.0f, 1.0f)};
    const auto layout = pr::layout_sbt(ctx.sbt_properties(),
                                       {{{1, 0}, {1, 0}, {1, std::uint32_t{sizeof(HitRecord)}}, {}}});
    const vk::RecordWrite records[] = {{pr::SbtRegionKind::raygen, 0, 0},
                                       {pr::SbtRegionKind::miss, 0, 1},
                                       {pr::SbtRegionKind::hit, 0, 2, Interface::root_arguments(green)}};
    const vk::SbtBuffer sbt(ctx, pipeline, layout, records);
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
