// A user's program built against the installed library: one procedural sphere, checked by pixels.
//   consumer OUT.png   -> exit 0 when the sphere is hit at the centre and the corner is background
#include <proceduray/proceduray.hpp>

#include <cstdio>
#include <exception>

namespace vk = proceduray::vk;

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

    const char* head = "#version 460\n#extension GL_EXT_ray_tracing : require\n";
    const std::string rgen = std::string(head) +
        "layout(binding = 0) uniform accelerationStructureEXT tlas;\n"
        "layout(binding = 1, rgba8) uniform writeonly image2D image;\n"
        "layout(location = 0) rayPayloadEXT vec3 c;\n"
        "void main() {\n"
        "  vec2 p = (vec2(gl_LaunchIDEXT.xy) + 0.5) / vec2(gl_LaunchSizeEXT.xy) * 4.0 - 2.0;\n"
        "  traceRayEXT(tlas, gl_RayFlagsOpaqueEXT, 0xFF, 0, 1, 0, vec3(p, 5.0), 0.0, vec3(0, 0, -1), 100.0, 0);\n"
        "  imageStore(image, ivec2(gl_LaunchIDEXT.xy), vec4(c, 1));\n"
        "}\n";
    const std::string miss = std::string(head) + "layout(location = 0) rayPayloadInEXT vec3 c;\nvoid main() { c = vec3(0); }\n";
    const std::string hit = std::string(head) + "layout(location = 0) rayPayloadInEXT vec3 c;\n"
        "layout(shaderRecordEXT) buffer R { vec4 colour; };\nvoid main() { c = colour.rgb; }\n";
    const std::string isect = std::string(head) + "#include \"primitives/sphere.glsl\"\n"
        "void main() { float a, b; if (ray_sphere(gl_ObjectRayOriginEXT, gl_ObjectRayDirectionEXT, vec3(0), 1.0, a, b))"
        " reportIntersectionEXT(a, 0u); }\n";
    vk::PipelineDesc desc;
    auto add = [&](vk::ShaderStage s, const std::string& code) {
      return desc.add_shader(s, vk::compile_glsl({.stage = s, .name = "consumer", .code = code}));
    };
    const auto r = add(vk::ShaderStage::raygen, rgen);
    const auto m = add(vk::ShaderStage::miss, miss);
    const auto h = add(vk::ShaderStage::closest_hit, hit);
    const auto i = add(vk::ShaderStage::intersection, isect);
    desc.groups = {vk::ShaderGroup::general_shader(r), vk::ShaderGroup::general_shader(m),
                   vk::ShaderGroup::procedural(h, i)};
    desc.set_layouts = {set.layout()};
    const vk::Pipeline pipeline(ctx, desc);

    const float colour[4] = {0.0f, 1.0f, 0.0f, 1.0f};
    const auto layout = proceduray::layout_sbt(ctx.sbt_properties(), {{{1, 0}, {1, 0}, {1, sizeof colour}, {}}});
    const vk::RecordWrite records[] = {{proceduray::SbtRegionKind::raygen, 0, 0},
                                     {proceduray::SbtRegionKind::miss, 0, 1},
                                     {proceduray::SbtRegionKind::hit, 0, 2, vk::bytes_of(colour)}};
    const vk::SbtBuffer sbt(ctx, pipeline, layout, records);
    vk::trace(ctx, pipeline, set, sbt, 64, 64);
    const auto rgba = image.read();
    proceduray::write_png(argv[1], 64, 64, rgba);

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
