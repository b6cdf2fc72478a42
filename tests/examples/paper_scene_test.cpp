// examples/02_paper_scene: the report's figure 3, checked by object ids and pixel classes.
#include "vk/test_context.hpp"

#include <02_paper_scene/frame.hpp>

#include <algorithm>
#include <array>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace proceduray;

namespace {

constexpr std::uint32_t width = 128;
constexpr std::uint32_t height = 96;

/// A renderer of the paper scene at the test size.
struct Paper {
  paper::PaperScene scene;
  vk::Renderer renderer;
  explicit Paper(const vk::Context& ctx) : renderer(ctx, scene, scene.renderer_options()) {}

  vk::Frame render(float time, std::uint32_t flags) {
    paper::Frame c = paper::default_frame(width, height, time);
    c.flags = flags;
    paper::set_frame(renderer, c);
    return renderer.render(width, height);
  }
};

glm::ivec3 at(const vk::Frame& f, glm::ivec2 p) {
  if (p.x < 0 || p.y < 0 || p.x >= static_cast<int>(width) || p.y >= static_cast<int>(height)) {
    FAIL("pixel (" << p.x << ", " << p.y << ") is outside the image");
  }
  const std::size_t i = (std::size_t(p.y) * width + std::size_t(p.x)) * 4;
  return {f.rgba[i], f.rgba[i + 1], f.rgba[i + 2]};
}

glm::ivec2 pixel_of(glm::vec3 world) {
  return project(paper::default_frame(width, height, 0.0f).camera, world, width, height);
}

int luminance(glm::ivec3 c) { return c.r + c.g + c.b; }

}  // namespace

TEST_CASE("paper scene shows each object in its screen region") {
  TestContext t;
  Paper p(t.ctx);
  const vk::Frame ids = p.render(0.0f, paper::flag_object_ids);
  CHECK(at(ids, pixel_of(paper::pacman_placements[0].translation)).r == paper::pacman0_id);
  CHECK(at(ids, pixel_of(paper::pacman_placements[1].translation)).r == paper::pacman1_id);
  CHECK(at(ids, pixel_of(paper::julia_placement.translation)).r == paper::julia_id);
  CHECK(at(ids, pixel_of(paper::mandelbulb_placement.translation)).r == paper::mandelbulb_id);
  CHECK(at(ids, pixel_of({0.0f, 0.0f, 3.5f})).r == paper::plane_id);
  CHECK(at(ids, {width / 2, 0}).r == paper::sky_id);
  // Marched objects report their steps (g channel); the analytic Pac-man takes none.
  CHECK(at(ids, pixel_of(paper::mandelbulb_placement.translation)).g > 0);
  CHECK(at(ids, pixel_of(paper::pacman_placements[0].translation)).g == 0);
}

TEST_CASE("paper scene ground under an object is darker with shadows on") {
  TestContext t;
  Paper p(t.ctx);
  const vk::Frame ids = p.render(0.0f, paper::flag_object_ids);
  const vk::Frame lit = p.render(0.0f, 0);
  const vk::Frame shadowed = p.render(0.0f, paper::flag_shadows);
  std::size_t darker = 0, brighter = 0, objects_changed = 0;
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      const int before = luminance(at(lit, {x, y})), after = luminance(at(shadowed, {x, y}));
      if (at(ids, {x, y}).r == paper::plane_id) {
        darker += after < before - 30;
        brighter += after > before;
      } else {
        objects_changed += after != before;
      }
    }
  }
  CHECK(darker > 100);  // the four objects cast shadows on the ground
  CHECK(brighter == 0);  // a shadow ray only ever removes light
  CHECK(objects_changed > 0);  // self-shadowing on the objects' far sides
  // Open ground in front of the objects sees the light either way.
  const glm::ivec2 open = pixel_of({0.0f, 0.0f, 4.0f});
  CHECK(std::abs(luminance(at(shadowed, open)) - luminance(at(lit, open))) <= 3);
}

