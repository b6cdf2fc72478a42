// vk/renderer.hpp: a scene table made into device objects and traced, checked by pixels.
#include "frame_pixels.hpp"
#include "renderer_scene.hpp"
#include "test_context.hpp"

#include <cstring>
#include <fstream>
#include <filesystem>
#include <iterator>
#include <limits>
#include <string>
#include <utility>
#include <vector>

using namespace proceduray;
using renderer_scene::RendererScene;

namespace {

constexpr std::uint32_t width = 96;
constexpr std::uint32_t height = 64;

glm::ivec4 pixel(const vk::Frame& f, glm::ivec2 p) { return frame_pixels::rgba(f, p); }
using frame_pixels::bytes;
bool near(glm::ivec4 a, glm::ivec4 b) { return frame_pixels::near(a, b, 1); }

glm::ivec2 where(glm::vec3 p) { return project(renderer_scene::constants(width, height).camera, p, width, height); }

}  // namespace

TEST_CASE("renderer traces a scene table: per-instance records, triangles and procedural") {
  TestContext t;
  RendererScene s;
  vk::Renderer renderer(t.ctx, s.table(t.ctx), RendererScene::options());
  renderer_scene::prepare(renderer, width, height);
  const vk::Frame f = renderer.render(width, height);
  REQUIRE(f.rgba.size() == std::size_t{width} * height * 4);
  CHECK(near(pixel(f, where(renderer_scene::ball_centres[0])), bytes(renderer_scene::ball_colours[0])));
  CHECK(near(pixel(f, where(renderer_scene::ball_centres[1])), bytes(renderer_scene::ball_colours[1])));
  CHECK(near(pixel(f, where({0.0f, -1.0f, 2.5f})), bytes(renderer_scene::floor_colour)));
  CHECK(near(pixel(f, {0, 0}), bytes(renderer_scene::constants(width, height).sky)));
  CHECK(f.trace_ms > 0.0);
  CHECK(f.host_ms >= 0.0);
  CHECK_FALSE(f.tlas_refit);
  CHECK(renderer.timings().acceleration_ms > 0.0);
}

TEST_CASE("renderer uniform changes reach the next trace without rebuilding") {
  TestContext t;
  RendererScene s;
  vk::Renderer renderer(t.ctx, s.table(t.ctx), RendererScene::options());
  renderer_scene::prepare(renderer, width, height);
  const vk::Frame before = renderer.render(width, height);
  const glm::vec4 dusk{0.9f, 0.5f, 0.1f, 1.0f};
  renderer.set(renderer_scene::constants_slot, renderer_scene::constants(width, height, dusk));
  const vk::Frame after = renderer.render(width, height);
  CHECK(near(pixel(after, {0, 0}), bytes(dusk)));
  CHECK(pixel(before, where(renderer_scene::ball_centres[0])) == pixel(after, where(renderer_scene::ball_centres[0])));
}

TEST_CASE("renderer set_transform refits the TLAS and the image follows") {
  TestContext t;
  RendererScene s(UpdatePolicy::DynamicTransform);
  vk::Renderer renderer(t.ctx, s.table(t.ctx), RendererScene::options());
  renderer_scene::prepare(renderer, width, height);
  const VkDeviceSize blas_before = renderer.blas_bytes();
  const glm::vec3 moved{0.0f, 1.2f, -1.0f};
  renderer.set_transform(s.ball(), 1, glm::translate(glm::mat4(1.0f), moved));
  const vk::Frame f = renderer.render(width, height);
  CHECK(f.tlas_refit);
  CHECK(f.work == vk::FrameWork{.tlas_updates = 1});  // DynamicTransform: no BLAS work at all
  CHECK(near(pixel(f, where(moved)), bytes(renderer_scene::ball_colours[1])));
  CHECK_FALSE(near(pixel(f, where(renderer_scene::ball_centres[1])), bytes(renderer_scene::ball_colours[1])));
  CHECK(renderer.blas_bytes() == blas_before);
  const vk::Frame still = renderer.render(width, height);
  CHECK_FALSE(still.tlas_refit);  // nothing moved since
  CHECK(still.work == vk::FrameWork{});
  CHECK_THROWS_WITH_AS(renderer.set_transform(s.ball(), 2, glm::mat4(1.0f)), doctest::Contains("no instance 2"),
                       InvalidGeometryError);
  const glm::mat4 flat = glm::scale(glm::mat4(1.0f), glm::vec3(0.0f));  // affine, rank 0
  CHECK_THROWS_WITH_AS(renderer.set_transform(s.ball(), 0, flat), doctest::Contains("singular"), InvalidGeometryError);
}

