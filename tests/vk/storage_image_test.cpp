#include "test_context.hpp"

#include <proceduray/vk/storage_image.hpp>
#include <proceduray/vk/trace.hpp>

#include <cstdint>
#include <vector>

using namespace proceduray;

TEST_CASE("storage image reads back the pixels a shader wrote, row by row from the top") {
  // A raygen-only pipeline writes (x, y, 7, 255) at each pixel; read() must return exactly those
  // bytes at (y * width + x) * 4: the right size, rows top to bottom, RGBA order, nothing left over.
  TestContext t;
  constexpr std::uint32_t width = 7, height = 3;
  vk::StorageImage image(t.ctx, width, height);
  vk::DescriptorSet set(t.ctx, {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}});
  set.write(0, image.view());
  vk::PipelineDesc desc;
  const auto raygen = desc.add_shader(
      vk::ShaderStage::raygen,
      vk::compile_glsl({.stage = vk::ShaderStage::raygen, .name = "storage_image_test.rgen",
                        .code = "#version 460\n#extension GL_EXT_ray_tracing : require\n"
                                "layout(binding = 0, rgba8) uniform writeonly image2D image;\n"
                                "void main() {\n"
                                "  uvec2 p = gl_LaunchIDEXT.xy;\n"
                                "  imageStore(image, ivec2(p), vec4(float(p.x), float(p.y), 7.0, 255.0) / 255.0);\n"
                                "}\n"}));
  desc.groups = {vk::ShaderGroup::general_shader(raygen)};
  desc.set_layouts = {set.layout()};
  const vk::Pipeline pipeline(t.ctx, desc);
  const auto layout = layout_sbt(t.ctx.sbt_properties(), {{{1, 0}, {}, {}, {}}});
  const vk::RecordWrite records[] = {{SbtRegionKind::raygen, 0, 0}};
  const vk::SbtBuffer sbt(t.ctx, pipeline, layout, records);
  vk::trace(t.ctx, pipeline, set, sbt, width, height);

  const std::vector<std::uint8_t> rgba = image.read();
  REQUIRE(rgba.size() == width * height * 4);
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      const std::size_t at = (std::size_t{y} * width + x) * 4;
      INFO("pixel (" << x << ", " << y << ")");
      CHECK(rgba[at + 0] == x);
      CHECK(rgba[at + 1] == y);
      CHECK(rgba[at + 2] == 7);
      CHECK(rgba[at + 3] == 255);
    }
  }
}

TEST_CASE("storage image rejects sizes outside the device's limit") {
  TestContext t;
  CHECK_THROWS_WITH_AS(vk::StorageImage(t.ctx, 0, 4), doctest::Contains("size 0x4"), UsageError);
  const auto limit = t.ctx.properties().limits.maxImageDimension2D;
  CHECK_THROWS_WITH_AS(vk::StorageImage(t.ctx, limit + 1, 4), doctest::Contains(std::to_string(limit).c_str()),
                       DeviceLimitError);
}
