// The Vulkan instance, the chosen ray-tracing device, its queue and its ray-tracing functions.
//
//   proceduray::vk::Context ctx({.device = proceduray::vk::DevicePreference::automatic,
//                                .validation = true});
//   ctx.name();              // "NVIDIA H100 80GB HBM3" or "llvmpipe (LLVM 15.0.6, 256 bits)"
//   ctx.sbt_properties();    // handle size and alignments for layout_sbt
//   ctx.submit([&](VkCommandBuffer cmd) { ... });   // records, submits and waits
//   ctx.validation_messages();  // what the validation layer reported (tests assert it is empty)
//
// Device choice: an NVIDIA (or other discrete) GPU when one offers ray tracing, else any
// other device that does (Mesa's lavapipe on a machine without a GPU). The environment
// variable PROCEDURAY_DEVICE=cpu|gpu|auto overrides DevicePreference::automatic.
// A Context is neither copied nor moved: every object made from it keeps a pointer to it.
#pragma once

#include <proceduray/scene/device_limits.hpp>
#include <proceduray/scene/sbt_layout.hpp>
#include <proceduray/vk/error.hpp>
#include <proceduray/vk/handle.hpp>
#include <proceduray/vk/structs.hpp>

#include <vulkan/vulkan.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace proceduray::vk {

/// Which kind of device to run on.
enum class DevicePreference {
  automatic,  ///< a GPU when one offers ray tracing, else a CPU device (lavapipe); PROCEDURAY_DEVICE may override
  gpu,        ///< a GPU only; throws when none offers ray tracing
  cpu,        ///< a CPU device (lavapipe) only
};

/// How a Context starts. Every member has a default that works on any supported machine.
struct ContextOptions {
  DevicePreference device = DevicePreference::automatic;  ///< default: automatic
  bool validation = false;  ///< enable VK_LAYER_KHRONOS_validation and collect its messages; default off
  bool print_validation = true;  ///< also print validation messages to stderr; default on
  const char* application_name = "proceduray";  ///< reported to the driver
};

/// Ray-tracing functions loaded from the device (extension entry points are not exported by the loader).
struct DeviceFunctions {
  PFN_vkCreateAccelerationStructureKHR create_acceleration_structure = nullptr;
  PFN_vkDestroyAccelerationStructureKHR destroy_acceleration_structure = nullptr;
  PFN_vkGetAccelerationStructureBuildSizesKHR get_acceleration_structure_build_sizes = nullptr;
  PFN_vkGetAccelerationStructureDeviceAddressKHR get_acceleration_structure_device_address = nullptr;
  PFN_vkCmdBuildAccelerationStructuresKHR cmd_build_acceleration_structures = nullptr;
  PFN_vkCreateRayTracingPipelinesKHR create_ray_tracing_pipelines = nullptr;
  PFN_vkGetRayTracingShaderGroupHandlesKHR get_ray_tracing_shader_group_handles = nullptr;
  PFN_vkCmdTraceRaysKHR cmd_trace_rays = nullptr;
  PFN_vkCmdWriteAccelerationStructuresPropertiesKHR cmd_write_acceleration_structures_properties = nullptr;
  PFN_vkCmdCopyAccelerationStructureKHR cmd_copy_acceleration_structure = nullptr;
  PFN_vkGetRayTracingShaderGroupStackSizeKHR get_ray_tracing_shader_group_stack_size = nullptr;
  PFN_vkCmdSetRayTracingPipelineStackSizeKHR cmd_set_ray_tracing_pipeline_stack_size = nullptr;
};

/// Thrown when no device can ray trace: says what each device lacks and how to get one that can.
class NoRayTracingDevice : public EnvironmentError {
 public:
  using EnvironmentError::EnvironmentError;
};

/// Instance, device, queue and command pool for one ray-tracing device.
class Context {
 public:
  explicit Context(const ContextOptions& options = {});
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
  ~Context();

