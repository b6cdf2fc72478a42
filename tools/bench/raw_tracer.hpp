// The raw-Vulkan reference of bench_frame_loop: the benchmark scene (one geometry of boxes, one
// instance, one hit group, one miss shader) traced with hand-written Vulkan, no library code in
// its setup of structures, descriptors, pipeline and shader table, nor in its frame loop. It takes
// the library's SPIR-V (so both sides run the same shaders) and the device (instance and queue).
//
//   RawTracer raw(device, physical, queue, family, spirv_by_stage, boxes, 2);  // 2 frames in flight
//   RawTracer::Ticket t = raw.submit(1024, 1024, true);   // trace (and copy) into a slot
//   raw.read(t, pixels);                                  // wait, copy rgba out
//   raw.gpu_ms(t);                                        // {trace, copy} GPU times
//
// Written the way a careful user writes it: everything made once, N command buffers and fences
// reused, host-cached readback memory, the image reached the general layout once.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace raw {

inline void ok(VkResult r, const char* what) {
  if (r != VK_SUCCESS) throw std::runtime_error(std::string("raw tracer: ") + what + " failed: " + std::to_string(r));
}

struct Box {
  float min[3], max[3];
};

/// One shader of the pipeline: its stage bit and SPIR-V.
struct Shader {
  VkShaderStageFlagBits stage;
  std::vector<std::uint32_t> spirv;
};

class RawTracer {
 public:
  struct Ticket {
    std::uint32_t slot;
    std::uint32_t width, height;
    bool readback;
  };

  RawTracer(VkDevice device, VkPhysicalDevice physical, VkQueue queue, std::uint32_t family,
            const std::array<Shader, 4>& shaders,  // raygen, miss, closest hit, intersection
            std::span<const Box> boxes, std::uint32_t frames_in_flight);
  RawTracer(const RawTracer&) = delete;
  RawTracer& operator=(const RawTracer&) = delete;
  ~RawTracer();

  /// Records and submits one frame into the next slot (waiting for that slot's last frame).
  Ticket submit(std::uint32_t width, std::uint32_t height, bool readback);
  /// Waits for the frame and copies its pixels out (readback frames).
  void read(const Ticket& t, std::span<std::uint8_t> out);
  /// Waits for the frame and views its pixels in the mapped readback memory (readback frames).
  std::span<const std::uint8_t> view(const Ticket& t) {
    Slot& s = m_slots[t.slot];
    wait(s);
    return {static_cast<const std::uint8_t*>(s.readback.mapped), std::size_t{t.width} * t.height * 4};
  }
  /// Waits for the frame; GPU ms of its trace and of its copy (0 without readback).
  std::pair<double, double> gpu_ms(const Ticket& t);
  void wait_idle() { vkQueueWaitIdle(m_queue); }

 private:
  struct Memory {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    void* mapped = nullptr;
    VkDeviceSize size = 0;
    bool coherent = true;
  };
  struct Slot {
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;
    bool pending = false;
    Memory readback;
  };
  std::uint32_t memory_type(std::uint32_t bits, VkMemoryPropertyFlags need, VkMemoryPropertyFlags prefer = 0) const;
  Memory buffer(VkDeviceSize size, VkBufferUsageFlags usage, VkMemoryPropertyFlags need, VkMemoryPropertyFlags prefer = 0);
  void destroy(Memory& m);
  VkDeviceAddress address(VkBuffer b) const;
  void one_time(const std::function<void(VkCommandBuffer)>& record);
  VkAccelerationStructureKHR build(const VkAccelerationStructureGeometryKHR& geometry, std::uint32_t count,
                                   VkAccelerationStructureTypeKHR type, Memory& storage);
  void make_image(std::uint32_t width, std::uint32_t height);
  void wait(Slot& s);

