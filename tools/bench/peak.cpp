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
#include "compute.hpp"

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

struct Push {
  std::uint32_t iterations;
  float a;
  float b;
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
      bench::ComputeKernel c(ctx, spirv, {VkDeviceSize{threads} * sizeof(float)}, sizeof(Push), "bench_peak");
      c.run(groups, 1, &push);  // warm-up
      std::vector<double> ms;
      for (std::uint32_t r = 0; r < runs; ++r) ms.push_back(c.run(groups, 1, &push));
      std::sort(ms.begin(), ms.end());
      const double median = ms[ms.size() / 2];
      for (std::uint32_t id : {0u, 1u, 255u, threads - 1}) {
        const float want = expected(id, independent, push), got = static_cast<const float*>(c.buffer(0))[id];
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
