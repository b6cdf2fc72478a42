// The Vulkan instance, the chosen ray-tracing device, its queue and its ray-tracing functions.
//
//   proceduray::vk::Context ctx({.device = proceduray::vk::DevicePreference::automatic,
//                                .validation = true});
//   ctx.name();              // "NVIDIA H100 80GB HBM3" or "llvmpipe (LLVM 15.0.6, 256 bits)"
//   ctx.sbt_properties();    // handle size and alignments for layout_sbt
//   ctx.submit([&](VkCommandBuffer cmd) { ... });   // records, submits and waits
//   ctx.validation_messages();  // what the validation layer reported (tests assert it is empty)
//
// The device is chosen by select_device (device_selection.hpp: a GPU when one can ray trace, else
// lavapipe; PROCEDURAY_DEVICE=cpu|gpu|auto overrides automatic); the instance and the validation
// messenger are made by vulkan_instance.hpp.
// A Context is a shared handle: copies share one device, which lives until the last copy goes. A
// Renderer keeps a copy, so destroying the Context first (or resetting the pointer that held it)
// leaves the renderer working; the device goes with the last of them.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/scene/device_limits.hpp>
#include <proceduray/scene/sbt_layout.hpp>
#include <proceduray/vk/device_selection.hpp>
#include <proceduray/vk/error.hpp>
#include <proceduray/vk/handle.hpp>
#include <proceduray/vk/structs.hpp>
#include <proceduray/vk/vulkan_instance.hpp>

#include <vulkan/vulkan.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <cstring>
#include <vector>

namespace proceduray::vk {

/// How a Context starts. Every member has a default that works on any supported machine.
struct ContextOptions {
  DevicePreference device = DevicePreference::automatic;  ///< default: automatic
  bool validation = false;  ///< enable VK_LAYER_KHRONOS_validation and collect its messages; default off
  bool print_validation = true;  ///< also print validation messages to stderr; default on
  /// > 0: report at most this maxRayRecursionDepth, as a device with that limit would (a test of
  /// portable scenes: Vulkan guarantees only 1); 0 (default): the device's own.
  std::uint32_t max_ray_recursion_depth = 0;
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

/// Instance, device, queue and command pool for one ray-tracing device: what a Context shares.
/// Neither copied nor moved: every object made from it keeps a pointer to it.
class ContextState {
 public:
  explicit ContextState(const ContextOptions& options = {});
  ContextState(const ContextState&) = delete;
  ContextState& operator=(const ContextState&) = delete;
  ~ContextState();

  VkInstance instance() const noexcept { return m_vulkan.get(); }
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
            m_max_geometry_count, m_max_instance_count, m_properties.limits.maxPushConstantsSize, name()};
  }
  /// Nanoseconds per timestamp tick; 0 when the queue cannot write timestamps.
  double timestamp_period_ns() const noexcept { return m_timestamp_period; }
  std::uint32_t queue_family() const noexcept { return m_queue_family; }
  VkCommandPool command_pool() const noexcept { return m_pool; }
  /// minAccelerationStructureScratchOffsetAlignment.
  std::uint32_t scratch_alignment() const noexcept { return m_scratch_alignment; }
  /// Whether VK_KHR_pipeline_library is enabled (when the device offers it): pipelines are then
  /// given the largest payload and hit attributes their stages use.
  bool pipeline_library() const noexcept { return m_pipeline_library; }
  /// Index of a memory type with all `flags` among `type_bits`; throws when there is none.
  std::uint32_t memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags flags) const;
  /// The same, preferring a type that also has `preferred` (host-cached readback memory, say).
  std::uint32_t memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags flags, VkMemoryPropertyFlags preferred) const {
    for (std::uint32_t i = 0; i < m_memory.memoryTypeCount; ++i) {
      const VkMemoryPropertyFlags has = m_memory.memoryTypes[i].propertyFlags;
      if ((type_bits & (1u << i)) != 0 && (has & (flags | preferred)) == (flags | preferred)) return i;
    }
    return memory_type(type_bits, flags);
  }
  /// The property flags of memory type `index`.
  VkMemoryPropertyFlags memory_flags(std::uint32_t index) const noexcept {
    return index < m_memory.memoryTypeCount ? m_memory.memoryTypes[index].propertyFlags : 0;
  }

  /// Records commands into a command buffer, submits it and waits for it. The command buffer and
  /// fence are made once and reused (creating a fence per call cost 0.3 ms on an H200).
  void submit(const std::function<void(VkCommandBuffer)>& record) const;
  /// How many times submit() has submitted (each a submit-and-wait): what a batch of builds saves.
  std::uint64_t submit_count() const noexcept { return m_submits.load(std::memory_order_relaxed); }

  /// Validation messages (warnings and errors) reported so far; empty when validation is off.
  std::vector<std::string> validation_messages() const { return m_log.messages(); }
  bool validation_enabled() const noexcept { return m_vulkan.validation_enabled(); }

 private:
  void release() noexcept;
  void submit_and_wait(VkCommandBuffer cmd, VkFence fence, const std::function<void(VkCommandBuffer)>& record) const;
  void read_properties();
  void create_device();

  // Declared in the order they are made: the log outlives the instance's messenger, and the
  // device (destroyed by release() in the destructor's body) goes before the instance.
  DevicePreference m_preference;
  ValidationLog m_log;
  VulkanInstance m_vulkan;
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
  bool m_pipeline_library = false;
  mutable std::atomic<std::uint64_t> m_submits{0};
  // submit()'s command buffer and fence, reused; a submit inside another's recording makes its own.
  VkCommandBuffer m_submit_cmd = VK_NULL_HANDLE;
  VkFence m_submit_fence = VK_NULL_HANDLE;
  mutable bool m_submitting = false;
};