  VkInstance instance() const noexcept { return m_instance; }
  VkPhysicalDevice physical_device() const noexcept { return m_physical; }
  VkDevice device() const noexcept { return m_device; }
  VkQueue queue() const noexcept { return m_queue; }
  const DeviceFunctions& rt() const noexcept { return m_rt; }
  /// The device's name as the driver reports it.
  const std::string& name() const noexcept { return m_name; }
  /// True when the device is a CPU implementation (lavapipe).
  bool is_cpu() const noexcept { return m_properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU; }
  const VkPhysicalDeviceProperties& properties() const noexcept { return m_properties; }
  const VkPhysicalDeviceRayTracingPipelinePropertiesKHR& ray_tracing_properties() const noexcept { return m_rt_properties; }
  /// The numbers layout_sbt needs, read from the device.
  SbtProperties sbt_properties() const noexcept {
    return {m_rt_properties.shaderGroupHandleSize, m_rt_properties.shaderGroupHandleAlignment,
            m_rt_properties.shaderGroupBaseAlignment, m_rt_properties.maxShaderGroupStride};
  }
  /// The limits the scene layer checks a built shader table against.
  DeviceLimits limits() const {
    return {sbt_properties(), m_rt_properties.maxRayRecursionDepth, m_rt_properties.maxRayHitAttributeSize,
            m_max_geometry_count, m_max_instance_count, name()};
  }
  /// Nanoseconds per timestamp tick; 0 when the queue cannot write timestamps.
  double timestamp_period_ns() const noexcept { return m_timestamp_period; }
  std::uint32_t queue_family() const noexcept { return m_queue_family; }
  VkCommandPool command_pool() const noexcept { return m_pool; }
  /// minAccelerationStructureScratchOffsetAlignment.
  std::uint32_t scratch_alignment() const noexcept { return m_scratch_alignment; }
  /// Index of a memory type with all `flags` among `type_bits`; throws when there is none.
  std::uint32_t memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags flags) const;

  /// Records commands into a one-time command buffer, submits it and waits for the queue.
  void submit(const std::function<void(VkCommandBuffer)>& record) const;

  /// Validation messages (warnings and errors) reported so far; empty when validation is off.
  std::vector<std::string> validation_messages() const {
    std::lock_guard lock(m_messages_mutex);
    return m_messages;
  }
  bool validation_enabled() const noexcept { return m_messenger != VK_NULL_HANDLE; }

 private:
  static VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void* self) {
    auto* context = static_cast<Context*>(self);
    std::string text = data->pMessage ? data->pMessage : "";
    if (context->m_print) {
      std::fprintf(stderr, "proceduray: validation %s: %s\n",
                   severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error" : "warning", text.c_str());
    }
    std::lock_guard lock(context->m_messages_mutex);
    context->m_messages.push_back(std::move(text));
    return VK_FALSE;
  }
  void release() noexcept;
  void create_instance(const ContextOptions& options);
  void pick_device(DevicePreference preference);
  void create_device();

  VkInstance m_instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT m_messenger = VK_NULL_HANDLE;
  VkPhysicalDevice m_physical = VK_NULL_HANDLE;
  VkDevice m_device = VK_NULL_HANDLE;
  VkQueue m_queue = VK_NULL_HANDLE;
  VkCommandPool m_pool = VK_NULL_HANDLE;
  std::uint32_t m_queue_family = 0;
  std::uint32_t m_scratch_alignment = 1;
  std::uint64_t m_max_geometry_count = 0;
  std::uint64_t m_max_instance_count = 0;
  double m_timestamp_period = 0.0;
  std::string m_name;
  VkPhysicalDeviceProperties m_properties{};
  VkPhysicalDeviceRayTracingPipelinePropertiesKHR m_rt_properties{};
  VkPhysicalDeviceMemoryProperties m_memory{};
  DeviceFunctions m_rt;
  bool m_print = true;
  mutable std::mutex m_messages_mutex;
  std::vector<std::string> m_messages;
};

// ---------------------------------------------------------------------------------------------

namespace detail {

inline constexpr const char* required_device_extensions[] = {
    VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME,
    VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
    VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME,
};

inline constexpr const char* validation_layer = "VK_LAYER_KHRONOS_validation";

/// What a physical device lacks for ray tracing, as readable phrases; empty when it has everything.
inline std::vector<std::string> missing_for_ray_tracing(VkPhysicalDevice device) {
  std::vector<std::string> missing;
  VkPhysicalDeviceProperties props{};
  vkGetPhysicalDeviceProperties(device, &props);
  if (props.apiVersion < VK_API_VERSION_1_2) missing.emplace_back("Vulkan 1.2");
  std::uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data());
  for (const char* name : required_device_extensions) {
    bool found = std::any_of(extensions.begin(), extensions.end(),
                             [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
    if (!found) missing.emplace_back(name);
  }
  if (!missing.empty()) return missing;
  auto as = make<VkPhysicalDeviceAccelerationStructureFeaturesKHR>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR);
  auto rt = make<VkPhysicalDeviceRayTracingPipelineFeaturesKHR>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR, &as);
  auto v12 = make<VkPhysicalDeviceVulkan12Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &rt);
  auto features = make<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &v12);
  vkGetPhysicalDeviceFeatures2(device, &features);
  if (!rt.rayTracingPipeline) missing.emplace_back("feature rayTracingPipeline");
  if (!as.accelerationStructure) missing.emplace_back("feature accelerationStructure");
  if (!v12.bufferDeviceAddress) missing.emplace_back("feature bufferDeviceAddress");
  if (!v12.scalarBlockLayout) missing.emplace_back("feature scalarBlockLayout");
  return missing;
}

