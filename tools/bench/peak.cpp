// Benchmark (not a test): the device's measured FP32 arithmetic peak, the ceiling every marching
// benchmark is read against. A compute shader (shaders/peak.comp) runs FMAs in 16 independent
// chains per thread (the peak) and in one dependent chain (the latency-bound rate); each is timed
// with GPU timestamps, several times, and the median reported. The sums are checked against the
// same recurrence on the host, so a dispatch that did not run (or was folded away) fails.
//
//   bench_peak [--device cpu|gpu|auto] [--groups N] [--iterations N] [--runs 7]
//
// Prints per variant: FLOP/s (2 per FMA), the threads, and the FMAs per thread. Exit status 1
// when a sum is wrong or the queue has no timestamps.
#include <proceduray/proceduray.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#ifndef PROCEDURAY_BENCH_SHADER_DIR
#define PROCEDURAY_BENCH_SHADER_DIR "tools/bench/shaders"
#endif

namespace pr = proceduray;

namespace {

void ok(VkResult r, const char* what) {
  if (r != VK_SUCCESS) throw std::runtime_error(std::string("bench_peak: ") + what + " failed (" + std::to_string(r) + ")");
}

struct Push {
  std::uint32_t iterations;
  float a;
  float b;
};

/// One compute pipeline over one storage buffer, with a timestamp pair around each dispatch.
class Compute {
 public:
  Compute(const pr::vk::Context& ctx, const std::vector<std::uint32_t>& spirv, std::uint32_t threads) : m_ctx(ctx) {
    const VkDevice d = ctx.device();
    VkBufferCreateInfo bi{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    bi.size = VkDeviceSize{threads} * sizeof(float);
    bi.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    ok(vkCreateBuffer(d, &bi, nullptr, &m_buffer), "vkCreateBuffer");
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(d, m_buffer, &req);
    VkPhysicalDeviceMemoryProperties mp;
    vkGetPhysicalDeviceMemoryProperties(ctx.physical_device(), &mp);
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
    if (ai.memoryTypeIndex == mp.memoryTypeCount) throw std::runtime_error("bench_peak: no host-visible memory");
    ok(vkAllocateMemory(d, &ai, nullptr, &m_memory), "vkAllocateMemory");
    ok(vkBindBufferMemory(d, m_buffer, m_memory, 0), "vkBindBufferMemory");
    ok(vkMapMemory(d, m_memory, 0, VK_WHOLE_SIZE, 0, &m_mapped), "vkMapMemory");

    VkDescriptorSetLayoutBinding b{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
    VkDescriptorSetLayoutCreateInfo li{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    li.bindingCount = 1;
    li.pBindings = &b;
    ok(vkCreateDescriptorSetLayout(d, &li, nullptr, &m_set_layout), "vkCreateDescriptorSetLayout");
    VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(Push)};
    VkPipelineLayoutCreateInfo pli{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    pli.setLayoutCount = 1;
    pli.pSetLayouts = &m_set_layout;
    pli.pushConstantRangeCount = 1;
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

    VkDescriptorPoolSize ps{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1};
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
    VkDescriptorBufferInfo dbi{m_buffer, 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = m_set;
    w.descriptorCount = 1;
    w.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    w.pBufferInfo = &dbi;
    vkUpdateDescriptorSets(d, 1, &w, 0, nullptr);

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
  Compute(const Compute&) = delete;
  Compute& operator=(const Compute&) = delete;
  ~Compute() {
    const VkDevice d = m_ctx.device();
    vkDeviceWaitIdle(d);
    vkDestroyQueryPool(d, m_queries, nullptr);
    vkDestroyCommandPool(d, m_commands, nullptr);
    vkDestroyDescriptorPool(d, m_pool, nullptr);
    vkDestroyPipeline(d, m_pipeline, nullptr);
    vkDestroyShaderModule(d, m_module, nullptr);
    vkDestroyPipelineLayout(d, m_layout, nullptr);
    vkDestroyDescriptorSetLayout(d, m_set_layout, nullptr);
    vkDestroyBuffer(d, m_buffer, nullptr);
    vkFreeMemory(d, m_memory, nullptr);
  }

  /// Runs `groups` groups of 256 threads once; the GPU milliseconds between its timestamps.
  double run(std::uint32_t groups, const Push& push) {
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    ok(vkBeginCommandBuffer(m_cmd, &begin), "vkBeginCommandBuffer");
    vkCmdResetQueryPool(m_cmd, m_queries, 0, 2);
    vkCmdBindPipeline(m_cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_pipeline);
    vkCmdBindDescriptorSets(m_cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_layout, 0, 1, &m_set, 0, nullptr);
    vkCmdPushConstants(m_cmd, m_layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(Push), &push);
    vkCmdWriteTimestamp(m_cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, m_queries, 0);
    vkCmdDispatch(m_cmd, groups, 1, 1);
    vkCmdWriteTimestamp(m_cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, m_queries, 1);
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
  const float* sums() const { return static_cast<const float*>(m_mapped); }

 private:
  const pr::vk::Context& m_ctx;
  VkBuffer m_buffer = VK_NULL_HANDLE;
  VkDeviceMemory m_memory = VK_NULL_HANDLE;
  void* m_mapped = nullptr;
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

/// What thread `id` must have summed: the shader's recurrence, in float with fused multiply-adds.
float expected(std::uint32_t id, bool independent, const Push& p) {
  const float seed = static_cast<float>(id & 255u) * (1.0f / 256.0f);
  const std::uint32_t fmas = 64 * p.iterations / (independent ? 16 : 1);
  float sum = 0.0f;
  for (int chain = 0; chain < (independent ? 16 : 1); ++chain) {
    float x = seed + static_cast<float>(chain);
    for (std::uint32_t i = 0; i < fmas; ++i) x = std::fma(x, p.a, p.b);
    sum += x;
  }
  return sum;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("bench_peak: cannot read " + path + "; set PROCEDURAY_BENCH_SHADER_DIR");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

int main(int argc, char** argv) {
  std::string device = "auto";
  std::uint32_t groups = 0, iterations = 0, runs = 7;
  CLI::App app{"The device's measured FP32 peak: FMAs in independent and dependent chains"};
  app.add_option("--device", device, "cpu (lavapipe), gpu or auto")->check(CLI::IsMember({"cpu", "gpu", "auto"}));
  app.add_option("--groups", groups, "groups of 256 threads (default: 8192 on a GPU, 32 on lavapipe)")
      ->check(CLI::Range(1u, 65535u));
  app.add_option("--iterations", iterations, "loop passes of 64 FMAs per thread (default: 2048 on a GPU, 256 on lavapipe)")
      ->check(CLI::Range(1u, 1u << 20));
  app.add_option("--runs", runs, "timed dispatches per variant (median)")->check(CLI::Range(1u, 1000u));
  CLI11_PARSE(app, argc, argv);
  try {
    const pr::vk::DevicePreference pref = device == "cpu"   ? pr::vk::DevicePreference::cpu
                                          : device == "gpu" ? pr::vk::DevicePreference::gpu
                                                            : pr::vk::DevicePreference::automatic;
    pr::vk::Context ctx({.device = pref});
    if (ctx.timestamp_period_ns() <= 0.0) throw std::runtime_error("bench_peak: the queue writes no timestamps");
    const bool cpu = ctx.name().find("llvmpipe") != std::string::npos;
    if (groups == 0) groups = cpu ? 32 : 8192;
    if (iterations == 0) iterations = cpu ? 256 : 2048;
    const char* env = std::getenv("PROCEDURAY_BENCH_SHADER_DIR");
    const std::string code = read_text(std::string(env && *env ? env : PROCEDURAY_BENCH_SHADER_DIR) + "/peak.comp");
    // x <- a x + b climbs toward 1000 by about b per FMA at first: every FMA shows in the sum.
    const Push push{iterations, 0.999999f, 1.0e-3f};
    const std::uint32_t threads = groups * 256;
    std::printf("device: %s\n", ctx.name().c_str());
    for (const bool independent : {true, false}) {
      const std::vector<std::uint32_t> spirv = pr::vk::compile_glsl(
          {.stage = pr::ShaderStage::compute, .name = "peak.comp", .code = code,
           .preamble = independent ? "#define INDEPENDENT 1\n" : "#define INDEPENDENT 0\n"});
      Compute c(ctx, spirv, threads);
      c.run(groups, push);  // warm-up
      std::vector<double> ms;
      for (std::uint32_t r = 0; r < runs; ++r) ms.push_back(c.run(groups, push));
      std::sort(ms.begin(), ms.end());
      const double median = ms[ms.size() / 2];
      for (std::uint32_t id : {0u, 1u, 255u, threads - 1}) {
        const float want = expected(id, independent, push), got = c.sums()[id];
        // 1%: an FMA may round once (fused) or twice, and the difference drifts over thousands;
        // a dispatch that skipped a tenth of its work is off by several percent.
        if (!(std::abs(got - want) <= 1e-2f * std::abs(want))) {
          std::fprintf(stderr, "bench_peak: thread %u summed %.9g, the recurrence gives %.9g: the dispatch did not do its work\n",
                       id, static_cast<double>(got), static_cast<double>(want));
          return 1;
        }
      }
      const double flops = 2.0 * 64.0 * iterations * threads;
      std::printf("%-12s FMAs (%2d chains per thread): %9.1f GFLOP/s  (median of %u: %.3f ms; %u threads x %u FMAs)\n",
                  independent ? "independent" : "dependent", independent ? 16 : 1, flops / (median * 1.0e6), runs, median,
                  threads, 64 * iterations);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