  VkDevice m_device;
  VkQueue m_queue;
  VkPhysicalDeviceMemoryProperties m_memory{};
  VkPhysicalDeviceRayTracingPipelinePropertiesKHR m_rt{};
  double m_period_ns = 1;
  PFN_vkCreateAccelerationStructureKHR m_create_as;
  PFN_vkDestroyAccelerationStructureKHR m_destroy_as;
  PFN_vkGetAccelerationStructureBuildSizesKHR m_sizes;
  PFN_vkGetAccelerationStructureDeviceAddressKHR m_as_address;
  PFN_vkCmdBuildAccelerationStructuresKHR m_cmd_build;
  PFN_vkCreateRayTracingPipelinesKHR m_create_pipelines;
  PFN_vkGetRayTracingShaderGroupHandlesKHR m_handles;
  PFN_vkCmdTraceRaysKHR m_trace;

  VkCommandPool m_pool = VK_NULL_HANDLE;
  Memory m_boxes, m_instances, m_blas_memory, m_tlas_memory, m_sbt;
  VkAccelerationStructureKHR m_blas = VK_NULL_HANDLE, m_tlas = VK_NULL_HANDLE;
  VkDescriptorSetLayout m_set_layout = VK_NULL_HANDLE;
  VkDescriptorPool m_descriptor_pool = VK_NULL_HANDLE;
  VkDescriptorSet m_set = VK_NULL_HANDLE;
  VkPipelineLayout m_layout = VK_NULL_HANDLE;
  VkPipeline m_pipeline = VK_NULL_HANDLE;
  VkStridedDeviceAddressRegionKHR m_regions[4]{};
  VkQueryPool m_queries = VK_NULL_HANDLE;
  VkImage m_image = VK_NULL_HANDLE;
  VkDeviceMemory m_image_memory = VK_NULL_HANDLE;
  VkImageView m_view = VK_NULL_HANDLE;
  std::uint32_t m_width = 0, m_height = 0;
  std::vector<Slot> m_slots;
  std::uint64_t m_next = 0;
};

// ---------------------------------------------------------------------------------------------

template <class T>
T chain(VkStructureType type, void* next = nullptr) {
  T t{};
  t.sType = type;
  t.pNext = next;
  return t;
}

inline std::uint32_t RawTracer::memory_type(std::uint32_t bits, VkMemoryPropertyFlags need,
                                            VkMemoryPropertyFlags prefer) const {
  for (int pass = 0; pass < 2; ++pass) {
    const VkMemoryPropertyFlags want = pass == 0 ? need | prefer : need;
    for (std::uint32_t i = 0; i < m_memory.memoryTypeCount; ++i) {
      if ((bits & (1u << i)) && (m_memory.memoryTypes[i].propertyFlags & want) == want) return i;
    }
  }
  throw std::runtime_error("raw tracer: no memory type");
}

inline RawTracer::Memory RawTracer::buffer(VkDeviceSize size, VkBufferUsageFlags usage, VkMemoryPropertyFlags need,
                                           VkMemoryPropertyFlags prefer) {
  Memory m;
  m.size = size;
  auto info = chain<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
  info.size = size;
  info.usage = usage;
  ok(vkCreateBuffer(m_device, &info, nullptr, &m.buffer), "vkCreateBuffer");
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(m_device, m.buffer, &req);
  auto flags = chain<VkMemoryAllocateFlagsInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO);
  flags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
  auto alloc = chain<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
                                           (usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT) ? &flags : nullptr);
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = memory_type(req.memoryTypeBits, need, prefer);
  m.coherent = (m_memory.memoryTypes[alloc.memoryTypeIndex].propertyFlags & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT) != 0;
  ok(vkAllocateMemory(m_device, &alloc, nullptr, &m.memory), "vkAllocateMemory");
  ok(vkBindBufferMemory(m_device, m.buffer, m.memory, 0), "vkBindBufferMemory");
  if (need & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) ok(vkMapMemory(m_device, m.memory, 0, VK_WHOLE_SIZE, 0, &m.mapped), "vkMapMemory");
  return m;
}

inline void RawTracer::destroy(Memory& m) {
  if (m.buffer) vkDestroyBuffer(m_device, m.buffer, nullptr);
  if (m.memory) vkFreeMemory(m_device, m.memory, nullptr);
  m = {};
}