TEST_CASE("renderer DynamicGeometry triangles: new vertices refit and a new mesh rebuilds") {
  TestContext t;
  RendererScene s(UpdatePolicy::Static, UpdatePolicy::DynamicGeometry);
  vk::Renderer renderer(t.ctx, s.table(t.ctx), RendererScene::options());
  renderer_scene::prepare(renderer, width, height);
  const GeometryId floor = s.scene().geometry_id("floor");
  const glm::ivec2 front_left = where({-2.0f, -1.0f, 2.5f});
  const glm::ivec2 front_right = where({2.0f, -1.0f, 2.5f});
  const glm::ivec4 grey = bytes(renderer_scene::floor_colour);
  const vk::Frame first = renderer.render(width, height);
  CHECK(near(pixel(first, front_left), grey));
  CHECK(first.work == vk::FrameWork{});
  // The same quad shrunk to x in [-6, 0]: the right half of the view loses its floor.
  const glm::vec3 half[] = {{-6, -1, -6}, {0, -1, -6}, {0, -1, 6}, {-6, -1, 6}};
  renderer.set_vertices(floor, half);
  const vk::Frame refit = renderer.render(width, height);
  CHECK(refit.work == vk::FrameWork{.blas_refits = 1, .tlas_updates = 1});
  CHECK(near(pixel(refit, front_left), grey));
  CHECK_FALSE(near(pixel(refit, front_right), grey));
  // One triangle of the full quad: other indices, so the BLAS is rebuilt and the TLAS with it.
  renderer.set_mesh(floor, {{{-6, -1, -6}, {6, -1, -6}, {6, -1, 6}, {-6, -1, 6}}, {0, 2, 1}});
  const vk::Frame rebuilt = renderer.render(width, height);
  CHECK(rebuilt.work == vk::FrameWork{.blas_builds = 1, .tlas_builds = 1});
  CHECK(near(pixel(rebuilt, where({2.2f, -1.0f, 1.5f})), grey));  // the triangle's half (x > z)
  CHECK_FALSE(near(pixel(rebuilt, front_left), grey));  // the missing triangle
  CHECK(renderer.render(width, height).work == vk::FrameWork{});
  const glm::vec3 three[3] = {};
  CHECK_THROWS_WITH_AS(renderer.set_vertices(floor, three),
                       doctest::Contains("has 4 vertices, 3 given; new positions keep the count: call set_mesh"),
                       InvalidGeometryError);
  CHECK_THROWS_WITH_AS(renderer.set_mesh(floor, {{{0, 0, 0}}, {0, 1, 2}}), doctest::Contains("index 1 is 1 but there are 1 vertices"),
                       InvalidGeometryError);
  CHECK_THROWS_WITH_AS(renderer.set_aabbs(floor, {}), doctest::Contains("is triangles; change its vertices with set_vertices"),
                       UsageError);
}