inline DevicePreference preference_from_environment(DevicePreference preference) {
  if (preference != DevicePreference::automatic) return preference;
  const char* env = std::getenv("PROCEDURAY_DEVICE");
  if (env == nullptr || *env == '\0' || std::strcmp(env, "auto") == 0) return preference;
  if (std::strcmp(env, "cpu") == 0) return DevicePreference::cpu;
  if (std::strcmp(env, "gpu") == 0) return DevicePreference::gpu;
  throw UsageError(std::string("Context: PROCEDURAY_DEVICE='") + env +
                   "' is not a device choice; use cpu, gpu or auto");
}

inline const char* to_string(DevicePreference p) {
  return p == DevicePreference::cpu ? "cpu" : p == DevicePreference::gpu ? "gpu" : "auto";
}

}  // namespace detail

inline Context::Context(const ContextOptions& options) : m_print(options.print_validation) {
  const DevicePreference preference = detail::preference_from_environment(options.device);
  try {
    create_instance(options);
    pick_device(preference);
    create_device();
  } catch (...) {
    release();  // the destructor does not run for a constructor that threw
    throw;
  }
}

inline Context::~Context() { release(); }

inline void Context::release() noexcept {
  if (m_device != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(m_device);
    if (m_pool != VK_NULL_HANDLE) vkDestroyCommandPool(m_device, m_pool, nullptr);
    vkDestroyDevice(m_device, nullptr);
    m_device = VK_NULL_HANDLE;
  }
  if (m_messenger != VK_NULL_HANDLE) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(m_instance, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy != nullptr) destroy(m_instance, m_messenger, nullptr);
    m_messenger = VK_NULL_HANDLE;
  }
  if (m_instance != VK_NULL_HANDLE) {
    vkDestroyInstance(m_instance, nullptr);
    m_instance = VK_NULL_HANDLE;
  }
}