/// The library's handle on one ray-tracing device (ContextState): cheap to copy, every copy the
/// same device. See ContextState for what each member returns.
class Context {
 public:
  explicit Context(const ContextOptions& options = {}) : m_state(std::make_shared<ContextState>(options)) {}

  VkInstance instance() const noexcept { return m_state->instance(); }
  VkPhysicalDevice physical_device() const noexcept { return m_state->physical_device(); }
  VkDevice device() const noexcept { return m_state->device(); }
  VkQueue queue() const noexcept { return m_state->queue(); }
  const DeviceFunctions& rt() const noexcept { return m_state->rt(); }
  const std::string& name() const noexcept { return m_state->name(); }
  bool is_cpu() const noexcept { return m_state->is_cpu(); }
  const VkPhysicalDeviceProperties& properties() const noexcept { return m_state->properties(); }
  const VkPhysicalDeviceRayTracingPipelinePropertiesKHR& ray_tracing_properties() const noexcept {
    return m_state->ray_tracing_properties();
  }
  SbtProperties sbt_properties() const noexcept { return m_state->sbt_properties(); }
  DeviceLimits limits() const { return m_state->limits(); }
  double timestamp_period_ns() const noexcept { return m_state->timestamp_period_ns(); }
  std::uint32_t queue_family() const noexcept { return m_state->queue_family(); }
  VkCommandPool command_pool() const noexcept { return m_state->command_pool(); }
  std::uint32_t scratch_alignment() const noexcept { return m_state->scratch_alignment(); }
  bool pipeline_library() const noexcept { return m_state->pipeline_library(); }
  std::uint32_t memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags flags) const {
    return m_state->memory_type(type_bits, flags);
  }
  std::uint32_t memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags flags, VkMemoryPropertyFlags preferred) const {
    return m_state->memory_type(type_bits, flags, preferred);
  }
  VkMemoryPropertyFlags memory_flags(std::uint32_t index) const noexcept { return m_state->memory_flags(index); }
  void submit(const std::function<void(VkCommandBuffer)>& record) const { m_state->submit(record); }
  std::uint64_t submit_count() const noexcept { return m_state->submit_count(); }
  std::vector<std::string> validation_messages() const { return m_state->validation_messages(); }
  bool validation_enabled() const noexcept { return m_state->validation_enabled(); }
  /// How many shares of this device there are now: the Context copies (a Renderer holds one) and
  /// the device objects made with own(ctx, ...), each of which keeps the device alive.
  long use_count() const noexcept { return m_state.use_count(); }
  /// A share of the device, for an object that must not outlive it (own(ctx, ...)).
  std::shared_ptr<const void> share() const noexcept { return m_state; }

 private:
  std::shared_ptr<ContextState> m_state;
};

/// Takes ownership of `handle`, made on ctx's device; the handle keeps the device alive until it
/// is destroyed, so a Buffer, Texture or pipeline may outlive every Context copy.
template <class Handle>
DeviceHandle<Handle> own(const Context& ctx, Handle handle, DestroyFn<Handle> destroy) {
  return own(ctx.device(), handle, destroy, ctx.share());
}

// ---------------------------------------------------------------------------------------------

namespace detail {

/// The ray-tracing entry points of `device`; throws NoRayTracingDevice naming one it lacks.
PROCEDURAY_DECL DeviceFunctions load_device_functions(VkDevice device, const std::string& name);

}  // namespace detail

}  // namespace proceduray::vk

#include "proceduray/vk/context-inl.hpp"  // the bodies (config.hpp)