TEST_CASE("renderer bad transforms, instances and boxes fail at the call with InvalidGeometryError naming it") {
  TestContext t;
  RendererScene s(UpdatePolicy::DynamicGeometry);  // "ball": two procedural instances that may move and reshape
  vk::Renderer renderer(t.ctx, s.table(t.ctx), RendererScene::options());
  const glm::mat4 tiny = glm::scale(glm::mat4(1.0f), glm::vec3(1e-11f));
  glm::mat4 nan(1.0f);
  nan[3][1] = std::numeric_limits<float>::quiet_NaN();
  const std::string fix = "check for a zero or tiny (< 1e-10) scale";
  auto message = [&](const std::string& call, int instance) {
    return call + ": geometry \"ball\" instance " + std::to_string(instance) + " transform";
  };
  auto check_throws = [](auto call, const std::string& where, const std::string& what) {
    try {
      call();
      FAIL("no exception");
    } catch (const InvalidGeometryError& e) {
      const std::string text = e.what();
      CHECK_MESSAGE(text.find(where) != std::string::npos, text);
      CHECK_MESSAGE(text.find(what) != std::string::npos, text);
    }
  };
  check_throws([&] { renderer.set_transform(s.ball(), 1, tiny); }, message("Renderer::set_transform", 1) + " is singular",
               fix);
  check_throws([&] { renderer.set_transform(s.ball(), 1, nan); },
               message("Renderer::set_transform", 1) + " has a non-finite element at row 1 column 3",
               "give a finite affine transform");
  check_throws([&] { renderer.set_transform(s.ball(), 5, glm::mat4(1.0f)); },
               "Renderer::set_transform: geometry \"ball\" has 2 instance slots, no instance 5",
               "pass an instance index below 2");
  const glm::mat4 second_tiny[] = {glm::mat4(1.0f), tiny};
  check_throws([&] { renderer.set_transforms(s.ball(), second_tiny); },
               message("Renderer::set_transforms", 1) + " is singular", fix);
  const glm::mat4 first_nan[] = {nan, glm::mat4(1.0f)};
  check_throws([&] { renderer.set_transforms(s.ball(), first_nan); },
               message("Renderer::set_transforms", 0) + " has a non-finite element", "give a finite affine transform");
  const Aabb boxes[] = {Aabb{}, Aabb{glm::vec3(1.0f), glm::vec3(-1.0f)}};
  check_throws([&] { renderer.set_aabbs(s.ball(), boxes); }, "Renderer::set_aabbs: geometry \"ball\" AABB 1 has min",
               "swap the corners so min <= max on every axis");
  // Refused calls change nothing: the next frame does no acceleration-structure work.
  renderer_scene::prepare(renderer, width, height);
  CHECK(renderer.render(width, height).work == vk::FrameWork{});
}

TEST_CASE("renderer refuses to move or reshape a Static geometry") {
  TestContext t;
  RendererScene s;
  vk::Renderer renderer(t.ctx, s.table(t.ctx), RendererScene::options());
  CHECK_THROWS_WITH_AS(renderer.set_transform(s.ball(), 0, glm::mat4(1.0f)),
                       doctest::Contains("geometry \"ball\" is Static, so its instances were built not to move; "
                                         "declare it with update = UpdatePolicy::DynamicTransform"),
                       UsageError);
  const Aabb box{};
  CHECK_THROWS_WITH_AS(renderer.set_aabbs(s.ball(), {&box, 1}),
                       doctest::Contains("Renderer::set_aabbs: geometry \"ball\" is Static, so its BLAS was built not "
                                         "to change; declare it with update = UpdatePolicy::DynamicGeometry"),
                       UsageError);
  const glm::vec3 moved[4] = {};
  CHECK_THROWS_WITH_AS(renderer.set_vertices(s.scene().geometry_id("floor"), moved),
                       doctest::Contains("Renderer::set_vertices: geometry \"floor\" is Static"), UsageError);
}

TEST_CASE("renderer renders are byte identical") {
  TestContext t;
  RendererScene s;
  vk::Renderer renderer(t.ctx, s.table(t.ctx), RendererScene::options());
  renderer_scene::prepare(renderer, width, height);
  CHECK(renderer.render(width, height).rgba == renderer.render(width, height).rgba);
}

TEST_CASE("renderer storage buffers reach the shaders indexed by instance") {
  TestContext t;
  RendererScene s;
  vk::Renderer renderer(t.ctx, s.table(t.ctx), RendererScene::options());
  renderer_scene::prepare(renderer, width, height);
  const Plan& table = renderer.plan();
  // The shader indexes by gl_InstanceCustomIndexEXT: the instance's place in the TLAS.
  std::vector<renderer_scene::Tint> tints(table.instances().size(), {glm::vec4(1.0f)});
  tints[table.tlas_index(s.ball(), 1)] = {glm::vec4(0.5f)};
  renderer.set_storage(renderer_scene::tints_slot, std::span<const renderer_scene::Tint>(tints));
  const vk::Frame f = renderer.render(width, height);
  CHECK(near(pixel(f, where(renderer_scene::ball_centres[0])), bytes(renderer_scene::ball_colours[0])));
  CHECK(near(pixel(f, where(renderer_scene::ball_centres[1])), glm::ivec4(0, 0, 128, 255)));  // blue halved
}

