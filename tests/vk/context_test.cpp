#include "test_context.hpp"

#include <proceduray/vk/context.hpp>

#include <cstdlib>
#include <string>

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
  // Every machine the tests run on has lavapipe; the GPU machine has it too once Mesa is installed.
  try {
    vk::Context ctx({.device = vk::DevicePreference::cpu, .validation = true});
    CHECK(ctx.is_cpu());
    CHECK(ctx.validation_messages().empty());
  } catch (const vk::NoRayTracingDevice& e) {
    // A machine with no CPU driver must say so, naming what to install.
    CHECK(std::string(e.what()).find("mesa-vulkan-drivers") != std::string::npos);
  }
}

TEST_CASE("context gpu preference either finds a gpu or explains what is missing") {
  try {
    vk::Context ctx({.device = vk::DevicePreference::gpu});
    CHECK_FALSE(ctx.is_cpu());
  } catch (const vk::NoRayTracingDevice& e) {
    const std::string what = e.what();
    CHECK(what.find("asked for device 'gpu'") != std::string::npos);
    CHECK(what.find("VK_KHR_ray_tracing_pipeline") != std::string::npos);
    CHECK(what.find("apt-get install") != std::string::npos);
  }
}

TEST_CASE("context rejects an unknown PROCEDURAY_DEVICE value") {
  ScopedEnv env("PROCEDURAY_DEVICE", "tpu");
  CHECK_THROWS_WITH_AS(vk::Context(), doctest::Contains("PROCEDURAY_DEVICE='tpu'"), std::invalid_argument);
}

TEST_CASE("context PROCEDURAY_DEVICE=cpu selects the cpu device") {
  ScopedEnv env("PROCEDURAY_DEVICE", "cpu");
  try {
    vk::Context ctx;
    CHECK(ctx.is_cpu());
  } catch (const vk::NoRayTracingDevice& e) {
    // Seen on the GPU machine, which has no lavapipe: the message names the device it skipped.
    const std::string what = e.what();
    CHECK(what.find("asked for device 'cpu'") != std::string::npos);
    CHECK(what.find("is not a cpu device") != std::string::npos);
  }
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

TEST_CASE("context submit runs the recorded commands and waits") {
  TestContext t;
  bool recorded = false;
  t.ctx.submit([&](VkCommandBuffer cmd) { recorded = cmd != VK_NULL_HANDLE; });
  CHECK(recorded);
}
