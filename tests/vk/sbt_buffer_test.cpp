#include "test_context.hpp"

#include <proceduray/shader/categories.hpp>
#include <proceduray/shader/field_list.hpp>
#include <proceduray/shader/glsl_codegen.hpp>
#include <proceduray/vk/sbt_buffer.hpp>

#include <cstring>
#include <string>

using namespace proceduray;

namespace {

/// Hit root arguments: one colour; its shaderRecordEXT block is generated from this struct.
struct ColourRecord {
  glm::vec4 colour;
};
PROCEDURAY_STRUCT(ColourRecord, std430, colour);
using Interface = ShaderInterface<Payload<>, RootComponent<>, RootArguments<ColourRecord>, Attributes<>>;

constexpr const char* raygen = "#version 460\n#extension GL_EXT_ray_tracing : require\nvoid main() {}\n";
constexpr const char* miss =
    "#version 460\n#extension GL_EXT_ray_tracing : require\nlayout(location = 0) rayPayloadInEXT vec4 p;\n"
    "void main() { p = vec4(0); }\n";
constexpr const char* hit =
    "#version 460\n#extension GL_EXT_ray_tracing : require\nlayout(location = 0) rayPayloadInEXT vec4 p;\n"
    "void main() { p = arguments.colour; }\n";
constexpr const char* isect =
    "#version 460\n#extension GL_EXT_ray_tracing : require\nvoid main() { reportIntersectionEXT(1.0, 0u); }\n";

/// raygen (group 0), miss (group 1), procedural hit (group 2).
vk::Pipeline small_pipeline(const vk::Context& ctx) {
  vk::PipelineDesc desc;
  auto add = [&](vk::ShaderStage s, const char* code) {
    std::string declarations;
    if (s == vk::ShaderStage::closest_hit) {
      declarations = glsl_declarations(Interface::types) + glsl_root_arguments(type_ops<ColourRecord>, "arguments");
    }
    return desc.add_shader(s, vk::compile_glsl({.stage = s, .name = "sbt_test", .code = code,
                                                .preamble = std::move(declarations)}));
  };
  const auto r = add(vk::ShaderStage::raygen, raygen);
  const auto m = add(vk::ShaderStage::miss, miss);
  const auto h = add(vk::ShaderStage::closest_hit, hit);
  const auto i = add(vk::ShaderStage::intersection, isect);
  desc.groups = {vk::ShaderGroup::general_shader(r), vk::ShaderGroup::general_shader(m),
                 vk::ShaderGroup::procedural(h, i)};
  return vk::Pipeline(ctx, desc);
}

}  // namespace

TEST_CASE("shader binding table writes handles and data where the layout says") {
  TestContext t;
  const auto pipeline = small_pipeline(t.ctx);
  const auto layout = layout_sbt(t.ctx.sbt_properties(), {{{1, 0}, {2, 0}, {3, std::uint32_t{sizeof(ColourRecord)}}, {}}});
  const ColourRecord colours[3] = {{{1, 0, 0, 1}}, {{0, 1, 0, 1}}, {{0, 0, 1, 1}}};
  std::vector<vk::RecordWrite> records{{SbtRegionKind::raygen, 0, 0}, {SbtRegionKind::miss, 0, 1},
                                     {SbtRegionKind::miss, 1, 1}};
  for (std::uint32_t i = 0; i < 3; ++i) records.push_back({SbtRegionKind::hit, i, 2, Interface::root_arguments(colours[i])});
  const vk::SbtBuffer sbt(t.ctx, pipeline, layout, records);

  const auto bytes = sbt.bytes();
  for (const auto& r : records) {
    const auto handle = pipeline.group_handle(r.group);
    CHECK(std::memcmp(bytes.data() + layout.record_offset(r.region, r.index), handle.data(), handle.size()) == 0);
    if (!r.data.empty()) {
      CHECK(std::memcmp(bytes.data() + layout.arguments_offset(r.region, r.index), r.data.data(), r.data.size()) == 0);
    }
  }
  const auto base = t.ctx.sbt_properties().base_alignment;
  const auto& regions = sbt.regions();
  for (int k = 0; k < 3; ++k) CHECK(regions[k].deviceAddress % base == 0);
  CHECK(regions[0].size == regions[0].stride);  // Vulkan: raygen size equals its stride
  CHECK(regions[2].size == 3 * regions[2].stride);
  CHECK(regions[3].deviceAddress == 0);  // no callable records
}

TEST_CASE("shader binding table rejects oversized data and missing or repeated records") {
  TestContext t;
  const auto pipeline = small_pipeline(t.ctx);
  const auto props = t.ctx.sbt_properties();
  const auto layout = layout_sbt(props, {{{1, 0}, {1, 0}, {1, 0}, {}}});
  // Room for data is whatever alignment left after the handle; ask for more than the stride holds.
  std::vector<std::byte> big(layout.region(SbtRegionKind::hit).stride, std::byte{1});
  const vk::RecordWrite base[] = {{SbtRegionKind::raygen, 0, 0}, {SbtRegionKind::miss, 0, 1}};
  std::vector<vk::RecordWrite> records(std::begin(base), std::end(base));
  records.push_back({SbtRegionKind::hit, 0, 2, big});
  CHECK_THROWS_WITH_AS(vk::SbtBuffer(t.ctx, pipeline, layout, records),
                       doctest::Contains("hit record 0 has"), UsageError);

  records.back() = {SbtRegionKind::hit, 0, 2};
  records.push_back({SbtRegionKind::hit, 0, 2});
  CHECK_THROWS_WITH_AS(vk::SbtBuffer(t.ctx, pipeline, layout, records), doctest::Contains("given twice"),
                       UsageError);
  records.pop_back();
  records.pop_back();
  CHECK_THROWS_WITH_AS(vk::SbtBuffer(t.ctx, pipeline, layout, records),
                       doctest::Contains("hit record 0 was laid out but never given"), UsageError);
  records.push_back({SbtRegionKind::hit, 0, 7});
  CHECK_THROWS_WITH_AS(vk::SbtBuffer(t.ctx, pipeline, layout, records), doctest::Contains("group 7"),
                       UsageError);
}

TEST_CASE("pipeline rejects a procedural hit group without an intersection shader") {
  TestContext t;
  vk::PipelineDesc desc;
  const auto r = desc.add_shader(vk::ShaderStage::raygen, vk::compile_glsl({.stage = vk::ShaderStage::raygen,
                                                                             .name = "r", .code = raygen}));
  desc.groups = {vk::ShaderGroup::general_shader(r), vk::ShaderGroup::procedural(VK_SHADER_UNUSED_KHR,
                                                                                  VK_SHADER_UNUSED_KHR)};
  CHECK_THROWS_WITH_AS(vk::Pipeline(t.ctx, desc), doctest::Contains("no intersection shader"), UsageError);
  desc.groups = {vk::ShaderGroup::general_shader(5)};
  CHECK_THROWS_WITH_AS(vk::Pipeline(t.ctx, desc), doctest::Contains("shader 5"), UsageError);
  desc.groups = {vk::ShaderGroup::general_shader(r)};
  desc.max_recursion_depth = t.ctx.ray_tracing_properties().maxRayRecursionDepth + 1;
  CHECK_THROWS_WITH_AS(vk::Pipeline(t.ctx, desc), doctest::Contains("maxRayRecursionDepth"), DeviceLimitError);
}
