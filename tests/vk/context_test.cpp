#include "test_context.hpp"

#include <proceduray/vk/buffer.hpp>
#include <proceduray/vk/context.hpp>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

using namespace proceduray;

namespace {
/// Sets an environment variable for one scope.
struct ScopedEnv {
  std::string name;
  std::string old;
  bool had;
  ScopedEnv(const char* n, const char* value) : name(n), had(std::getenv(n) != nullptr) {
    if (had) old = std::getenv(n);
    setenv(n, value, 1);
  }
  ~ScopedEnv() {
    if (had) setenv(name.c_str(), old.c_str(), 1);
    else unsetenv(name.c_str());
  }
};

/// How many devices of each kind can ray trace here, counted apart from Context with a bare
/// instance and the same requirements (detail::missing_for_ray_tracing), so each preference test
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
    if (!vk::detail::missing_for_ray_tracing(device).empty()) continue;
    VkPhysicalDeviceProperties props{};
    vkGetPhysicalDeviceProperties(device, &props);
    ++(props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? found.cpu : found.gpu);
  }
  vkDestroyInstance(instance, nullptr);
  return found;
}
}  // namespace

TEST_CASE("context picks a ray tracing device with sane SBT properties") {
  TestContext t;
  const SbtProperties p = t.ctx.sbt_properties();
  CHECK(p.handle_size >= 32);
  CHECK(p.base_alignment >= p.handle_alignment);
  CHECK(p.max_stride >= 4096);
  CHECK_FALSE(t.ctx.name().empty());
  CHECK(t.ctx.validation_enabled());
  CHECK(t.ctx.ray_tracing_properties().maxRayHitAttributeSize >= 32);
}

TEST_CASE("context honours a cpu preference") {
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

TEST_CASE("context gpu preference finds a gpu exactly when one can ray trace, else explains what is missing") {
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

TEST_CASE("context rejects an unknown PROCEDURAY_DEVICE value") {
  ScopedEnv env("PROCEDURAY_DEVICE", "tpu");
  CHECK_THROWS_WITH_AS(vk::Context(), doctest::Contains("PROCEDURAY_DEVICE='tpu'"), UsageError);
}

TEST_CASE("context PROCEDURAY_DEVICE=cpu selects the cpu device") {
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

TEST_CASE("context automatic preference takes a gpu when one can ray trace, else the cpu device") {
  const RayTracingDevices here = count_ray_tracing_devices();
  REQUIRE_MESSAGE(here.cpu + here.gpu > 0, "no ray-tracing device here: every vk test needs one");
  TestContext t;
  CHECK(t.ctx.is_cpu() == (here.gpu == 0));
}

TEST_CASE("context without any Vulkan driver names the install step") {
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
}

TEST_CASE("context submit runs the recorded commands and waits for them") {
  // The GPU fills a host-visible buffer; the host reads it the moment submit returns. Without the
  // wait the read races the device (lavapipe runs the queue on its own thread) and sees zeros.
  TestContext t;
  constexpr std::uint32_t words = 1u << 20;  // 4 MiB: long enough for a race to show
  vk::Buffer buffer(t.ctx, words * sizeof(std::uint32_t), VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::Buffer::host_visible);
  std::memset(buffer.data(), 0, words * sizeof(std::uint32_t));
  for (std::uint32_t round : {0xC0FFEEu, 0xBEEFu}) {
    t.ctx.submit([&](VkCommandBuffer cmd) {
      vkCmdFillBuffer(cmd, buffer.get(), 0, VK_WHOLE_SIZE, round);
      auto to_host = vk::make<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
      to_host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
      to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
      vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &to_host, 0, nullptr,
                           0, nullptr);
    });
    const auto* values = static_cast<const std::uint32_t*>(buffer.data());
    CHECK(values[0] == round);
    CHECK(values[words / 2] == round);
    CHECK(values[words - 1] == round);
  }
}