TEST_CASE("paper scene reflections change reflective surfaces only") {
  TestContext t;
  Paper p(t.ctx);
  const vk::Frame ids = p.render(0.0f, paper::flag_object_ids);
  const vk::Frame plain = p.render(0.0f, paper::flag_shadows);
  const vk::Frame mirrored = p.render(0.0f, paper::flag_shadows | paper::flag_reflections);
  std::size_t sky_changed = 0, plane_changed = 0;
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      const glm::ivec2 px(x, y);
      const bool changed = at(plain, px) != at(mirrored, px);
      if (at(ids, px).r == paper::sky_id) sky_changed += changed;
      if (at(ids, px).r == paper::plane_id) plane_changed += changed;
    }
  }
  CHECK(sky_changed == 0);        // the sky reflects nothing
  CHECK(plane_changed > 100);     // the ground mirrors the objects (reflectance 0.15)
}

TEST_CASE("paper scene renders are identical and animation moves only animated objects") {
  TestContext t;
  Paper p(t.ctx);
  const vk::Frame first = p.render(0.0f, paper::flag_object_ids);
  CHECK(p.render(0.0f, paper::flag_object_ids).rgba == first.rgba);
  const vk::Frame later = p.render(1.5f, paper::flag_object_ids);
  std::size_t changed = 0, changed_elsewhere = 0;
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      const glm::ivec3 a = at(first, {x, y}), b = at(later, {x, y});
      if (a == b) continue;
      ++changed;
      const auto animated = [](int id) { return id == paper::julia_id || id == paper::mandelbulb_id; };
      changed_elsewhere += !(animated(a.r) || animated(b.r));
    }
  }
  CHECK(changed > 20);
  CHECK(changed_elsewhere == 0);
}