inline VkDeviceAddress RawTracer::address(VkBuffer b) const {
  auto info = chain<VkBufferDeviceAddressInfo>(VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO);
  info.buffer = b;
  return vkGetBufferDeviceAddress(m_device, &info);
}

inline void RawTracer::one_time(const std::function<void(VkCommandBuffer)>& record) {
  auto alloc = chain<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
  alloc.commandPool = m_pool;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd;
  ok(vkAllocateCommandBuffers(m_device, &alloc, &cmd), "vkAllocateCommandBuffers");
  auto begin = chain<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
  vkBeginCommandBuffer(cmd, &begin);
  record(cmd);
  vkEndCommandBuffer(cmd);
  auto submit = chain<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  ok(vkQueueSubmit(m_queue, 1, &submit, VK_NULL_HANDLE), "vkQueueSubmit");
  vkQueueWaitIdle(m_queue);
  vkFreeCommandBuffers(m_device, m_pool, 1, &cmd);
}

inline VkAccelerationStructureKHR RawTracer::build(const VkAccelerationStructureGeometryKHR& geometry,
                                                   std::uint32_t count, VkAccelerationStructureTypeKHR type,
                                                   Memory& storage) {
  auto info = chain<VkAccelerationStructureBuildGeometryInfoKHR>(
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR);
  info.type = type;
  info.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;
  info.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
  info.geometryCount = 1;
  info.pGeometries = &geometry;
  auto sizes = chain<VkAccelerationStructureBuildSizesInfoKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR);
  m_sizes(m_device, VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &info, &count, &sizes);
  storage = buffer(sizes.accelerationStructureSize,
                   VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                   VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  auto create = chain<VkAccelerationStructureCreateInfoKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR);
  create.buffer = storage.buffer;
  create.size = sizes.accelerationStructureSize;
  create.type = type;
  VkAccelerationStructureKHR as;
  ok(m_create_as(m_device, &create, nullptr, &as), "vkCreateAccelerationStructureKHR");
  // Scratch padded by 256 so it can start aligned (minAccelerationStructureScratchOffsetAlignment <= 256 here).
  Memory scratch = buffer(sizes.buildScratchSize + 256,
                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                          VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  info.dstAccelerationStructure = as;
  info.scratchData.deviceAddress = (address(scratch.buffer) + 255) & ~VkDeviceAddress{255};
  VkAccelerationStructureBuildRangeInfoKHR range{count, 0, 0, 0};
  const VkAccelerationStructureBuildRangeInfoKHR* ranges = &range;
  one_time([&](VkCommandBuffer cmd) { m_cmd_build(cmd, 1, &info, &ranges); });
  destroy(scratch);
  return as;
}