inline void Context::create_instance(const ContextOptions& options) {
  auto app = make<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
  app.pApplicationName = options.application_name;
  app.pEngineName = "proceduray";
  app.apiVersion = VK_API_VERSION_1_2;

  std::vector<const char*> layers;
  std::vector<const char*> extensions;
  auto messenger = make<VkDebugUtilsMessengerCreateInfoEXT>(VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
  if (options.validation) {
    std::uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> available(count);
    vkEnumerateInstanceLayerProperties(&count, available.data());
    bool found = std::any_of(available.begin(), available.end(), [](const VkLayerProperties& l) {
      return std::strcmp(l.layerName, detail::validation_layer) == 0;
    });
    if (!found) {
      throw EnvironmentError(
          "Context: validation was asked for but VK_LAYER_KHRONOS_validation is not installed; "
          "install it (apt-get install vulkan-validationlayers) or set ContextOptions::validation = false");
    }
    layers.push_back(detail::validation_layer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    messenger.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messenger.pfnUserCallback = &Context::on_message;
    messenger.pUserData = this;
  }

  auto info = make<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
  info.pNext = options.validation ? &messenger : nullptr;  // also catches messages from instance creation
  info.pApplicationInfo = &app;
  info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VkResult result = vkCreateInstance(&info, nullptr, &m_instance);
  if (result == VK_ERROR_INCOMPATIBLE_DRIVER) {
    throw NoRayTracingDevice(
        "Context: vkCreateInstance found no Vulkan driver (VK_ERROR_INCOMPATIBLE_DRIVER). On a machine without a "
        "GPU install Mesa >= 24.1 (Debian 12: apt-get install -t bookworm-backports mesa-vulkan-drivers; "
        "tools/setup.sh does this); on an NVIDIA GPU install its driver");
  }
  check(result, "vkCreateInstance");
  if (options.validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(m_instance, "vkCreateDebugUtilsMessengerEXT"));
    check(create(m_instance, &messenger, nullptr, &m_messenger), "vkCreateDebugUtilsMessengerEXT");
  }
}

inline void Context::pick_device(DevicePreference preference) {
  std::uint32_t count = 0;
  check(vkEnumeratePhysicalDevices(m_instance, &count, nullptr), "vkEnumeratePhysicalDevices");
  std::vector<VkPhysicalDevice> devices(count);
  check(vkEnumeratePhysicalDevices(m_instance, &count, devices.data()), "vkEnumeratePhysicalDevices");

  // Rank capable devices: discrete GPU, integrated, virtual, then CPU.
  auto rank = [](VkPhysicalDeviceType type) {
    switch (type) {
      case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
      case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
      case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
      case VK_PHYSICAL_DEVICE_TYPE_CPU: return 4;
      default: return 3;
    }
  };
  std::string report;
  int best_rank = 1 << 30;
  for (VkPhysicalDevice device : devices) {
    VkPhysicalDeviceProperties props{};
    vkGetPhysicalDeviceProperties(device, &props);
    const bool cpu = props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    const auto missing = detail::missing_for_ray_tracing(device);
    report += std::string("\n  ") + props.deviceName + (cpu ? " (cpu)" : " (gpu)") + ": ";
    if (!missing.empty()) {
      report += "lacks";
      for (const auto& m : missing) report += " " + m;
      continue;
    }
    if ((preference == DevicePreference::cpu && !cpu) || (preference == DevicePreference::gpu && cpu)) {
      report += std::string("can ray trace but is not a ") + detail::to_string(preference) + " device";
      continue;
    }
    report += "can ray trace";
    if (rank(props.deviceType) < best_rank) {
      best_rank = rank(props.deviceType);
      m_physical = device;
      m_properties = props;
    }
  }
  if (m_physical == VK_NULL_HANDLE) {
    throw NoRayTracingDevice(
        std::string("Context: no Vulkan device can ray trace (asked for device '") + detail::to_string(preference) +
        "'). Devices found:" + (devices.empty() ? std::string("\n  none") : report) +
        "\nRay tracing needs VK_KHR_ray_tracing_pipeline and VK_KHR_acceleration_structure. Without a GPU install "
        "Mesa >= 24.1 for lavapipe (Debian 12: tools/setup.sh, or apt-get install -t bookworm-backports "
        "mesa-vulkan-drivers); with an NVIDIA GPU install its driver; or set PROCEDURAY_DEVICE=auto");
  }
  m_name = m_properties.deviceName;
  auto as = make<VkPhysicalDeviceAccelerationStructurePropertiesKHR>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR);
  m_rt_properties = make<VkPhysicalDeviceRayTracingPipelinePropertiesKHR>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR, &as);
  auto props2 = make<VkPhysicalDeviceProperties2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &m_rt_properties);
  vkGetPhysicalDeviceProperties2(m_physical, &props2);
  m_rt_properties.pNext = nullptr;
  m_scratch_alignment = std::max(1u, as.minAccelerationStructureScratchOffsetAlignment);
  m_max_geometry_count = as.maxGeometryCount;
  m_max_instance_count = as.maxInstanceCount;
  vkGetPhysicalDeviceMemoryProperties(m_physical, &m_memory);
}