namespace {

/// One expected hit record: its group, ray, geometry, instance (-1: the shared block) and material.
struct ExpectedHit {
  const char* group;
  std::uint32_t ray;
  const char* geometry;
  int instance;
  const paper::MaterialRecord* material;
};

/// Root arguments of a record as a MaterialRecord (48 bytes), or nothing.
std::optional<paper::MaterialRecord> material_of(const Plan& plan, const SbtRecord& r) {
  const auto bytes = plan.root_arguments(r);
  if (bytes.size() != sizeof(paper::MaterialRecord)) return std::nullopt;
  paper::MaterialRecord m;
  std::memcpy(&m, bytes.data(), sizeof m);
  return m;
}

bool same_bytes(const paper::MaterialRecord& a, const paper::MaterialRecord& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

}  // namespace

TEST_CASE("paper scene plan equals the recorded groups records and bytes") {
  const Plan plan = compile(paper::PaperScene{});  // no device
  const PipelinePlan& pipeline = plan.pipeline();
  // Groups: raygen, two misses, then the used hit groups in registration order (add_object makes
  // "<id>" for radiance and "<id>_shadow" for shadow).
  const std::vector<std::string> groups{"raygen.rgen", "radiance.rmiss", "shadow.rmiss", "plane", "plane_shadow",
                                        "pacman", "pacman_shadow", "julia", "julia_shadow", "mandelbulb",
                                        "mandelbulb_shadow"};
  REQUIRE(pipeline.groups.size() == groups.size());
  for (std::size_t g = 0; g < groups.size(); ++g) CHECK(pipeline.groups[g].name == groups[g]);
  const std::vector<std::pair<ShaderStage, std::string>> stages{
      {ShaderStage::raygen, "raygen.rgen"},        {ShaderStage::miss, "radiance.rmiss"},
      {ShaderStage::miss, "shadow.rmiss"},         {ShaderStage::closest_hit, "plane.rchit"},
      {ShaderStage::closest_hit, "shade.rchit"},   {ShaderStage::intersection, "pacman.rint"},
      {ShaderStage::intersection, "julia.field.rint"},   {ShaderStage::intersection, "mandelbulb.field.rint"}};
  REQUIRE(pipeline.stages.size() == stages.size());
  for (std::size_t s = 0; s < stages.size(); ++s) {
    CHECK(pipeline.stages[s].stage == stages[s].first);
    CHECK(pipeline.stages[s].shader == stages[s].second);
  }
  CHECK(pipeline.max_recursion_depth == paper::max_depth_limit + 1);
  CHECK(pipeline.recursion_depth_declared);
  CHECK(pipeline.max_payload_size == sizeof(paper::RadiancePayload));
  CHECK(pipeline.max_attribute_size == sizeof(FieldHit));
  CHECK(pipeline.max_root_arguments_size == std::array<std::uint32_t, 4>{0, 0, sizeof(paper::MaterialRecord), 0});

  // Hit records: the plane's shared block, one block per Pac-man (each has its own material),
  // then the Julia set's and the Mandelbulb's shared blocks; ray-minor inside each block.
  const std::vector<ExpectedHit> hits{
      {"plane", 0, "plane", -1, &paper::plane_material},
      {"plane_shadow", 1, "plane", -1, &paper::plane_material},
      {"pacman", 0, "pacman", 0, &paper::pacman_materials[0]},
      {"pacman_shadow", 1, "pacman", 0, &paper::pacman_materials[0]},
      {"pacman", 0, "pacman", 1, &paper::pacman_materials[1]},
      {"pacman_shadow", 1, "pacman", 1, &paper::pacman_materials[1]},
      {"julia", 0, "julia", -1, &paper::julia_material},
      {"julia_shadow", 1, "julia", -1, &paper::julia_material},
      {"mandelbulb", 0, "mandelbulb", -1, &paper::mandelbulb_material},
      {"mandelbulb_shadow", 1, "mandelbulb", -1, &paper::mandelbulb_material}};
  const auto records = plan.records(SbtRegionKind::hit);
  REQUIRE(records.size() == hits.size());
  for (std::size_t i = 0; i < hits.size(); ++i) {
    CAPTURE(i);
    const SbtRecord& r = records[i];
    CHECK(pipeline.groups[r.group].name == hits[i].group);
    CHECK(r.ray == hits[i].ray);
    CHECK(plan.geometries()[r.geometry].name == hits[i].geometry);
    CHECK(r.instance == (hits[i].instance < 0 ? no_index : std::uint32_t(hits[i].instance)));
    const auto m = material_of(plan, r);
    REQUIRE(m.has_value());
    CHECK(same_bytes(*m, *hits[i].material));
  }
  // Raygen and miss records carry no data; TLAS instances point at their blocks.
  CHECK(plan.records(SbtRegionKind::raygen).size() == 1);
  CHECK(plan.records(SbtRegionKind::miss).size() == 2);
  CHECK(plan.root_arguments(plan.records(SbtRegionKind::miss)[0]).empty());
  std::vector<std::uint32_t> offsets;
  for (const TlasInstance& i : plan.instances()) offsets.push_back(i.sbt_offset);
  CHECK(offsets == std::vector<std::uint32_t>{0, 2, 4, 6, 8});
  // A value: the same scene compiles to an equal plan, and a copy stays equal.
  const Plan again = compile(paper::PaperScene{});
  CHECK(again == plan);
}

TEST_CASE("paper scene declarations written at build time with no device equal the renderer's at run time") {
#ifndef PAPER_GLSL_DIR
#error "PAPER_GLSL_DIR must name the folder the build wrote the paper scene's declarations to"
#endif
  const std::filesystem::path dir = examples::generated_glsl_dir(PAPER_GLSL_DIR);  // PROCEDURAY_GLSL_DIR overrides
  TestContext t;
  paper::PaperScene scene;
  vk::Renderer renderer(t.ctx, scene, scene.renderer_options());
  std::ifstream list(dir / "files.txt");
  REQUIRE(list.good());
  std::vector<std::string> listed{std::istream_iterator<std::string>(list), std::istream_iterator<std::string>()};
  const auto& stages = renderer.plan().pipeline().stages;
  REQUIRE(listed.size() == stages.size());
  for (const PlannedStage& stage : stages) {
    CAPTURE(stage.shader);
    CHECK(std::count(listed.begin(), listed.end(), glsl_file_name(stage.stage, stage.shader)) == 1);
    std::ifstream in(dir / glsl_file_name(stage.stage, stage.shader), std::ios::binary);
    const std::string written{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    CHECK(!written.empty());
    CHECK(written == stage.declarations);
  }
  // The example renders with those declarations and sees its objects.
  Paper p(t.ctx);
  const vk::Frame ids = p.render(0.0f, paper::flag_object_ids);
  CHECK(at(ids, pixel_of(paper::pacman_placements[0].translation)).r == paper::pacman0_id);
}

namespace {
/// glsl_files_main's exit code and what it printed on stdout and stderr.
struct MainRun {
  int code;
  std::string out, err;
};
MainRun generator(std::vector<std::string> args) {
  args.insert(args.begin(), "generator");
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  std::ostringstream out, err;
  std::streambuf* old_out = std::cout.rdbuf(out.rdbuf());
  std::streambuf* old_err = std::cerr.rdbuf(err.rdbuf());
  const int code = glsl_files_main(paper::PaperScene{}, static_cast<int>(argv.size()), argv.data());
  std::cout.rdbuf(old_out);
  std::cerr.rdbuf(old_err);
  return {code, out.str(), err.str()};
}
}  // namespace

TEST_CASE("paper scene generator --names prints what a shader can call, and refuses an unknown shader") {
  const MainRun names = generator({"--names", "closest_hit", "shade.rchit"});
  CHECK(names.code == 0);
  CHECK(names.out.find("RadiancePayload trace_radiance(vec3 origin, float tmin, vec3 direction, float tmax, "
                       "RadiancePayload p)\n") != std::string::npos);
  CHECK(names.out.find("void trace_shadow(vec3 origin, float tmin, vec3 direction, float tmax)\n") != std::string::npos);
  CHECK(names.out.find("rayPayloadInEXT RadiancePayload payload;\n") != std::string::npos);
  CHECK(names.out.find("const vec3 pacman_aabb_min = vec3(") != std::string::npos);  // derived, not appended
  const MainRun list = generator({"--names"});
  CHECK(list.code == 0);
  CHECK(list.out.find("closest_hit shade.rchit\n") != std::string::npos);
  const MainRun unknown = generator({"--names", "closest_hit", "nope.rchit"});
  CHECK(unknown.code == 1);
  CHECK(unknown.err.find("the scene has no closest_hit shader \"nope.rchit\"; its stages are:") != std::string::npos);
  CHECK(unknown.err.find("raygen raygen.rgen") != std::string::npos);
}

TEST_CASE("paper scene knobs a march cannot survive are refused when set, naming the field, before the device sees them") {
  TestContext t;
  Paper p(t.ctx);
  // The fractals' knobs are the library's (set_field_knobs, through paper::set_frame), not the uniform's.
  paper::Frame c = paper::default_frame(width, height, 0.0f);
  c.knobs[paper::mandelbulb_id].max_steps = 0xFFFFFFFFu;  // 4 billion steps a ray: a hung device
  c.knobs[paper::mandelbulb_id].step_scale = 1e-30f;
  CHECK_THROWS_WITH_AS(paper::set_frame(p.renderer, c),
                       "march knobs of 'Renderer::set_field_knobs: field \"mandelbulb\"' (fractal field): max_steps "
                       "4294967295 is out of range; give 1 to 65536 (0 steps never hit; more would hold the device for minutes)",
                       UsageError);
  c.knobs[paper::mandelbulb_id].max_steps = 256;
  CHECK_THROWS_WITH_AS(paper::set_frame(p.renderer, c),
                       doctest::Contains("Renderer::set_field_knobs: field \"mandelbulb\"' (fractal field): step_scale 1e-30 must be in [1/1024, 1]"),
                       UsageError);
  c.knobs[paper::mandelbulb_id].step_scale = 1.0f;
  c.knobs[paper::julia_id].iterations = 1u << 20;
  CHECK_THROWS_WITH_AS(paper::set_frame(p.renderer, c),
                       doctest::Contains("field \"julia\"' (fractal field): iterations 1048576 is past 64"), UsageError);
  // A refused value left the last good one in place: the frame is the default scene's.
  c.knobs[paper::julia_id].iterations = 10;
  paper::set_frame(p.renderer, c);
  const vk::Frame ids = p.render(0.0f, paper::flag_object_ids);
  CHECK(at(ids, pixel_of(paper::mandelbulb_placement.translation)).r == paper::mandelbulb_id);
  CHECK(t.ctx.validation_messages().empty());
}
