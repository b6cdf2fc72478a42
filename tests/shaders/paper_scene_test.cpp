// Tests for examples/02_paper_scene: every shader compiles with glslang against the
// declarations the scene derives (glsl_for), and the shader-side types have the sizes the
// pipeline and the SBT rely on.
#include "02_paper_scene/paper_scene.hpp"

#include <proceduray/vk/shader_compiler.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

namespace vk = proceduray::vk;

namespace {

std::filesystem::path paper_shader_dir() {
  return std::filesystem::path(__FILE__).parent_path().parent_path().parent_path() / "examples" / "02_paper_scene" /
         "shaders";
}

vk::ShaderStage stage_of(const std::filesystem::path& file) {
  const std::string ext = file.extension().string();
  if (ext == ".rgen") return vk::ShaderStage::raygen;
  if (ext == ".rmiss") return vk::ShaderStage::miss;
  if (ext == ".rchit") return vk::ShaderStage::closest_hit;
  return vk::ShaderStage::intersection;
}

/// The scene; no device is needed to derive declarations.
const paper::PaperScene& paper_scene() {
  static const paper::PaperScene scene;
  return scene;
}

/// The scene compiled, once.
const proceduray::Plan& paper_plan() {
  static const proceduray::Plan plan = proceduray::compile(paper_scene());
  return plan;
}

std::string declarations(std::string_view file) {
  return proceduray::glsl_for(paper_plan(), stage_of(std::filesystem::path(file)), file);
}

/// A stage's SPIR-V: its file, or the source the library generated (a distance field's
/// intersection), compiled as if it sat in the example's shader folder.
std::vector<std::uint32_t> compile_paper_shader(const proceduray::PlannedStage& stage) {
  const std::filesystem::path path = paper_shader_dir() / stage.shader;
  return vk::compile_glsl({.stage = stage_of(path), .name = path.string(),
                           .code = stage.source.empty() ? vk::read_text_file(path) : stage.source,
                           .preamble = declarations(stage.shader)});
}

}  // namespace

TEST_CASE("every paper scene shader compiles with its generated declarations") {
  REQUIRE(paper_plan().pipeline().stages.size() == 8);  // raygen, 2 miss, 2 closest hit, 3 intersection
  for (const proceduray::PlannedStage& stage : paper_plan().pipeline().stages) {
    CAPTURE(stage.shader);
    std::vector<std::uint32_t> spirv;
    CHECK_NOTHROW(spirv = compile_paper_shader(stage));
    REQUIRE(spirv.size() > 5);
    CHECK(spirv[0] == 0x07230203u);  // SPIR-V magic
  }
}

TEST_CASE("every paper shader file is a stage of the pipeline") {
  const auto& stages = paper_plan().pipeline().stages;
  std::size_t on_disk = 0;
  for (const auto& entry : std::filesystem::directory_iterator(paper_shader_dir())) {
    if (entry.path().extension() == ".glsl") continue;  // included by the stages
    ++on_disk;
    const std::string name = entry.path().filename().string();
    CAPTURE(name);
    CHECK(std::any_of(stages.begin(), stages.end(), [&](const auto& s) { return s.shader == name; }));
  }
  // The fractals' intersections are generated (distance fields), no files.
  const auto generated = std::count_if(stages.begin(), stages.end(), [](const auto& s) { return !s.source.empty(); });
  CHECK(generated == 2);
  CHECK(on_disk + static_cast<std::size_t>(generated) == stages.size());
}


