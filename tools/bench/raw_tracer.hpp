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
// Written the way a careful user writes it: everything made once (raw_setup.hpp), N command
// buffers and fences reused, host-cached readback memory, the image reached the general layout
// once (the frame loop, below).
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

template <class T>
T chain(VkStructureType type, void* next = nullptr) {
  T t{};
  t.sType = type;
  t.pNext = next;
  return t;
}

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
  void load_functions();
  void build_structures(std::span<const Box> boxes);
  void build_descriptors();
  void build_pipeline(const std::array<Shader, 4>& shaders);
  void build_table();
  void build_slots(std::uint32_t frames_in_flight);
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

// The frame loop.

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

#include "raw_setup.hpp"  // the one-time work
