// vk/vulkan_instance.hpp: the instance, the validation layer and its log.
#include "scoped_env.hpp"
#include "test_context.hpp"

#include <proceduray/vk/vulkan_instance.hpp>

#include <string>
#include <utility>

using namespace proceduray;

TEST_CASE("vulkan_instance: without any Vulkan driver names the install step") {
  // Point the loader at a driver manifest that does not exist: no device at all.
  ScopedEnv icd("VK_ICD_FILENAMES", "/nonexistent/proceduray_icd.json");
  ScopedEnv drivers("VK_DRIVER_FILES", "/nonexistent/proceduray_icd.json");
  try {
    vk::Context ctx;
    FAIL("a context was made with no driver");
  } catch (const vk::NoRayTracingDevice& e) {
    const std::string what = e.what();
    CHECK(what.find("mesa-vulkan-drivers") != std::string::npos);
  }
  CHECK_THROWS_WITH_AS(vk::VulkanInstance("proceduray tests", nullptr), doctest::Contains("VK_ERROR_INCOMPATIBLE_DRIVER"),
                       vk::NoRayTracingDevice);
}

TEST_CASE("vulkan_instance: a log turns validation on, no log leaves it off, and a move hands the instance over") {
  vk::ValidationLog log(/*print=*/true);
  vk::VulkanInstance with_log("proceduray tests", &log);
  CHECK(with_log.get() != VK_NULL_HANDLE);
  CHECK(with_log.validation_enabled());
  vk::VulkanInstance moved(std::move(with_log));
  CHECK(with_log.get() == VK_NULL_HANDLE);  // NOLINT(bugprone-use-after-move): moved-from is empty
  CHECK_FALSE(with_log.validation_enabled());
  CHECK(moved.validation_enabled());
  CHECK(log.messages().empty());
  const vk::VulkanInstance bare("proceduray tests", nullptr);
  CHECK(bare.get() != VK_NULL_HANDLE);
  CHECK_FALSE(bare.validation_enabled());
}
