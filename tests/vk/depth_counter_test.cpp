// The depth counter of the generated trace functions (scene/glsl_for.hpp, vk/output_images.hpp):
// shaders that trace in a cycle, 40 planes deep on one ray, under a declared depth of 31 (the
// most lavapipe and the NVIDIA driver allow) render, stopped at the declared depth and flagged,
// instead of nesting past the pipeline's depth (SIGSEGV in lavapipe).
#include "test_context.hpp"
#include "test_paths.hpp"

#include <proceduray/proceduray.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace depth_counter_test {
namespace pr = proceduray;
struct Colour {
  glm::vec3 rgb;
};
PROCEDURAY_STRUCT(Colour, scalar, rgb);
using SceneInterface = proceduray::ShaderInterface<proceduray::Payload<Colour>, proceduray::RootComponent<>,
                                                   proceduray::RootArguments<>, proceduray::Attributes<>>;
using Scene = proceduray::Scene<SceneInterface>;

constexpr std::uint32_t planes = 40;

/// `planes` squares across the view at z = 1, 2, ...; each closest hit traces on (nest.rchit).
/// `depth` 0 declares none.
Scene stack(std::uint32_t depth) {
  Scene s;
  const auto primary = s.add_ray<Colour>("primary", {});  // no miss shader: a miss keeps the payload
  const auto group = s.add_hit_group("plane", {.kind = pr::HitGroupKind::triangles, .closest_hit = "nest.rchit"});
  pr::TriangleMesh mesh;
  for (std::uint32_t i = 0; i < planes; ++i) {
    const float z = 1.0f + static_cast<float>(i);
    const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), {{-2, -2, z}, {2, -2, z}, {2, 2, z}, {-2, 2, z}});
    mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  const auto geometry = s.add_geometry("planes", pr::GeometryDesc::triangles(mesh));
  s.set_global_signature(pr::default_global_signature());
  s.add_raygen("nest.rgen");
  s.add_hit(primary, group, geometry);
  if (depth > 0) s.set_max_recursion_depth(depth);
  s.set_outputs({pr::Output::flags});
  return s;
}

pr::vk::RendererOptions options() { return {.shader_dirs = {test_source_dir() / "vk" / "shaders" / "nest"}}; }
}  // namespace depth_counter_test

using namespace proceduray;
using namespace depth_counter_test;

TEST_CASE("bad input: shaders that trace in a cycle 40 deep under a declared depth of 31 render, stopped and flagged") {
  TestContext t;  // validation on: a message fails the test
  constexpr std::uint32_t size = 16;
  for (std::uint32_t depth : {31u, 5u}) {
    CAPTURE(depth);
    const depth_counter_test::Scene scene = stack(depth);
    const Plan plan = compile(scene);
    REQUIRE(plan.depth_binding() != no_index);
    vk::Renderer renderer(t.ctx, scene, options());
    const vk::Frame f = renderer.render(size, size);
    REQUIRE(f.outputs.flags.size() == std::size_t{size} * size);
    // Every ray passes exactly `depth` planes: raygen's trace and depth - 1 nested ones.
    const auto expected = static_cast<int>(std::lround(255.0 * depth / planes));
    for (std::size_t i = 0; i < std::size_t{size} * size; ++i) {
      CHECK(static_cast<int>(f.rgba[4 * i]) == expected);
      CHECK((f.outputs.flags[i] & output_flag_depth) != 0);
    }
  }
}

TEST_CASE("the depth counter is generated only for a declared depth") {
  const depth_counter_test::Scene deep = stack(31);
  const std::string rchit = glsl_for(compile(deep), ShaderStage::closest_hit, "nest.rchit");
  CHECK(rchit.find("if (proceduray_level >= proceduray_max_depth) { output_flags(output_flag_depth); return false; }") !=
        std::string::npos);
  CHECK(rchit.find("const uint proceduray_max_depth = 31u;") != std::string::npos);
  const std::string rgen = glsl_for(compile(deep), ShaderStage::raygen, "nest.rgen");
  CHECK(rgen.find("bool proceduray_enter() { imageStore(proceduray_depth_image, ivec2(gl_LaunchIDEXT.xy), uvec4(1u)); "
                  "return true; }") != std::string::npos);
  // A derived depth is exact (and a cycle refused when the renderer builds): no counter, no cost.
  const Plan derived = compile(stack(0));
  CHECK(derived.depth_binding() == no_index);
  CHECK(glsl_for(derived, ShaderStage::closest_hit, "nest.rchit").find("proceduray_enter") == std::string::npos);
}
