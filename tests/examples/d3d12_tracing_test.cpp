// examples/03_d3d12_scene with Tracing::iterative: the sample's scene, shadows and a reflection
// traced from raygen, gives the recursive image on a device whose maxRayRecursionDepth is forced
// to 1, where the recursive scene is refused.
#include "vk/frame_pixels.hpp"
#include "vk/test_context.hpp"

#include <03_d3d12_scene/d3d12_scene.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

using namespace proceduray;

TEST_CASE("d3d12 tracing - iterative tracing gives the recursive image where maxRayRecursionDepth is 1") {
  constexpr std::uint32_t width = 96, height = 64;
  const d3d12::SceneConstants c = d3d12::default_constants(d3d12::sample_camera(width, height), 0.5f);
  const auto prims = d3d12::default_primitives();
  TestContext full;
  const d3d12::D3d12Scene recursive(prims);
  vk::Renderer a(full.ctx, recursive, recursive.renderer_options());
  d3d12::set_frame(a, c);
  const std::vector<std::uint8_t> expected = a.render(width, height).rgba;
  vk::Context limited({.validation = true, .max_ray_recursion_depth = 1});
  const d3d12::D3d12Scene iterative(prims, d3d12::Layout::sample, {}, d3d12::Tracing::iterative);
  CHECK(compile(iterative).pipeline().max_recursion_depth == 1);
  vk::Renderer b(limited, iterative, iterative.renderer_options());
  d3d12::set_frame(b, c);
  const std::vector<std::uint8_t> got = b.render(width, height).rgba;
  d3d12::SceneConstants flat = c;
  flat.flags &= ~d3d12::flag_reflections;
  d3d12::set_frame(b, flat);
  const std::vector<std::uint8_t> no_reflections = b.render(width, height).rgba;
  const frame_pixels::Diff same = frame_pixels::diff(got, expected, 1);
  const int worst = same.worst;
  const std::size_t differ = same.over;
  const std::size_t reflected = frame_pixels::diff(got, no_reflections, 8).over;
  CAPTURE(worst);
  CAPTURE(differ);
  CHECK(worst <= 3);
  CHECK(differ <= got.size() / 200);
  CHECK(reflected > 200);  // the reflective ground mirrors the primitives
  CHECK_THROWS_WITH_AS(vk::Renderer(limited, recursive, recursive.renderer_options()),
                       doctest::Contains("trace iteratively from raygen instead"), DeviceLimitError);
  // The iterative scene carries its switch (a define, declared on the scene), so any options compile
  // its shaders for it: the pipeline needs depth 1 (a cycle with no declared depth is refused by
  // Plan::settle_recursion, tests/scene/recursion_test.cpp).
  vk::Renderer again(limited, iterative, d3d12::renderer_options());
  CHECK(again.plan().pipeline().max_recursion_depth == 1);
  CHECK(limited.validation_messages().empty());
}
