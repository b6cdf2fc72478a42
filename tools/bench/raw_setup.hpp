// The one-time work of RawTracer (raw_tracer.hpp): buffers and memory, the acceleration
// structures, the descriptor set, the pipeline and the shader table, all by hand. Include
// raw_tracer.hpp, which includes this file.
#pragma once

#include "raw_tracer.hpp"

namespace raw {

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
  auto pool = chain<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
  pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool.queueFamilyIndex = family;
  ok(vkCreateCommandPool(device, &pool, nullptr, &m_pool), "vkCreateCommandPool");

  load_functions();
  build_structures(boxes);
  build_descriptors();
  build_pipeline(shaders);
  build_table();
  build_slots(frames_in_flight);
}

/// The ray-tracing and acceleration-structure entry points (no loader links them).
inline void RawTracer::load_functions() {
  auto load = [&](auto& fn, const char* name) {
    fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(vkGetDeviceProcAddr(m_device, name));
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
}

/// The boxes' BLAS, one instance of it in the TLAS.
inline void RawTracer::build_structures(std::span<const Box> boxes) {
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
  instance.accelerationStructureReference = m_as_address(m_device, &where);
  m_instances = buffer(sizeof instance, input, host);
  std::memcpy(m_instances.mapped, &instance, sizeof instance);
  auto instances = chain<VkAccelerationStructureGeometryKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR);
  instances.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
  instances.geometry.instances = chain<VkAccelerationStructureGeometryInstancesDataKHR>(
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR);
  instances.geometry.instances.data.deviceAddress = address(m_instances.buffer);
  m_tlas = build(instances, 1, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, m_tlas_memory);
}

/// Set 0 = TLAS at binding 0, storage image at binding 1 (the library's layout).
inline void RawTracer::build_descriptors() {
  const VkShaderStageFlags all = VK_SHADER_STAGE_RAYGEN_BIT_KHR | VK_SHADER_STAGE_MISS_BIT_KHR |
                                 VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR | VK_SHADER_STAGE_INTERSECTION_BIT_KHR;
  const VkDescriptorSetLayoutBinding bindings[2] = {
      {0, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1, all, nullptr},
      {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, all, nullptr}};
  auto set_layout = chain<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
  set_layout.bindingCount = 2;
  set_layout.pBindings = bindings;
  ok(vkCreateDescriptorSetLayout(m_device, &set_layout, nullptr, &m_set_layout), "vkCreateDescriptorSetLayout");
  const VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1},
                                         {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1}};
  auto dpool = chain<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
  dpool.maxSets = 1;
  dpool.poolSizeCount = 2;
  dpool.pPoolSizes = sizes;
  ok(vkCreateDescriptorPool(m_device, &dpool, nullptr, &m_descriptor_pool), "vkCreateDescriptorPool");
  auto set_alloc = chain<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
  set_alloc.descriptorPool = m_descriptor_pool;
  set_alloc.descriptorSetCount = 1;
  set_alloc.pSetLayouts = &m_set_layout;
  ok(vkAllocateDescriptorSets(m_device, &set_alloc, &m_set), "vkAllocateDescriptorSets");
  auto as_write = chain<VkWriteDescriptorSetAccelerationStructureKHR>(
      VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR);
  as_write.accelerationStructureCount = 1;
  as_write.pAccelerationStructures = &m_tlas;
  auto write = chain<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, &as_write);
  write.dstSet = m_set;
  write.dstBinding = 0;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
  vkUpdateDescriptorSets(m_device, 1, &write, 0, nullptr);
}

/// Stages in the order given, groups raygen, miss, procedural hit.
inline void RawTracer::build_pipeline(const std::array<Shader, 4>& shaders) {
  auto layout = chain<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
  layout.setLayoutCount = 1;
  layout.pSetLayouts = &m_set_layout;
  ok(vkCreatePipelineLayout(m_device, &layout, nullptr, &m_layout), "vkCreatePipelineLayout");
  std::vector<VkShaderModule> modules;
  std::vector<VkPipelineShaderStageCreateInfo> stages;
  for (const Shader& s : shaders) {
    auto module = chain<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
    module.codeSize = s.spirv.size() * 4;
    module.pCode = s.spirv.data();
    VkShaderModule m;
    ok(vkCreateShaderModule(m_device, &module, nullptr, &m), "vkCreateShaderModule");
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
  ok(m_create_pipelines(m_device, VK_NULL_HANDLE, VK_NULL_HANDLE, 1, &pipeline, nullptr, &m_pipeline),
     "vkCreateRayTracingPipelinesKHR");
  for (VkShaderModule m : modules) vkDestroyShaderModule(m_device, m, nullptr);
}

/// One record per region, each region at a base-aligned offset.
inline void RawTracer::build_table() {
  const VkMemoryPropertyFlags host = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  const std::uint32_t handle = m_rt.shaderGroupHandleSize;
  const std::uint32_t stride = (handle + m_rt.shaderGroupHandleAlignment - 1) & ~(m_rt.shaderGroupHandleAlignment - 1);
  const std::uint32_t region = (stride + m_rt.shaderGroupBaseAlignment - 1) & ~(m_rt.shaderGroupBaseAlignment - 1);
  std::vector<std::uint8_t> handles(3 * handle);
  ok(m_handles(m_device, m_pipeline, 0, 3, handles.size(), handles.data()), "vkGetRayTracingShaderGroupHandlesKHR");
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
}

/// Frame slots and timestamps (three per slot: before the trace, after it, after the copy).
inline void RawTracer::build_slots(std::uint32_t frames_in_flight) {
  auto queries = chain<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
  queries.queryType = VK_QUERY_TYPE_TIMESTAMP;
  queries.queryCount = 3 * frames_in_flight;
  ok(vkCreateQueryPool(m_device, &queries, nullptr, &m_queries), "vkCreateQueryPool");
  m_slots.resize(frames_in_flight);
  for (Slot& s : m_slots) {
    auto alloc = chain<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
    alloc.commandPool = m_pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    ok(vkAllocateCommandBuffers(m_device, &alloc, &s.cmd), "vkAllocateCommandBuffers");
    auto fence = chain<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
    ok(vkCreateFence(m_device, &fence, nullptr, &s.fence), "vkCreateFence");
  }
}

}  // namespace raw
