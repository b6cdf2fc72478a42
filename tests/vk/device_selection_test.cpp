// vk/device_selection.hpp: the preference, PROCEDURAY_DEVICE, and what a device lacks.
#include "scoped_env.hpp"
#include "test_context.hpp"

#include <proceduray/vk/device_selection.hpp>
#include <proceduray/vk/vulkan_instance.hpp>

#include <cstdint>
#include <string>
#include <vector>

using namespace proceduray;

namespace {
/// How many devices of each kind can ray trace here, counted apart from Context with a bare
/// instance and the same requirements (missing_for_ray_tracing), so each preference test
/// knows which outcome this machine must give.
struct RayTracingDevices {
  int cpu = 0;
  int gpu = 0;
};
RayTracingDevices count_ray_tracing_devices() {
  auto app = vk::make<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
  app.apiVersion = VK_API_VERSION_1_2;
  auto info = vk::make<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
  info.pApplicationInfo = &app;
  VkInstance instance = VK_NULL_HANDLE;
  RayTracingDevices found;
  if (vkCreateInstance(&info, nullptr, &instance) != VK_SUCCESS) return found;
  std::uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance, &count, devices.data());
  for (VkPhysicalDevice device : devices) {
    if (!vk::missing_for_ray_tracing(device).empty()) continue;
    VkPhysicalDeviceProperties props{};
    vkGetPhysicalDeviceProperties(device, &props);
    ++(props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? found.cpu : found.gpu);
  }
  vkDestroyInstance(instance, nullptr);
  return found;
}
}  // namespace

TEST_CASE("device_selection: honours a cpu preference") {
  const RayTracingDevices here = count_ray_tracing_devices();
  INFO("ray-tracing devices here: " << here.cpu << " cpu, " << here.gpu << " gpu");
  if (here.cpu > 0) {  // lavapipe (Mesa >= 24.1): every machine set up by tools/setup.sh
    vk::Context ctx({.device = vk::DevicePreference::cpu, .validation = true});
    CHECK(ctx.is_cpu());
    CHECK(ctx.validation_messages().empty());
  } else {  // a GPU machine without lavapipe: the message names the package to install
    CHECK_THROWS_WITH_AS(vk::Context({.device = vk::DevicePreference::cpu}),
                         doctest::Contains("mesa-vulkan-drivers"), vk::NoRayTracingDevice);
  }
}

TEST_CASE("device_selection: gpu preference finds a gpu exactly when one can ray trace, else explains what is missing") {
  const RayTracingDevices here = count_ray_tracing_devices();
  INFO("ray-tracing devices here: " << here.cpu << " cpu, " << here.gpu << " gpu");
  if (here.gpu > 0) {
    vk::Context ctx({.device = vk::DevicePreference::gpu});
    CHECK_FALSE(ctx.is_cpu());
  } else {  // lavapipe only (CI): it is skipped by name, and the message says what a gpu needs
    try {
      vk::Context ctx({.device = vk::DevicePreference::gpu});
      FAIL("a gpu context was made on a machine whose ray-tracing devices are all cpus: " << ctx.name());
    } catch (const vk::NoRayTracingDevice& e) {
      const std::string what = e.what();
      CHECK(what.find("asked for device 'gpu'") != std::string::npos);
      CHECK(what.find("VK_KHR_ray_tracing_pipeline") != std::string::npos);
      CHECK(what.find("apt-get install") != std::string::npos);
      if (here.cpu > 0) CHECK(what.find("can ray trace but is not a gpu device") != std::string::npos);
    }
  }
}

TEST_CASE("device_selection: rejects an unknown PROCEDURAY_DEVICE value") {
  ScopedEnv env("PROCEDURAY_DEVICE", "tpu");
  CHECK_THROWS_WITH_AS(vk::Context(), doctest::Contains("PROCEDURAY_DEVICE='tpu'"), UsageError);
}

TEST_CASE("device_selection: PROCEDURAY_DEVICE=cpu selects the cpu device") {
  const RayTracingDevices here = count_ray_tracing_devices();
  INFO("ray-tracing devices here: " << here.cpu << " cpu, " << here.gpu << " gpu");
  ScopedEnv env("PROCEDURAY_DEVICE", "cpu");
  if (here.cpu > 0) {
    vk::Context ctx;  // automatic, overridden by the environment even when a gpu is present
    CHECK(ctx.is_cpu());
  } else {  // the GPU machine without lavapipe: the message names the device it skipped
    try {
      vk::Context ctx;
      FAIL("a context was made with PROCEDURAY_DEVICE=cpu and no cpu device: " << ctx.name());
    } catch (const vk::NoRayTracingDevice& e) {
      const std::string what = e.what();
      CHECK(what.find("asked for device 'cpu'") != std::string::npos);
      if (here.gpu > 0) CHECK(what.find("is not a cpu device") != std::string::npos);
    }
  }
}

TEST_CASE("device_selection: automatic preference takes a gpu when one can ray trace, else the cpu device") {
  const RayTracingDevices here = count_ray_tracing_devices();
  REQUIRE_MESSAGE(here.cpu + here.gpu > 0, "no ray-tracing device here: every vk test needs one");
  TestContext t;
  CHECK(t.ctx.is_cpu() == (here.gpu == 0));
}

TEST_CASE("device_selection: select_device alone returns a device that lacks nothing for ray tracing") {
  vk::VulkanInstance instance("proceduray tests", nullptr);
  const RayTracingDevices here = count_ray_tracing_devices();
  REQUIRE(here.cpu + here.gpu > 0);
  const VkPhysicalDevice device = vk::select_device(instance.get(), vk::DevicePreference::automatic);
  REQUIRE(device != VK_NULL_HANDLE);
  CHECK(vk::missing_for_ray_tracing(device).empty());
  VkPhysicalDeviceProperties props{};
  vkGetPhysicalDeviceProperties(device, &props);
  CHECK((props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) == (here.gpu == 0));
}