inline RawTracer::RawTracer(VkDevice device, VkPhysicalDevice physical, VkQueue queue, std::uint32_t family,
                            const std::array<Shader, 4>& shaders, std::span<const Box> boxes,
                            std::uint32_t frames_in_flight)
    : m_device(device), m_queue(queue) {
  vkGetPhysicalDeviceMemoryProperties(physical, &m_memory);
  m_rt = chain<VkPhysicalDeviceRayTracingPipelinePropertiesKHR>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR);
  auto props = chain<VkPhysicalDeviceProperties2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &m_rt);
  vkGetPhysicalDeviceProperties2(physical, &props);
  m_period_ns = props.properties.limits.timestampPeriod;
  auto load = [&](auto& fn, const char* name) {
    fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(vkGetDeviceProcAddr(device, name));
    if (!fn) throw std::runtime_error(std::string("raw tracer: no ") + name);
  };
  load(m_create_as, "vkCreateAccelerationStructureKHR");
  load(m_destroy_as, "vkDestroyAccelerationStructureKHR");
  load(m_sizes, "vkGetAccelerationStructureBuildSizesKHR");
  load(m_as_address, "vkGetAccelerationStructureDeviceAddressKHR");
  load(m_cmd_build, "vkCmdBuildAccelerationStructuresKHR");
  load(m_create_pipelines, "vkCreateRayTracingPipelinesKHR");
  load(m_handles, "vkGetRayTracingShaderGroupHandlesKHR");
  load(m_trace, "vkCmdTraceRaysKHR");

  auto pool = chain<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
  pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool.queueFamilyIndex = family;
  ok(vkCreateCommandPool(device, &pool, nullptr, &m_pool), "vkCreateCommandPool");

  // Structures: the boxes' BLAS, one instance of it in the TLAS.
  const VkMemoryPropertyFlags host = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  const VkBufferUsageFlags input = VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
                                   VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
  m_boxes = buffer(boxes.size_bytes(), input, host);
  std::memcpy(m_boxes.mapped, boxes.data(), boxes.size_bytes());
  auto aabbs = chain<VkAccelerationStructureGeometryKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR);
  aabbs.geometryType = VK_GEOMETRY_TYPE_AABBS_KHR;
  aabbs.flags = VK_GEOMETRY_OPAQUE_BIT_KHR;
  aabbs.geometry.aabbs = chain<VkAccelerationStructureGeometryAabbsDataKHR>(
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_AABBS_DATA_KHR);
  aabbs.geometry.aabbs.data.deviceAddress = address(m_boxes.buffer);
  aabbs.geometry.aabbs.stride = sizeof(Box);
  m_blas = build(aabbs, static_cast<std::uint32_t>(boxes.size()), VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR,
                 m_blas_memory);
  VkAccelerationStructureInstanceKHR instance{};
  instance.transform.matrix[0][0] = instance.transform.matrix[1][1] = instance.transform.matrix[2][2] = 1.0f;
  instance.mask = 0xFF;
  auto where = chain<VkAccelerationStructureDeviceAddressInfoKHR>(
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR);
  where.accelerationStructure = m_blas;
  instance.accelerationStructureReference = m_as_address(device, &where);
  m_instances = buffer(sizeof instance, input, host);
  std::memcpy(m_instances.mapped, &instance, sizeof instance);
  auto instances = chain<VkAccelerationStructureGeometryKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR);
  instances.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
  instances.geometry.instances = chain<VkAccelerationStructureGeometryInstancesDataKHR>(
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR);
  instances.geometry.instances.data.deviceAddress = address(m_instances.buffer);
  m_tlas = build(instances, 1, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, m_tlas_memory);

  // Descriptors: set 0 = TLAS at binding 0, storage image at binding 1 (the library's layout).
  const VkShaderStageFlags all = VK_SHADER_STAGE_RAYGEN_BIT_KHR | VK_SHADER_STAGE_MISS_BIT_KHR |
                                 VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR | VK_SHADER_STAGE_INTERSECTION_BIT_KHR;
  const VkDescriptorSetLayoutBinding bindings[2] = {
      {0, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1, all, nullptr},
      {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, all, nullptr}};
  auto set_layout = chain<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
  set_layout.bindingCount = 2;
  set_layout.pBindings = bindings;
  ok(vkCreateDescriptorSetLayout(device, &set_layout, nullptr, &m_set_layout), "vkCreateDescriptorSetLayout");
  const VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1},
                                         {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1}};
  auto dpool = chain<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
  dpool.maxSets = 1;
  dpool.poolSizeCount = 2;
  dpool.pPoolSizes = sizes;
  ok(vkCreateDescriptorPool(device, &dpool, nullptr, &m_descriptor_pool), "vkCreateDescriptorPool");
  auto set_alloc = chain<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
  set_alloc.descriptorPool = m_descriptor_pool;
  set_alloc.descriptorSetCount = 1;
  set_alloc.pSetLayouts = &m_set_layout;
  ok(vkAllocateDescriptorSets(device, &set_alloc, &m_set), "vkAllocateDescriptorSets");
  auto as_write = chain<VkWriteDescriptorSetAccelerationStructureKHR>(
      VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR);
  as_write.accelerationStructureCount = 1;
  as_write.pAccelerationStructures = &m_tlas;
  auto write = chain<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, &as_write);
  write.dstSet = m_set;
  write.dstBinding = 0;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
  vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);

  // Pipeline: stages in the order given, groups raygen, miss, procedural hit.
  auto layout = chain<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
  layout.setLayoutCount = 1;
  layout.pSetLayouts = &m_set_layout;
  ok(vkCreatePipelineLayout(device, &layout, nullptr, &m_layout), "vkCreatePipelineLayout");
  std::vector<VkShaderModule> modules;
  std::vector<VkPipelineShaderStageCreateInfo> stages;
  for (const Shader& s : shaders) {
    auto module = chain<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
    module.codeSize = s.spirv.size() * 4;
    module.pCode = s.spirv.data();
    VkShaderModule m;
    ok(vkCreateShaderModule(device, &module, nullptr, &m), "vkCreateShaderModule");
    modules.push_back(m);
    auto stage = chain<VkPipelineShaderStageCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
    stage.stage = s.stage;
    stage.module = m;
    stage.pName = "main";
    stages.push_back(stage);
  }
  std::array<VkRayTracingShaderGroupCreateInfoKHR, 3> groups{};
  for (auto& g : groups) {
    g = chain<VkRayTracingShaderGroupCreateInfoKHR>(VK_STRUCTURE_TYPE_RAY_TRACING_SHADER_GROUP_CREATE_INFO_KHR);
    g.generalShader = g.closestHitShader = g.anyHitShader = g.intersectionShader = VK_SHADER_UNUSED_KHR;
  }
  groups[0].type = groups[1].type = VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR;
  groups[0].generalShader = 0;
  groups[1].generalShader = 1;
  groups[2].type = VK_RAY_TRACING_SHADER_GROUP_TYPE_PROCEDURAL_HIT_GROUP_KHR;
  groups[2].closestHitShader = 2;
  groups[2].intersectionShader = 3;
  auto pipeline = chain<VkRayTracingPipelineCreateInfoKHR>(VK_STRUCTURE_TYPE_RAY_TRACING_PIPELINE_CREATE_INFO_KHR);
  pipeline.stageCount = static_cast<std::uint32_t>(stages.size());
  pipeline.pStages = stages.data();
  pipeline.groupCount = 3;
  pipeline.pGroups = groups.data();
  pipeline.maxPipelineRayRecursionDepth = 1;
  pipeline.layout = m_layout;
  ok(m_create_pipelines(device, VK_NULL_HANDLE, VK_NULL_HANDLE, 1, &pipeline, nullptr, &m_pipeline),
     "vkCreateRayTracingPipelinesKHR");
  for (VkShaderModule m : modules) vkDestroyShaderModule(device, m, nullptr);

  // Shader table: one record per region, each region at a base-aligned offset.
  const std::uint32_t handle = m_rt.shaderGroupHandleSize;
  const std::uint32_t stride = (handle + m_rt.shaderGroupHandleAlignment - 1) & ~(m_rt.shaderGroupHandleAlignment - 1);
  const std::uint32_t region = (stride + m_rt.shaderGroupBaseAlignment - 1) & ~(m_rt.shaderGroupBaseAlignment - 1);
  std::vector<std::uint8_t> handles(3 * handle);
  ok(m_handles(device, m_pipeline, 0, 3, handles.size(), handles.data()), "vkGetRayTracingShaderGroupHandlesKHR");
  m_sbt = buffer(3 * region + m_rt.shaderGroupBaseAlignment,
                 VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT, host);
  const VkDeviceAddress base = address(m_sbt.buffer);
  const VkDeviceAddress start = (base + m_rt.shaderGroupBaseAlignment - 1) & ~VkDeviceAddress{m_rt.shaderGroupBaseAlignment - 1};
  for (std::uint32_t g = 0; g < 3; ++g) {
    std::memcpy(static_cast<std::uint8_t*>(m_sbt.mapped) + (start - base) + g * region, handles.data() + g * handle, handle);
  }
  m_regions[0] = {start, stride, stride};  // raygen: size == stride
  m_regions[1] = {start + region, stride, stride};
  m_regions[2] = {start + 2 * region, stride, stride};
  m_regions[3] = {0, 0, 0};

  // Frame slots and timestamps (three per slot: before the trace, after it, after the copy).
  auto queries = chain<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
  queries.queryType = VK_QUERY_TYPE_TIMESTAMP;
  queries.queryCount = 3 * frames_in_flight;
  ok(vkCreateQueryPool(device, &queries, nullptr, &m_queries), "vkCreateQueryPool");
  m_slots.resize(frames_in_flight);
  for (Slot& s : m_slots) {
    auto alloc = chain<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
    alloc.commandPool = m_pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    ok(vkAllocateCommandBuffers(device, &alloc, &s.cmd), "vkAllocateCommandBuffers");
    auto fence = chain<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
    ok(vkCreateFence(device, &fence, nullptr, &s.fence), "vkCreateFence");
  }
}