TEST_CASE("renderer refuses to trace before its uniforms have values") {
  TestContext t;
  RendererScene s;
  vk::Renderer renderer(t.ctx, s.table(t.ctx), RendererScene::options());
  CHECK_THROWS_WITH_AS(renderer.render(width, height), doctest::Contains("set 0 binding 2 was never given a value"),
                       UsageError);
  renderer.set(renderer_scene::constants_slot, renderer_scene::constants(width, height));
  CHECK_THROWS_WITH_AS(renderer.render(width, height),
                       doctest::Contains("storage buffer at set 0 binding 3 was never given data"), UsageError);
  CHECK_THROWS_WITH_AS(renderer.set_storage(renderer_scene::tints_slot, {}), doctest::Contains("no elements"),
                       UsageError);
  renderer_scene::prepare(renderer, width, height);
  CHECK_THROWS_WITH_AS(renderer.render(0, height), doctest::Contains("size 0x64"), UsageError);
}

TEST_CASE("renderer names a missing shader and the folders it searched") {
  TestContext t;
  RendererScene s;
  auto options = RendererScene::options();
  options.shader_dirs = {test_output_dir("no_shaders_here")};
  CHECK_THROWS_WITH_AS(vk::Renderer(t.ctx, s.table(t.ctx), options), doctest::Contains("shader 'scene.rgen'"),
                       UsageError);
}

namespace {
/// A copy of the test shaders with `file` replaced by `text` (and `extra` files beside it).
std::filesystem::path shaders_with(const char* folder, const char* file, const std::string& text,
                                   const std::vector<std::pair<const char*, std::string>>& extra = {}) {
  const std::filesystem::path dir = test_output_dir(folder);
  std::filesystem::copy(test_source_dir() / "vk" / "shaders", dir,
                        std::filesystem::copy_options::recursive | std::filesystem::copy_options::overwrite_existing);
  std::ofstream(dir / file, std::ios::trunc) << text;
  for (const auto& [name, body] : extra) std::ofstream(dir / name, std::ios::trunc) << body;
  return dir;
}
std::string build_error(vk::Context& ctx, RendererScene& s, const std::filesystem::path& dir) {
  auto options = RendererScene::options();
  options.shader_dirs = {dir};
  options.cache = false;
  try {
    vk::Renderer renderer(ctx, s.table(ctx), options);
  } catch (const vk::ShaderCompileError& e) {
    return e.what();
  }
  return "built";
}
}  // namespace

TEST_CASE("renderer shader errors name the stage, the hit groups, and the included file and line") {
  TestContext t;
  RendererScene s;
  const auto dir = shaders_with("error_in_include", "ball.rchit", "#version 460\n#include \"colour.glsl\"\n"
                                "void main() { payload.rgb = ball_colour(); }\n",
                                {{"colour.glsl", "// line 1\nvec3 ball_colour() {\n  return nothing_here;\n}\n"}});
  const std::string what = build_error(t.ctx, s, dir);
  CAPTURE(what);
  CHECK(what.find("make_scene_pipeline: closest_hit shader '" + (dir / "ball.rchit").string() +
                  "' (hit groups \"ball\" (ray \"primary\")) failed to compile at " + (dir / "colour.glsl").string() +
                  ":3: 'nothing_here' : undeclared identifier") != std::string::npos);
}

TEST_CASE("renderer bad input: a trace function of an undeclared ray, or in a stage that cannot trace") {
  TestContext t;
  RendererScene s;
  const std::string glow = build_error(
      t.ctx, s, shaders_with("trace_undeclared", "ball.rchit", "#version 460\nvoid main() {\n"
                             "  payload = trace_glow(vec3(0.0), 0.0, vec3(1.0, 0.0, 0.0), 1.0, payload);\n}\n"));
  CAPTURE(glow);
  CHECK(glow.find("trace_glow is not generated: the scene declares no ray \"glow\" (its rays: \"primary\")") !=
        std::string::npos);
  const std::string isect = build_error(
      t.ctx, s, shaders_with("trace_in_intersection", "ball.rint", "#version 460\nvoid main() {\n"
                             "  trace_primary(vec3(0.0), 0.0, vec3(1.0, 0.0, 0.0), 1.0);\n}\n"));
  CAPTURE(isect);
  CHECK(isect.find("trace_primary is not generated for intersection shaders") != std::string::npos);
  // The generated function itself works: the unchanged shaders trace with it elsewhere (features test).
}

