// vk/output_images.hpp: per-pixel outputs traced on the device and read back, checked against the
// closed form of a unit ball under orthographic rays; and a scene that asks for none pays nothing.
#include "test_context.hpp"
#include "test_paths.hpp"

#include <proceduray/proceduray.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace output_images_test {
namespace pr = proceduray;
struct Colour {
  glm::vec3 rgb;
};
PROCEDURAY_STRUCT(Colour, scalar, rgb);
struct BallHit {
  glm::vec3 normal;
};
PROCEDURAY_STRUCT(BallHit, scalar, normal);
using SceneInterface = proceduray::ShaderInterface<proceduray::Payload<Colour>, proceduray::RootComponent<>, proceduray::RootArguments<>,
                                   proceduray::Attributes<BallHit>>;
using Scene = proceduray::Scene<SceneInterface>;

/// One unit ball at the origin, orthographic rays along +z (tests/vk/shaders/outputs).
Scene ball_scene(pr::OutputSet outputs) {
  Scene s;
  const auto primary = s.add_ray<Colour>("primary", {.miss = "sky.rmiss"});
  s.set_global_signature(pr::default_global_signature());
  s.add_raygen("ortho.rgen");
  pr::add_object<BallHit>(s, "ball", {.geometry = pr::GeometryDesc::procedural({pr::Aabb{}}), .intersection = "ball.rint",
                                      .closest_hit = {{primary, "ball.rchit"}}});
  s.set_outputs(outputs);
  return s;
}

pr::vk::RendererOptions options() { return {.shader_dirs = {test_source_dir() / "vk" / "shaders" / "outputs"}}; }

/// The ray of pixel (x, y) of a size x size frame (ortho.rgen's formula, in double).
glm::dvec2 ray_xy(std::uint32_t x, std::uint32_t y, std::uint32_t size) {
  const double u = (x + 0.5) / size * 3.0 - 1.5, v = (y + 0.5) / size * 3.0 - 1.5;
  return {u, -v};
}
}  // namespace output_images_test

using namespace proceduray;
using namespace output_images_test;

TEST_CASE("output images hold the camera ray's t, normal, ids, steps and flags per pixel") {
  TestContext t;
  constexpr std::uint32_t size = 48;
  const auto scene = ball_scene({Output::t, Output::normal, Output::ids, Output::steps, Output::flags});
  vk::Renderer renderer(t.ctx, scene, options());
  const vk::Frame f = renderer.render(size, size);
  const std::size_t n = std::size_t{size} * size;
  REQUIRE(f.outputs.t.size() == n);
  REQUIRE(f.outputs.normal.size() == 4 * n);
  REQUIRE(f.outputs.ids.size() == 4 * n);
  REQUIRE(f.outputs.steps.size() == n);
  REQUIRE(f.outputs.flags.size() == n);
  std::size_t hits = 0, checked = 0;
  for (std::uint32_t y = 0; y < size; ++y) {
    for (std::uint32_t x = 0; x < size; ++x) {
      const std::size_t i = std::size_t{y} * size + x;
      const glm::dvec2 p = ray_xy(x, y, size);
      const double r2 = glm::dot(p, p);
      const bool in_box = std::abs(p.x) <= 1.0 && std::abs(p.y) <= 1.0;
      if (std::abs(r2 - 1.0) < 1e-3) continue;  // too close to the silhouette to call in float
      ++checked;
      // Every call of the intersection shader adds 3; it runs only for rays that enter the box.
      CHECK(f.outputs.steps[i] % 3 == 0);
      CHECK((f.outputs.steps[i] > 0) == in_box);
      CHECK(((f.outputs.flags[i] & output_flag_started_inside) != 0) == (in_box && p.x > 0.0));
      if (r2 < 1.0) {
        ++hits;
        const double t_ref = 4.0 - std::sqrt(1.0 - r2);
        CHECK(f.outputs.t[i] == doctest::Approx(t_ref).epsilon(1e-5));
        const glm::dvec3 n_ref(p.x, p.y, -std::sqrt(1.0 - r2));
        const glm::dvec3 got(f.outputs.normal[4 * i], f.outputs.normal[4 * i + 1], f.outputs.normal[4 * i + 2]);
        CHECK(glm::length(got - n_ref) < 1e-4);
        CHECK(f.outputs.ids[4 * i] == 0u);      // instance custom index: the only instance
        CHECK(f.outputs.ids[4 * i + 1] == 0u);  // geometry index
        CHECK(f.outputs.ids[4 * i + 2] == 0u);  // primitive
        CHECK(f.rgba[4 * i] == 255);
      } else {
        CHECK(f.outputs.t[i] == -1.0f);  // cleared: nothing hit
        CHECK(f.outputs.normal[4 * i] == 0.0f);
        CHECK(f.outputs.ids[4 * i] == 0xffffffffu);
        CHECK(f.rgba[4 * i] == 0);
      }
    }
  }
  CHECK(hits > checked / 4);  // the ball covers pi/9 of the frame
  // A second frame starts from cleared images: the atomics do not accumulate across frames.
  const vk::Frame again = renderer.render(size, size);
  CHECK(again.outputs.steps == f.outputs.steps);
  CHECK(again.outputs.t == f.outputs.t);
}

