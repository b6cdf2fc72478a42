// examples/02_paper_scene with Tracing::iterative: reflections and shadows traced in a loop from
// raygen give the recursive image on a device whose maxRayRecursionDepth is forced to 1 (where
// the recursive scene is refused), and the pipeline's recursion depth and stack size are the
// minimum the scene needs.
#include "vk/frame_pixels.hpp"
#include "vk/test_context.hpp"

#include <02_paper_scene/paper_scene.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

using namespace proceduray;

namespace {

constexpr std::uint32_t width = 96, height = 64;

std::vector<std::uint8_t> render(const vk::Context& ctx, const paper::PaperScene& scene, std::uint32_t max_depth) {
  vk::Renderer renderer(ctx, scene, scene.renderer_options());
  paper::SceneConstants c = paper::default_constants(width, height, 0.0f);
  c.max_depth = max_depth;
  paper::set_frame(renderer, c);
  return renderer.render(width, height).rgba;
}

/// The spec's stack size with `depth` from the sizes the driver reports for the pipeline's groups.
VkDeviceSize stack_for(const vk::Context& ctx, const vk::Renderer& r, std::uint32_t depth) {
  const PipelinePlan& plan = r.plan().pipeline();
  VkDeviceSize raygen = 0, miss = 0, closest = 0, intersection = 0;
  auto size = [&](std::uint32_t g, VkShaderGroupShaderKHR which) {
    return ctx.rt().get_ray_tracing_shader_group_stack_size(ctx.device(), r.pipeline().get(), g, which);
  };
  for (std::uint32_t g = 0; g < plan.groups.size(); ++g) {
    const PlannedGroup& group = plan.groups[g];
    if (group.type == GroupType::general) {
      const VkDeviceSize s = size(g, VK_SHADER_GROUP_SHADER_GENERAL_KHR);
      (plan.stages[group.general].stage == ShaderStage::raygen ? raygen : miss) =
          std::max(plan.stages[group.general].stage == ShaderStage::raygen ? raygen : miss, s);
      continue;
    }
    if (group.closest_hit != unused_shader) closest = std::max(closest, size(g, VK_SHADER_GROUP_SHADER_CLOSEST_HIT_KHR));
    if (group.intersection != unused_shader) {
      intersection = std::max(intersection, size(g, VK_SHADER_GROUP_SHADER_INTERSECTION_KHR));
    }
  }
  return raygen + std::max({closest, miss, intersection}) + (depth - 1) * std::max(closest, miss);
}

}  // namespace

TEST_CASE("paper tracing - iterative tracing gives the recursive image where maxRayRecursionDepth is 1") {
  TestContext full;
  const paper::PaperScene recursive;
  const std::vector<std::uint8_t> expected = render(full.ctx, recursive, 3);
  vk::Context limited({.validation = true, .max_ray_recursion_depth = 1});
  REQUIRE(limited.limits().max_ray_recursion_depth == 1);
  const paper::PaperScene iterative({}, paper::Tracing::iterative);
  const std::vector<std::uint8_t> got = render(limited, iterative, 3);
  const std::vector<std::uint8_t> no_reflections = render(limited, iterative, 1);
  const frame_pixels::Diff same = frame_pixels::diff(got, expected, 1);
  const int worst = same.worst;
  const std::size_t differ = same.over;
  const std::size_t reflected = frame_pixels::diff(got, no_reflections, 8).over;
  CAPTURE(worst);
  CAPTURE(differ);
  CHECK(worst <= 3);                  // the same sum, added up in another order
  CHECK(differ <= got.size() / 200);  // and nearly everywhere to 1/255
  CHECK(reflected > 200);             // reflections were traced (the plane mirrors the objects)
  // The recursive scene needs depth 4 there: refused before any Vulkan object, with the fix.
  CHECK_THROWS_WITH_AS(vk::Renderer(limited, recursive, recursive.renderer_options()),
                       doctest::Contains("maxRayRecursionDepth); trace iteratively from raygen instead"),
                       DeviceLimitError);
  CHECK(limited.validation_messages().empty());
}

TEST_CASE("paper tracing - recursion depth and pipeline stack size are the scene's minimum") {
  TestContext t;
  const paper::PaperScene iterative({}, paper::Tracing::iterative);
  const Plan iterative_plan = compile(iterative);
  CHECK(iterative_plan.pipeline().max_recursion_depth == 1);  // derived: only raygen traces
  CHECK_FALSE(iterative_plan.pipeline().recursion_depth_declared);
  for (const std::uint32_t limit : {3u, 9u}) {
    const paper::PaperScene recursive({}, paper::Tracing::recursive, limit);
    CHECK(compile(recursive).pipeline().max_recursion_depth == limit + 1);  // radiance segments + the last shadow ray
  }
  CHECK_THROWS_WITH_AS(paper::PaperScene({}, paper::Tracing::recursive, 0), doctest::Contains("depth limit 0 is out of range"),
                       UsageError);
  const paper::PaperScene recursive;
  vk::Renderer a(t.ctx, iterative, iterative.renderer_options());
  vk::Renderer b(t.ctx, recursive, recursive.renderer_options());
  CHECK(a.pipeline().stack_size() == stack_for(t.ctx, a, 1));
  CHECK(b.pipeline().stack_size() == stack_for(t.ctx, b, paper::max_depth_limit + 1));
  CHECK(a.pipeline().stack_size() <= b.pipeline().stack_size());
  // Payload: the largest ray's, the radiance payload (iterative fields included).
  CHECK(iterative_plan.pipeline().max_payload_size == sizeof(paper::RadiancePayload));
}