inline void Context::create_device() {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(m_physical, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(m_physical, &count, families.data());
  auto family = std::find_if(families.begin(), families.end(), [](const VkQueueFamilyProperties& f) {
    return (f.queueFlags & VK_QUEUE_COMPUTE_BIT) != 0;
  });
  if (family == families.end()) {
    throw NoRayTracingDevice("Context: device " + m_name + " has no compute queue to trace rays on");
  }
  m_queue_family = static_cast<std::uint32_t>(family - families.begin());
  m_timestamp_period = family->timestampValidBits > 0 ? m_properties.limits.timestampPeriod : 0.0;

  // Optional features the shader layer can use when present (64-bit integers for device addresses).
  VkPhysicalDeviceFeatures supported{};
  vkGetPhysicalDeviceFeatures(m_physical, &supported);

  auto as = make<VkPhysicalDeviceAccelerationStructureFeaturesKHR>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR);
  as.accelerationStructure = VK_TRUE;
  auto rt = make<VkPhysicalDeviceRayTracingPipelineFeaturesKHR>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR, &as);
  rt.rayTracingPipeline = VK_TRUE;
  auto v12 = make<VkPhysicalDeviceVulkan12Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &rt);
  v12.bufferDeviceAddress = VK_TRUE;
  v12.scalarBlockLayout = VK_TRUE;
  auto features = make<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &v12);
  features.features.shaderInt64 = supported.shaderInt64;
  features.features.shaderFloat64 = supported.shaderFloat64;

  const float priority = 1.0f;
  auto queue = make<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
  queue.queueFamilyIndex = m_queue_family;
  queue.queueCount = 1;
  queue.pQueuePriorities = &priority;
  auto info = make<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &features);
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue;
  info.enabledExtensionCount = static_cast<std::uint32_t>(std::size(detail::required_device_extensions));
  info.ppEnabledExtensionNames = detail::required_device_extensions;
  check(vkCreateDevice(m_physical, &info, nullptr, &m_device), "vkCreateDevice", m_name);
  vkGetDeviceQueue(m_device, m_queue_family, 0, &m_queue);

  auto pool = make<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
  pool.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT | VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool.queueFamilyIndex = m_queue_family;
  check(vkCreateCommandPool(m_device, &pool, nullptr, &m_pool), "vkCreateCommandPool");

  auto load = [&](auto& fn, const char* name) {
    fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(vkGetDeviceProcAddr(m_device, name));
    if (fn == nullptr) throw NoRayTracingDevice("Context: device " + m_name + " does not export " + name);
  };
  load(m_rt.create_acceleration_structure, "vkCreateAccelerationStructureKHR");
  load(m_rt.destroy_acceleration_structure, "vkDestroyAccelerationStructureKHR");
  load(m_rt.get_acceleration_structure_build_sizes, "vkGetAccelerationStructureBuildSizesKHR");
  load(m_rt.get_acceleration_structure_device_address, "vkGetAccelerationStructureDeviceAddressKHR");
  load(m_rt.cmd_build_acceleration_structures, "vkCmdBuildAccelerationStructuresKHR");
  load(m_rt.create_ray_tracing_pipelines, "vkCreateRayTracingPipelinesKHR");
  load(m_rt.get_ray_tracing_shader_group_handles, "vkGetRayTracingShaderGroupHandlesKHR");
  load(m_rt.cmd_trace_rays, "vkCmdTraceRaysKHR");
  load(m_rt.cmd_write_acceleration_structures_properties, "vkCmdWriteAccelerationStructuresPropertiesKHR");
  load(m_rt.cmd_copy_acceleration_structure, "vkCmdCopyAccelerationStructureKHR");
  load(m_rt.get_ray_tracing_shader_group_stack_size, "vkGetRayTracingShaderGroupStackSizeKHR");
  load(m_rt.cmd_set_ray_tracing_pipeline_stack_size, "vkCmdSetRayTracingPipelineStackSizeKHR");
}

inline std::uint32_t Context::memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags flags) const {
  for (std::uint32_t i = 0; i < m_memory.memoryTypeCount; ++i) {
    if ((type_bits & (1u << i)) != 0 && (m_memory.memoryTypes[i].propertyFlags & flags) == flags) return i;
  }
  throw VulkanError(VK_ERROR_OUT_OF_DEVICE_MEMORY, "vkAllocateMemory",
                    "Context::memory_type: device " + m_name + " has no memory type with property flags " +
                        std::to_string(flags) + " for type bits " + std::to_string(type_bits));
}

inline void Context::submit(const std::function<void(VkCommandBuffer)>& record) const {
  auto alloc = make<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
  alloc.commandPool = m_pool;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  check(vkAllocateCommandBuffers(m_device, &alloc, &cmd), "vkAllocateCommandBuffers");
  struct Free {
    VkDevice device;
    VkCommandPool pool;
    VkCommandBuffer cmd;
    ~Free() { vkFreeCommandBuffers(device, pool, 1, &cmd); }
  } free_later{m_device, m_pool, cmd};

  auto begin = make<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
  record(cmd);
  check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");

  auto fence_info = make<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
  VkFence raw_fence = VK_NULL_HANDLE;
  check(vkCreateFence(m_device, &fence_info, nullptr, &raw_fence), "vkCreateFence");
  auto fence = own(m_device, raw_fence, vkDestroyFence);
  auto submit = make<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  check(vkQueueSubmit(m_queue, 1, &submit, raw_fence), "vkQueueSubmit");
  check(vkWaitForFences(m_device, 1, &raw_fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
}

}  // namespace proceduray::vk