TEST_CASE("output views of submitted frames equal the outputs render() copies, per frame in flight") {
  TestContext t;
  constexpr std::uint32_t size = 32;
  const auto scene = ball_scene({Output::t, Output::steps});
  vk::Renderer renderer(t.ctx, scene, options());
  const vk::Frame f = renderer.render(size, size);
  const vk::FrameTicket a = renderer.submit(size, size, vk::Readback::all);
  const vk::FrameTicket b = renderer.submit(size, size, vk::Readback::all);
  for (const vk::FrameTicket& ticket : {a, b}) {
    const std::span<const float> t_view = renderer.output<float>(ticket, Output::t);
    const std::span<const std::uint32_t> steps = renderer.output<std::uint32_t>(ticket, Output::steps);
    CHECK(std::vector<float>(t_view.begin(), t_view.end()) == f.outputs.t);
    CHECK(std::vector<std::uint32_t>(steps.begin(), steps.end()) == f.outputs.steps);
    const std::span<const std::uint8_t> rgba = renderer.rgba(ticket);
    CHECK(std::vector<std::uint8_t>(rgba.begin(), rgba.end()) == f.rgba);
  }
  CHECK_THROWS_WITH_AS(renderer.output<std::uint32_t>(a, Output::t),
                       doctest::Contains("output 't' holds float values; ask for output<float>"), UsageError);
  CHECK_THROWS_WITH_AS(renderer.output<float>(a, Output::normal),
                       doctest::Contains("does not ask for output 'normal'; add it with Scene::set_outputs"), UsageError);
  const vk::FrameTicket c = renderer.submit(size, size, vk::Readback::rgba);
  CHECK_THROWS_WITH_AS(renderer.output<float>(c, Output::t),
                       doctest::Contains("frame 4 was not submitted with Readback::all"), UsageError);
}

TEST_CASE("output images exist only for the outputs asked for and none give an empty Outputs") {
  TestContext t;
  vk::Renderer some(t.ctx, ball_scene({Output::t}), options());
  const vk::Frame f = some.render(16, 16);
  CHECK(f.outputs.t.size() == 256);
  CHECK(f.outputs.normal.empty());
  CHECK(f.outputs.steps.empty());
  vk::Renderer none(t.ctx, ball_scene({}), options());
  const vk::Frame g = none.render(16, 16);
  CHECK(g.outputs.t.empty());
  CHECK(g.outputs.flags.empty());
  CHECK(g.rgba == f.rgba);  // the colour does not depend on the outputs
}

TEST_CASE("output helpers of a scene without outputs leave the SPIR-V as it is without the calls") {
  const auto scene = ball_scene({});
  const Plan plan = compile(scene);
  const auto spirv = [&](ShaderStage stage, const std::string& name, const std::string& body) {
    return vk::compile_glsl({.stage = stage, .name = name, .code = "#version 460\n" + body,
                             .include_dirs = {}, .preamble = glsl_for(plan, stage, name)});
  };
  const std::string hit_with = "void main() { output_hit(normalize(hit.normal)); payload.rgb = vec3(1.0); }\n";
  const std::string hit_without = "void main() { payload.rgb = vec3(1.0); }\n";
  CHECK(spirv(ShaderStage::closest_hit, "ball.rchit", hit_with) == spirv(ShaderStage::closest_hit, "ball.rchit", hit_without));
  const std::string rint_with =
      "void main() { output_steps(3u); output_flags(output_flag_exhausted); output_t(1.0); hit.normal = vec3(1.0);"
      " reportIntersectionEXT(1.0, 0u); }\n";
  const std::string rint_without = "void main() { hit.normal = vec3(1.0); reportIntersectionEXT(1.0, 0u); }\n";
  CHECK(spirv(ShaderStage::intersection, "ball.rint", rint_with) == spirv(ShaderStage::intersection, "ball.rint", rint_without));
  // With outputs the calls are real: the SPIR-V differs (so the comparison above could fail).
  const Plan with = compile(ball_scene({Output::t, Output::steps}));
  const auto with_spirv = vk::compile_glsl({.stage = ShaderStage::intersection, .name = "ball.rint",
                                            .code = "#version 460\n" + rint_with, .include_dirs = {},
                                            .preamble = glsl_for(with, ShaderStage::intersection, "ball.rint")});
  CHECK(with_spirv != spirv(ShaderStage::intersection, "ball.rint", rint_with));
  // Payloads and records are untouched by outputs.
  CHECK(with.pipeline().max_payload_size == plan.pipeline().max_payload_size);
  CHECK(with.pipeline().max_attribute_size == plan.pipeline().max_attribute_size);
}
