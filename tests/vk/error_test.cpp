// vk/error.hpp: failed Vulkan calls become VulkanError naming the call, the result and the fix.
// A real device loss is not provoked (it can take the GPU down for other work); the report
// every call site goes through is checked instead.
#include <proceduray/vk/error.hpp>

#include <proceduray/scene/compile.hpp>
#include <proceduray/vk/shader_compiler.hpp>

#include <doctest/doctest.h>

#include <exception>
#include <stdexcept>
#include <string>
#include <system_error>

using namespace proceduray::vk;

TEST_CASE("error device lost names the call that lost it and how to find the cause") {
  try {
    check(VK_ERROR_DEVICE_LOST, "vkQueueSubmit", "trace 1920x1080");
    FAIL("check did not throw");
  } catch (const VulkanError& e) {
    const std::string what = e.what();
    CHECK(e.result() == VK_ERROR_DEVICE_LOST);
    CHECK(e.call() == "vkQueueSubmit");
    CHECK(what.find("vkQueueSubmit failed (trace 1920x1080)") != std::string::npos);
    CHECK(what.find("the device was lost") != std::string::npos);
    CHECK(what.find("validation layer") != std::string::npos);
    CHECK(e.code().message().find("VK_ERROR_DEVICE_LOST") != std::string::npos);
  }
}

TEST_CASE("error out of memory suggests smaller work and success does not throw") {
  CHECK_NOTHROW(check(VK_SUCCESS, "vkCreateBuffer"));
  CHECK_THROWS_WITH_AS(check(VK_ERROR_OUT_OF_DEVICE_MEMORY, "vkAllocateMemory"),
                       doctest::Contains("vkAllocateMemory failed: out of memory; render smaller images"), VulkanError);
  CHECK_THROWS_WITH_AS(check(VK_ERROR_INITIALIZATION_FAILED, "vkCreateInstance"),
                       doctest::Contains("vkCreateInstance failed"), VulkanError);
}

namespace {
/// Runs `call` three times and checks it throws something caught as proceduray::Error, as
/// `StdBase` and as std::exception, each time with `expected` in what().
template <class StdBase, class Call>
void check_caught(Call call, const std::string& expected) {
  std::string as_error, as_std, as_exception;
  try {
    call();
  } catch (const proceduray::Error& e) {
    as_error = e.what();
  }
  try {
    call();
  } catch (const StdBase& e) {
    as_std = e.what();
  }
  try {
    call();
  } catch (const std::exception& e) {  // unambiguous: Error has no std base of its own
    as_exception = e.what();
  }
  CHECK_MESSAGE(as_error.find(expected) != std::string::npos, as_error);
  CHECK(as_std == as_error);
  CHECK(as_exception == as_error);
}
}  // namespace

TEST_CASE("error every library exception is a proceduray::Error and its std base") {
  proceduray::Scene<proceduray::ShaderInterface<proceduray::Payload<>, proceduray::RootComponent<>, proceduray::RootArguments<>, proceduray::Attributes<>>> scene;
  check_caught<std::logic_error>([&] { (void)scene.geometry_id("Pacmn"); },
                                 "Scene::geometry_id: unknown geometry id \"Pacmn\"");
  scene.add_raygen("scene.rgen");
  scene.set_max_recursion_depth(4);
  const proceduray::Plan plan = proceduray::compile(scene);
  proceduray::DeviceLimits shallow;
  shallow.max_ray_recursion_depth = 2;
  check_caught<std::runtime_error>([&] { (void)plan.layout(shallow); }, "allows 2 (maxRayRecursionDepth)");
  check_caught<std::system_error>([] { check(VK_ERROR_DEVICE_LOST, "vkQueueSubmit"); }, "vkQueueSubmit failed");
  check_caught<std::logic_error>(
      [] {
        (void)compile_glsl({.stage = proceduray::ShaderStage::miss, .name = "broken.rmiss",
                            .code = "#version 460\nvoid main() { nope = 1; }\n"});
      },
      "compile_glsl: shader 'broken.rmiss' failed to compile");
  // Usage errors and limits are told apart by their std base, and SceneError is a UsageError.
  try {
    (void)plan.layout(shallow);
    FAIL("no exception");
  } catch (const proceduray::UsageError&) {
    FAIL("a device limit caught as a usage error");
  } catch (const proceduray::DeviceLimitError& e) {
    CHECK(std::string(e.what()).find("Plan::layout") != std::string::npos);
  }
  CHECK_THROWS_AS((void)scene.geometry_id("Pacmn"), proceduray::UsageError);
  CHECK_THROWS_AS((void)scene.geometry_id("Pacmn"), proceduray::SceneError);
}
