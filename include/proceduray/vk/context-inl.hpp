// The bodies of proceduray/vk/context.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/context.hpp"

#if PROCEDURAY_BODIES
namespace proceduray::vk::detail {

PROCEDURAY_DECL DeviceFunctions load_device_functions(VkDevice device, const std::string& name) {
  DeviceFunctions rt;
  auto load = [&](auto& fn, const char* entry) {
    fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(vkGetDeviceProcAddr(device, entry));
    if (fn == nullptr) throw NoRayTracingDevice("Context: device " + name + " does not export " + entry);
  };
  load(rt.create_acceleration_structure, "vkCreateAccelerationStructureKHR");
  load(rt.destroy_acceleration_structure, "vkDestroyAccelerationStructureKHR");
  load(rt.get_acceleration_structure_build_sizes, "vkGetAccelerationStructureBuildSizesKHR");
  load(rt.get_acceleration_structure_device_address, "vkGetAccelerationStructureDeviceAddressKHR");
  load(rt.cmd_build_acceleration_structures, "vkCmdBuildAccelerationStructuresKHR");
  load(rt.create_ray_tracing_pipelines, "vkCreateRayTracingPipelinesKHR");
  load(rt.get_ray_tracing_shader_group_handles, "vkGetRayTracingShaderGroupHandlesKHR");
  load(rt.cmd_trace_rays, "vkCmdTraceRaysKHR");
  load(rt.cmd_write_acceleration_structures_properties, "vkCmdWriteAccelerationStructuresPropertiesKHR");
  load(rt.cmd_copy_acceleration_structure, "vkCmdCopyAccelerationStructureKHR");
  load(rt.get_ray_tracing_shader_group_stack_size, "vkGetRayTracingShaderGroupStackSizeKHR");
  load(rt.cmd_set_ray_tracing_pipeline_stack_size, "vkCmdSetRayTracingPipelineStackSizeKHR");
  return rt;
}

}  // namespace proceduray::vk::detail

namespace proceduray::vk {

PROCEDURAY_DECL ContextState::ContextState(const ContextOptions& options)
    : m_preference(detail::preference_from_environment(options.device)),  // a bad PROCEDURAY_DEVICE throws first
      m_log(options.print_validation),
      m_vulkan(options.application_name, options.validation ? &m_log : nullptr) {
  try {
    m_physical = select_device(m_vulkan.get(), m_preference);
    read_properties();
    if (options.max_ray_recursion_depth > 0) {
      m_rt_properties.maxRayRecursionDepth = std::min(m_rt_properties.maxRayRecursionDepth, options.max_ray_recursion_depth);
    }
    create_device();
  } catch (...) {
    release();  // the destructor does not run for a constructor that threw (the members' do)
    throw;
  }
}

PROCEDURAY_DECL ContextState::~ContextState() { release(); }

PROCEDURAY_DECL void ContextState::release() noexcept {
  if (m_device != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(m_device);
    if (m_submit_fence != VK_NULL_HANDLE) vkDestroyFence(m_device, m_submit_fence, nullptr);
    if (m_pool != VK_NULL_HANDLE) vkDestroyCommandPool(m_device, m_pool, nullptr);
    vkDestroyDevice(m_device, nullptr);
    m_device = VK_NULL_HANDLE;
  }
}

PROCEDURAY_DECL void ContextState::read_properties() {
  vkGetPhysicalDeviceProperties(m_physical, &m_properties);
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

PROCEDURAY_DECL void ContextState::create_device() {
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
  std::vector<const char*> extensions(std::begin(detail::required_device_extensions),
                                      std::end(detail::required_device_extensions));
  // Optional: with pipeline libraries a pipeline may be told the largest payload and hit
  // attributes its stages use (the plan's sizes, PipelineDesc::max_payload_size).
  std::uint32_t offered_count = 0;
  vkEnumerateDeviceExtensionProperties(m_physical, nullptr, &offered_count, nullptr);
  std::vector<VkExtensionProperties> offered(offered_count);
  vkEnumerateDeviceExtensionProperties(m_physical, nullptr, &offered_count, offered.data());
  for (const VkExtensionProperties& e : offered) {
    if (std::strcmp(e.extensionName, VK_KHR_PIPELINE_LIBRARY_EXTENSION_NAME) == 0) m_pipeline_library = true;
  }
  if (m_pipeline_library) extensions.push_back(VK_KHR_PIPELINE_LIBRARY_EXTENSION_NAME);
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  check(vkCreateDevice(m_physical, &info, nullptr, &m_device), "vkCreateDevice", m_name);
  vkGetDeviceQueue(m_device, m_queue_family, 0, &m_queue);

  auto pool = make<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
  pool.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT | VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool.queueFamilyIndex = m_queue_family;
  check(vkCreateCommandPool(m_device, &pool, nullptr, &m_pool), "vkCreateCommandPool");
  auto alloc = make<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
  alloc.commandPool = m_pool;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  check(vkAllocateCommandBuffers(m_device, &alloc, &m_submit_cmd), "vkAllocateCommandBuffers");
  auto fence = make<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
  check(vkCreateFence(m_device, &fence, nullptr, &m_submit_fence), "vkCreateFence");

  m_rt = detail::load_device_functions(m_device, m_name);
}

PROCEDURAY_DECL std::uint32_t ContextState::memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags flags) const {
  for (std::uint32_t i = 0; i < m_memory.memoryTypeCount; ++i) {
    if ((type_bits & (1u << i)) != 0 && (m_memory.memoryTypes[i].propertyFlags & flags) == flags) return i;
  }
  throw VulkanError(VK_ERROR_OUT_OF_DEVICE_MEMORY, "vkAllocateMemory",
                    "Context::memory_type: device " + m_name + " has no memory type with property flags " +
                        std::to_string(flags) + " for type bits " + std::to_string(type_bits));
}

PROCEDURAY_DECL void ContextState::submit(const std::function<void(VkCommandBuffer)>& record) const {
  if (m_submitting) {  // a submit from inside another's recording: its own command buffer and fence
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
    auto fence_info = make<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
    VkFence raw_fence = VK_NULL_HANDLE;
    check(vkCreateFence(m_device, &fence_info, nullptr, &raw_fence), "vkCreateFence");
    auto fence = own(m_device, raw_fence, vkDestroyFence);
    submit_and_wait(cmd, raw_fence, record);
    return;
  }
  m_submitting = true;
  struct Done {
    bool& flag;
    ~Done() { flag = false; }
  } done{m_submitting};
  check(vkResetCommandBuffer(m_submit_cmd, 0), "vkResetCommandBuffer");
  submit_and_wait(m_submit_cmd, m_submit_fence, record);
}

PROCEDURAY_DECL void ContextState::submit_and_wait(VkCommandBuffer cmd, VkFence fence,
                                              const std::function<void(VkCommandBuffer)>& record) const {
  auto begin = make<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
  record(cmd);
  check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
  auto submit = make<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  check(vkResetFences(m_device, 1, &fence), "vkResetFences");
  check(vkQueueSubmit(m_queue, 1, &submit, fence), "vkQueueSubmit");
  m_submits.fetch_add(1, std::memory_order_relaxed);
  check(vkWaitForFences(m_device, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
