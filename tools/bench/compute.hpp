// A compute pipeline for the benchmarks: one shader over host-visible storage buffers (set 0,
// bindings 0..n-1, mapped for the host to fill and read) and push constants, each dispatch timed
// with GPU timestamps. bench_peak's FMA chains and bench_instances' compute peer run on it.
//
//   bench::ComputeKernel k(ctx, spirv, {bytes_out, bytes_in}, sizeof(Push), "bench_instances");
//   std::memcpy(k.buffer(1), instances.data(), bytes_in);
//   double ms = k.run(groups_x, groups_y, &push);   // waits; the GPU time between the timestamps
//   const auto* out = static_cast<const std::uint32_t*>(k.buffer(0));
#pragma once

#include <proceduray/proceduray.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace bench {

class ComputeKernel {
 public:
  ComputeKernel(const proceduray::vk::Context& ctx, const std::vector<std::uint32_t>& spirv,
                const std::vector<VkDeviceSize>& buffer_bytes, std::uint32_t push_bytes, std::string program)
      : m_ctx(ctx), m_program(std::move(program)), m_push_bytes(push_bytes) {
    const VkDevice d = ctx.device();
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (std::size_t i = 0; i < buffer_bytes.size(); ++i) {
      m_buffers.push_back(make_buffer(buffer_bytes[i]));
      bindings.push_back({static_cast<std::uint32_t>(i), VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT,
                          nullptr});
    }
    VkDescriptorSetLayoutCreateInfo li{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    li.bindingCount = static_cast<std::uint32_t>(bindings.size());
    li.pBindings = bindings.data();
    ok(vkCreateDescriptorSetLayout(d, &li, nullptr, &m_set_layout), "vkCreateDescriptorSetLayout");
    VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, push_bytes};
    VkPipelineLayoutCreateInfo pli{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    pli.setLayoutCount = 1;
    pli.pSetLayouts = &m_set_layout;
    pli.pushConstantRangeCount = push_bytes > 0 ? 1 : 0;
    pli.pPushConstantRanges = &range;
    ok(vkCreatePipelineLayout(d, &pli, nullptr, &m_layout), "vkCreatePipelineLayout");
    VkShaderModuleCreateInfo mi{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    mi.codeSize = spirv.size() * sizeof(std::uint32_t);
    mi.pCode = spirv.data();
    ok(vkCreateShaderModule(d, &mi, nullptr, &m_module), "vkCreateShaderModule");
    VkComputePipelineCreateInfo ci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    ci.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_COMPUTE_BIT, m_module,
                "main", nullptr};
    ci.layout = m_layout;
    ok(vkCreateComputePipelines(d, VK_NULL_HANDLE, 1, &ci, nullptr, &m_pipeline), "vkCreateComputePipelines");

    VkDescriptorPoolSize ps{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, static_cast<std::uint32_t>(bindings.size())};
    VkDescriptorPoolCreateInfo dpi{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    dpi.maxSets = 1;
    dpi.poolSizeCount = 1;
    dpi.pPoolSizes = &ps;
    ok(vkCreateDescriptorPool(d, &dpi, nullptr, &m_pool), "vkCreateDescriptorPool");
    VkDescriptorSetAllocateInfo dai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    dai.descriptorPool = m_pool;
    dai.descriptorSetCount = 1;
    dai.pSetLayouts = &m_set_layout;
    ok(vkAllocateDescriptorSets(d, &dai, &m_set), "vkAllocateDescriptorSets");
    for (std::size_t i = 0; i < m_buffers.size(); ++i) {
      VkDescriptorBufferInfo dbi{m_buffers[i].buffer, 0, VK_WHOLE_SIZE};
      VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
      w.dstSet = m_set;
      w.dstBinding = static_cast<std::uint32_t>(i);
      w.descriptorCount = 1;
      w.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      w.pBufferInfo = &dbi;
      vkUpdateDescriptorSets(d, 1, &w, 0, nullptr);
    }

    VkCommandPoolCreateInfo cpi{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    cpi.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    cpi.queueFamilyIndex = ctx.queue_family();
    ok(vkCreateCommandPool(d, &cpi, nullptr, &m_commands), "vkCreateCommandPool");
    VkCommandBufferAllocateInfo cai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    cai.commandPool = m_commands;
    cai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    cai.commandBufferCount = 1;
    ok(vkAllocateCommandBuffers(d, &cai, &m_cmd), "vkAllocateCommandBuffers");
    VkQueryPoolCreateInfo qi{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    qi.queryType = VK_QUERY_TYPE_TIMESTAMP;
    qi.queryCount = 2;
    ok(vkCreateQueryPool(d, &qi, nullptr, &m_queries), "vkCreateQueryPool");
  }
  ComputeKernel(const ComputeKernel&) = delete;
  ComputeKernel& operator=(const ComputeKernel&) = delete;
  ~ComputeKernel() {
    const VkDevice d = m_ctx.device();
    vkDeviceWaitIdle(d);
    vkDestroyQueryPool(d, m_queries, nullptr);
    vkDestroyCommandPool(d, m_commands, nullptr);
    vkDestroyDescriptorPool(d, m_pool, nullptr);
    vkDestroyPipeline(d, m_pipeline, nullptr);
    vkDestroyShaderModule(d, m_module, nullptr);
    vkDestroyPipelineLayout(d, m_layout, nullptr);
    vkDestroyDescriptorSetLayout(d, m_set_layout, nullptr);
    for (const Buffer& b : m_buffers) {
      vkDestroyBuffer(d, b.buffer, nullptr);
      vkFreeMemory(d, b.memory, nullptr);
    }
  }

  /// Buffer i's mapped bytes (host-coherent).
  void* buffer(std::size_t i) const { return m_buffers.at(i).mapped; }

  /// Runs gx x gy groups once and waits; the GPU milliseconds between its timestamps.
  double run(std::uint32_t gx, std::uint32_t gy, const void* push) {
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    ok(vkBeginCommandBuffer(m_cmd, &begin), "vkBeginCommandBuffer");
    vkCmdResetQueryPool(m_cmd, m_queries, 0, 2);
    vkCmdBindPipeline(m_cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_pipeline);
    vkCmdBindDescriptorSets(m_cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_layout, 0, 1, &m_set, 0, nullptr);
    if (m_push_bytes > 0) vkCmdPushConstants(m_cmd, m_layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, m_push_bytes, push);
    vkCmdWriteTimestamp(m_cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, m_queries, 0);
    vkCmdDispatch(m_cmd, gx, gy, 1);
    vkCmdWriteTimestamp(m_cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, m_queries, 1);
    // The host reads the buffers after the wait: make the shader's writes visible to it.
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(m_cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0,
                         nullptr, 0, nullptr);
    ok(vkEndCommandBuffer(m_cmd), "vkEndCommandBuffer");
    VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    si.commandBufferCount = 1;
    si.pCommandBuffers = &m_cmd;
    ok(vkQueueSubmit(m_ctx.queue(), 1, &si, VK_NULL_HANDLE), "vkQueueSubmit");
    ok(vkQueueWaitIdle(m_ctx.queue()), "vkQueueWaitIdle");
    std::uint64_t t[2] = {};
    ok(vkGetQueryPoolResults(m_ctx.device(), m_queries, 0, 2, sizeof t, t, sizeof(std::uint64_t),
                             VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
       "vkGetQueryPoolResults");
    return static_cast<double>(t[1] - t[0]) * m_ctx.timestamp_period_ns() * 1.0e-6;
  }

 private:
  struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    void* mapped = nullptr;
  };

  void ok(VkResult r, const char* what) const {
    if (r != VK_SUCCESS) throw std::runtime_error(m_program + ": " + what + " failed (" + std::to_string(r) + ")");
  }

  Buffer make_buffer(VkDeviceSize bytes) {
    const VkDevice d = m_ctx.device();
    Buffer b;
    VkBufferCreateInfo bi{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    bi.size = bytes;
    bi.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    ok(vkCreateBuffer(d, &bi, nullptr, &b.buffer), "vkCreateBuffer");
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(d, b.buffer, &req);
    VkPhysicalDeviceMemoryProperties mp;
    vkGetPhysicalDeviceMemoryProperties(m_ctx.physical_device(), &mp);
    const VkMemoryPropertyFlags want = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    ai.allocationSize = req.size;
    ai.memoryTypeIndex = mp.memoryTypeCount;
    for (std::uint32_t i = 0; i < mp.memoryTypeCount; ++i) {
      if ((req.memoryTypeBits & (1u << i)) && (mp.memoryTypes[i].propertyFlags & want) == want) {
        ai.memoryTypeIndex = i;
        break;
      }
    }
    if (ai.memoryTypeIndex == mp.memoryTypeCount) {
      vkDestroyBuffer(d, b.buffer, nullptr);
      throw std::runtime_error(m_program + ": no host-visible memory");
    }
    ok(vkAllocateMemory(d, &ai, nullptr, &b.memory), "vkAllocateMemory");
    ok(vkBindBufferMemory(d, b.buffer, b.memory, 0), "vkBindBufferMemory");
    ok(vkMapMemory(d, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped), "vkMapMemory");
    return b;
  }

  const proceduray::vk::Context& m_ctx;
  std::string m_program;
  std::uint32_t m_push_bytes = 0;
  std::vector<Buffer> m_buffers;
  VkDescriptorSetLayout m_set_layout = VK_NULL_HANDLE;
  VkPipelineLayout m_layout = VK_NULL_HANDLE;
  VkShaderModule m_module = VK_NULL_HANDLE;
  VkPipeline m_pipeline = VK_NULL_HANDLE;
  VkDescriptorPool m_pool = VK_NULL_HANDLE;
  VkDescriptorSet m_set = VK_NULL_HANDLE;
  VkCommandPool m_commands = VK_NULL_HANDLE;
  VkCommandBuffer m_cmd = VK_NULL_HANDLE;
  VkQueryPool m_queries = VK_NULL_HANDLE;
};

}  // namespace bench
