// What the compute-peer benchmarks (bench_instances, bench_paper_peer) share around their command
// lines: the size and device options, their shader folder and text, and the median they print.
//
//   unsigned w, h;
//   if (!bench::parse_size(size, "bench_instances", "512x512", w, h)) return 2;
//   pr::vk::Context ctx({.device = bench::device_preference(device), .validation = validation});
//   const std::string code = bench::read_text(bench::shader_dir() / "instances.comp", "bench_instances");
#pragma once

#include <proceduray/proceduray.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#ifndef PROCEDURAY_BENCH_SHADER_DIR
#define PROCEDURAY_BENCH_SHADER_DIR "tools/bench/shaders"
#endif

namespace bench {

/// Reads "WxH" with sides 1..8192 into w and h; else prints why, naming `tool` and an `example`, and returns false.
inline bool parse_size(const std::string& size, const char* tool, const char* example, unsigned& w, unsigned& h) {
  if (std::sscanf(size.c_str(), "%ux%u", &w, &h) == 2 && w > 0 && h > 0 && w <= 8192 && h <= 8192) return true;
  std::fprintf(stderr, "%s: --size '%s' is not WxH with sides 1..8192, e.g. %s\n", tool, size.c_str(), example);
  return false;
}

/// --device cpu | gpu | auto as the context's preference.
inline proceduray::vk::DevicePreference device_preference(const std::string& device) {
  return device == "cpu"   ? proceduray::vk::DevicePreference::cpu
         : device == "gpu" ? proceduray::vk::DevicePreference::gpu
                           : proceduray::vk::DevicePreference::automatic;
}

/// The benchmarks' shaders: $PROCEDURAY_BENCH_SHADER_DIR, else the source tree's (a GPU run carries them).
inline std::filesystem::path shader_dir() {
  const char* env = std::getenv("PROCEDURAY_BENCH_SHADER_DIR");
  return env != nullptr && *env != '\0' ? env : PROCEDURAY_BENCH_SHADER_DIR;
}

/// A shader's text; throws naming `tool` and the variable that moves the folder.
inline std::string read_text(const std::filesystem::path& path, const char* tool) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(std::string(tool) + ": cannot read " + path.string() + "; set PROCEDURAY_BENCH_SHADER_DIR");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// True when the validation layer reported nothing; else prints the count and the first message,
/// naming `tool` (a message fails a benchmark's run).
inline bool validation_clean(const proceduray::vk::Context& ctx, const char* tool) {
  const std::vector<std::string> messages = ctx.validation_messages();
  if (messages.empty()) return true;
  std::fprintf(stderr, "%s: the validation layer reported %zu message(s), the first: %s\n", tool, messages.size(),
               messages.front().c_str());
  return false;
}

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace bench