TEST_CASE("paper types fit the pipeline limits") {
  static_assert(sizeof(proceduray::FieldHit) <= proceduray::max_hit_attribute_size);
  const proceduray::PipelinePlan& plan = paper_plan().pipeline();
  CHECK(plan.max_attribute_size == 20);  // FieldHit: normal, steps, threshold
  CHECK(plan.max_payload_size == sizeof(paper::RadiancePayload));
  static_assert(sizeof(paper::RadiancePayload) == 88);  // colour, depth, object id, steps, weight; the iterative fields
  static_assert(sizeof(paper::ShadowPayload) == 4);
  CHECK(plan.max_root_arguments_size[2] == 48);  // a MaterialRecord per hit record
  static_assert(sizeof(proceduray::MarchKnobs) == 15 * 4);
  static_assert(sizeof(proceduray::CutPlanes) == 2 * 16 + 16);
  // camera, light and sky, depth, flags, weight, the Julia set's cut planes, the mouth (no knobs:
  // the library owns the fields')
  static_assert(sizeof(paper::SceneConstants) == 80 + 4 * 11 + 4 * 3 + sizeof(proceduray::CutPlanes) + 4);
  // Payload locations are ray indices: radiance 0, shadow 1 (the shaders' radiance_ray, shadow_ray).
  CHECK(paper_scene().ray_id<paper::RadiancePayload>("radiance").index() == 0);
  CHECK(paper_scene().ray_id<paper::ShadowPayload>("shadow").index() == 1);
  CHECK(plan.max_recursion_depth == paper::max_depth_limit + 1);  // the deepest radiance hit traces a shadow ray
}

TEST_CASE("generated declarations carry the uniform block and no hand copies") {
  const std::string decl = declarations("shade.rchit");
  CHECK(decl.find("layout(set = 0, binding = 2, scalar) uniform SceneConstantsUniform {") != std::string::npos);
  CHECK(decl.find("layout(shaderRecordEXT, scalar) buffer MaterialRecordRootArguments {") != std::string::npos);
  CHECK(decl.find("hitAttributeEXT FieldHit hit;") != std::string::npos);
  CHECK(decl.find("layout(location = 2) rayPayloadInEXT RadiancePayload payload;") != std::string::npos);  // past the outgoing
  CHECK(decl.find("layout(location = 0) rayPayloadEXT RadiancePayload radiance;") != std::string::npos);  // reflections
  CHECK(decl.find("layout(location = 1) rayPayloadEXT ShadowPayload shadow;") != std::string::npos);
  CHECK(decl.find("const vec3 julia_aabb_min = vec3(-1.5, -1.5, -1.5);") != std::string::npos);
  CHECK(decl.find("layout(set = 0, binding = 0) uniform accelerationStructureEXT tlas;") != std::string::npos);
  CHECK(declarations("raygen.rgen").find("layout(location = 0) rayPayloadEXT RadiancePayload radiance;") !=
        std::string::npos);
  CHECK(declarations("shadow.rmiss").find("layout(location = 2) rayPayloadInEXT ShadowPayload payload;") !=
        std::string::npos);
  CHECK(declarations("julia.field.rint").find("rayPayload") == std::string::npos);  // intersection shaders have none
  // The shaders declare no struct of their own: every struct comes from the C++ types.
  for (const auto& entry : std::filesystem::directory_iterator(paper_shader_dir())) {
    CAPTURE(entry.path().string());
    CHECK(vk::read_text_file(entry.path()).find("struct ") == std::string::npos);
  }
}

TEST_CASE("default constants frame the scene") {
  const paper::SceneConstants c = paper::default_constants(1024, 768, 0.0f);
  CHECK(c.max_depth == 3);
  CHECK(c.max_depth <= paper::max_depth_limit);
  CHECK(c.flags == (paper::flag_shadows | paper::flag_reflections));
  CHECK(c.camera.pixel_angle > 0.0f);
  const glm::vec3 centres[] = {paper::pacman_placements[0].translation, paper::pacman_placements[1].translation,
                               paper::julia_placement.translation, paper::mandelbulb_placement.translation};
  for (const glm::vec3& centre : centres) {
    const glm::ivec2 px = proceduray::project(c.camera, centre, 1024, 768);
    CAPTURE(px.x);
    CAPTURE(px.y);
    CHECK(px.x > 0);
    CHECK(px.x < 1024);
    CHECK(px.y > 0);
    CHECK(px.y < 768);
  }
}