TEST_CASE("renderer pipeline cache is reused and a corrupt one is rebuilt") {
  TestContext t;
  RendererScene s;
  const auto path = test_output_dir("renderer_cache") / "pipeline.cache";
  std::filesystem::remove(path);
  {
    vk::Renderer cold(t.ctx, s.table(t.ctx), RendererScene::options(path));
    CHECK_FALSE(cold.timings().pipeline_cached);
  }
  REQUIRE(std::filesystem::exists(path));
  {
    vk::Renderer warm(t.ctx, s.table(t.ctx), RendererScene::options(path));
    CHECK(warm.timings().pipeline_cached);
  }
  std::ifstream in(path, std::ios::binary);
  const std::string valid((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  constexpr std::size_t head = vk::PipelineCache::magic.size() + 16;
  REQUIRE(valid.size() >= head + 32);  // lavapipe keeps only the header for ray-tracing pipelines
  std::string flipped = valid;
  flipped[head + 20] = static_cast<char>(flipped[head + 20] ^ 0x5A);
  // Another device's cache: a well-formed file whose driver header names another vendor.
  std::string foreign = valid;
  foreign[head + 8] = static_cast<char>(foreign[head + 8] ^ 0x01);
  const std::uint64_t sum = vk::PipelineCache::checksum(reinterpret_cast<const std::uint8_t*>(foreign.data()) + head,
                                                        foreign.size() - head);
  std::memcpy(foreign.data() + vk::PipelineCache::magic.size() + 8, &sum, 8);
  const std::pair<std::string, const char*> bad[] = {{"garbage", "not a proceduray pipeline cache"},
                                                     {valid.substr(0, valid.size() - 4), "checksum"},
                                                     {flipped, "checksum"},
                                                     {foreign, "another device or driver"}};
  for (const auto& [junk, why] : bad) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << junk;
    vk::PipelineCache cache(t.ctx, path);
    CHECK_FALSE(cache.loaded());
    CHECK(cache.warning().find(why) != std::string::npos);
    vk::Renderer rebuilt(t.ctx, s.table(t.ctx), RendererScene::options(path));
    CHECK_FALSE(rebuilt.timings().pipeline_cached);
    renderer_scene::prepare(rebuilt, width, height);
    CHECK(near(pixel(rebuilt.render(width, height), where(renderer_scene::ball_centres[0])),
               bytes(renderer_scene::ball_colours[0])));
    CHECK(vk::PipelineCache(t.ctx, path).loaded());  // saved again, valid
  }
}

TEST_CASE("renderer with unbound geometry fails at build naming the missing pairs") {
  TestContext t;
  RendererScene s;
  CHECK_THROWS_WITH_AS(compile(s.table(t.ctx, false)), doctest::Contains("ball"), SceneError);
}

TEST_CASE("renderer a ray without a miss shader leaves a missed payload as the raygen set it") {
  // Defined behaviour (docs/guide/errors.md): the miss record is null, so a miss runs no
  // shader; the raygen must initialise the payload before traceRayEXT.
  TestContext t;
  namespace rs = renderer_scene;
  rs::Scene scene;
  const auto primary = scene.add_ray<rs::Colour>("primary", {});
  const auto floor_group = scene.add_hit_group("floor", {.kind = HitGroupKind::triangles, .closest_hit = "floor.rchit"});
  const TriangleMesh quad{{{-6, -1, -6}, {6, -1, -6}, {6, -1, 6}, {-6, -1, 6}}, {0, 2, 1, 0, 3, 2}};
  const GeometryId floor = scene.add_geometry("floor", GeometryDesc::triangles(quad));
  scene.set_global_signature({.bindings = {{BindingKind::acceleration_structure, 0, 0, 1, "tlas"},
                                           {BindingKind::storage_image, 1, 0, 1, "image"}, rs::constants_slot, rs::tints_slot}});
  const auto paint = scene.add_local_signature<rs::Paint>("paint");
  scene.add_raygen("init.rgen");
  scene.add_hit(primary, floor_group, paint, rs::Paint{rs::floor_colour}, floor);
  vk::Renderer renderer(t.ctx, scene, RendererScene::options());
  rs::prepare(renderer, width, height);
  const vk::Frame f = renderer.render(width, height);
  CHECK(near(pixel(f, {0, 0}), bytes(glm::vec4(1, 0, 1, 1))));  // the sky: missed, payload as initialised
  CHECK(near(pixel(f, where({0.0f, -1.0f, 2.5f})), bytes(rs::floor_colour)));
}