inline void RawTracer::make_image(std::uint32_t width, std::uint32_t height) {
  vkQueueWaitIdle(m_queue);
  if (m_view) vkDestroyImageView(m_device, m_view, nullptr);
  if (m_image) vkDestroyImage(m_device, m_image, nullptr);
  if (m_image_memory) vkFreeMemory(m_device, m_image_memory, nullptr);
  auto info = chain<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = VK_FORMAT_R8G8B8A8_UNORM;
  info.extent = {width, height, 1};
  info.mipLevels = info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  ok(vkCreateImage(m_device, &info, nullptr, &m_image), "vkCreateImage");
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(m_device, m_image, &req);
  auto alloc = chain<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  ok(vkAllocateMemory(m_device, &alloc, nullptr, &m_image_memory), "vkAllocateMemory");
  ok(vkBindImageMemory(m_device, m_image, m_image_memory, 0), "vkBindImageMemory");
  auto view = chain<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
  view.image = m_image;
  view.viewType = VK_IMAGE_VIEW_TYPE_2D;
  view.format = VK_FORMAT_R8G8B8A8_UNORM;
  view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  ok(vkCreateImageView(m_device, &view, nullptr, &m_view), "vkCreateImageView");
  one_time([&](VkCommandBuffer cmd) {
    auto barrier = chain<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
    barrier.dstAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    barrier.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    barrier.newLayout = VK_IMAGE_LAYOUT_GENERAL;
    barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = m_image;
    barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, 0, 0,
                         nullptr, 0, nullptr, 1, &barrier);
  });
  VkDescriptorImageInfo image{VK_NULL_HANDLE, m_view, VK_IMAGE_LAYOUT_GENERAL};
  auto write = chain<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
  write.dstSet = m_set;
  write.dstBinding = 1;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  write.pImageInfo = &image;
  vkUpdateDescriptorSets(m_device, 1, &write, 0, nullptr);
  m_width = width;
  m_height = height;
}

