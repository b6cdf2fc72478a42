// vk/error.hpp: failed Vulkan calls become VulkanError naming the call, the result and the fix.
// A real device loss is not provoked (it can take the GPU down for other work); the report
// every call site goes through is checked instead.
#include <proceduray/vk/error.hpp>

#include <doctest/doctest.h>

#include <string>

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