inline void RawTracer::wait(Slot& s) {
  if (!s.pending) return;
  ok(vkWaitForFences(m_device, 1, &s.fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
  s.pending = false;
  if (s.readback.mapped && !s.readback.coherent) {
    auto range = chain<VkMappedMemoryRange>(VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE);
    range.memory = s.readback.memory;
    range.size = VK_WHOLE_SIZE;
    vkInvalidateMappedMemoryRanges(m_device, 1, &range);
  }
}

inline RawTracer::Ticket RawTracer::submit(std::uint32_t width, std::uint32_t height, bool readback) {
  if (width != m_width || height != m_height) make_image(width, height);
  const std::uint32_t index = static_cast<std::uint32_t>(m_next++ % m_slots.size());
  Slot& s = m_slots[index];
  wait(s);
  const VkDeviceSize bytes = VkDeviceSize{width} * height * 4;
  if (readback && s.readback.size < bytes) {
    destroy(s.readback);
    s.readback = buffer(bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT,
                        VK_MEMORY_PROPERTY_HOST_CACHED_BIT);
  }
  vkResetCommandBuffer(s.cmd, 0);
  auto begin = chain<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vkBeginCommandBuffer(s.cmd, &begin);
  vkCmdResetQueryPool(s.cmd, m_queries, 3 * index, 3);
  // The frame before may still copy out of the image this frame writes.
  auto before = chain<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
  before.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  before.dstAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  vkCmdPipelineBarrier(s.cmd, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR | VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, 0, 1, &before, 0, nullptr, 0, nullptr);
  vkCmdBindPipeline(s.cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, m_pipeline);
  vkCmdBindDescriptorSets(s.cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, m_layout, 0, 1, &m_set, 0, nullptr);
  vkCmdWriteTimestamp(s.cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, m_queries, 3 * index);
  m_trace(s.cmd, &m_regions[0], &m_regions[1], &m_regions[2], &m_regions[3], width, height, 1);
  vkCmdWriteTimestamp(s.cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, m_queries, 3 * index + 1);
  if (readback) {
    auto barrier = chain<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    barrier.oldLayout = VK_IMAGE_LAYOUT_GENERAL;
    barrier.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = m_image;
    barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdPipelineBarrier(s.cmd, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0,
                         nullptr, 0, nullptr, 1, &barrier);
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {width, height, 1};
    vkCmdCopyImageToBuffer(s.cmd, m_image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, s.readback.buffer, 1, &copy);
    barrier.srcAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    barrier.dstAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    barrier.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    barrier.newLayout = VK_IMAGE_LAYOUT_GENERAL;
    vkCmdPipelineBarrier(s.cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, 0, 0,
                         nullptr, 0, nullptr, 1, &barrier);
    auto to_host = chain<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    to_host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(s.cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &to_host, 0, nullptr, 0,
                         nullptr);
  }
  vkCmdWriteTimestamp(s.cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, m_queries, 3 * index + 2);
  vkEndCommandBuffer(s.cmd);
  vkResetFences(m_device, 1, &s.fence);
  auto submit = chain<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &s.cmd;
  ok(vkQueueSubmit(m_queue, 1, &submit, s.fence), "vkQueueSubmit");
  s.pending = true;
  return {index, width, height, readback};
}

inline void RawTracer::read(const Ticket& t, std::span<std::uint8_t> out) {
  Slot& s = m_slots[t.slot];
  wait(s);
  std::memcpy(out.data(), s.readback.mapped, std::size_t{t.width} * t.height * 4);
}

inline std::pair<double, double> RawTracer::gpu_ms(const Ticket& t) {
  wait(m_slots[t.slot]);
  std::uint64_t stamps[3] = {};
  ok(vkGetQueryPoolResults(m_device, m_queries, 3 * t.slot, 3, sizeof stamps, stamps, 8,
                           VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
     "vkGetQueryPoolResults");
  return {static_cast<double>(stamps[1] - stamps[0]) * m_period_ns * 1e-6,
          static_cast<double>(stamps[2] - stamps[1]) * m_period_ns * 1e-6};
}

inline RawTracer::~RawTracer() {
  vkDeviceWaitIdle(m_device);
  for (Slot& s : m_slots) {
    vkDestroyFence(m_device, s.fence, nullptr);
    destroy(s.readback);
  }
  vkDestroyQueryPool(m_device, m_queries, nullptr);
  if (m_view) vkDestroyImageView(m_device, m_view, nullptr);
  if (m_image) vkDestroyImage(m_device, m_image, nullptr);
  if (m_image_memory) vkFreeMemory(m_device, m_image_memory, nullptr);
  vkDestroyPipeline(m_device, m_pipeline, nullptr);
  vkDestroyPipelineLayout(m_device, m_layout, nullptr);
  vkDestroyDescriptorPool(m_device, m_descriptor_pool, nullptr);
  vkDestroyDescriptorSetLayout(m_device, m_set_layout, nullptr);
  m_destroy_as(m_device, m_tlas, nullptr);
  m_destroy_as(m_device, m_blas, nullptr);
  destroy(m_sbt);
  destroy(m_tlas_memory);
  destroy(m_blas_memory);
  destroy(m_instances);
  destroy(m_boxes);
  vkDestroyCommandPool(m_device, m_pool, nullptr);
}

}  // namespace raw
