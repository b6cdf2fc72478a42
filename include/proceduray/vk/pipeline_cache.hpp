// A VkPipelineCache kept on disk, so a second run skips shader compilation.
//
//   proceduray::vk::PipelineCache cache(ctx, "proceduray.cache");   // loads it if valid
//   // ... create pipelines with cache.get() ...
//   cache.save();                                                    // writes it back
//
// The file is this library's own: a magic, the data size and an FNV-1a checksum, then the
// driver's cache data. A file that is corrupt, truncated, written by another device or
// driver, or not a cache at all is ignored with a warning (warning(), and stderr) and
// replaced on save(): never handed to the driver, so it can never crash it.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/vk/context.hpp>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace proceduray::vk {

/// The pipeline cache's file name for this device and driver: pipeline-<vendor>-<device>-<cache UUID>.bin.
PROCEDURAY_DECL std::string default_pipeline_cache_name(const Context& ctx);

/// A pipeline cache loaded from and saved to one file.
class PipelineCache {
 public:
  /// Opens the cache at `path` (empty: memory only). An unusable file is ignored with a warning.
  PipelineCache(const Context& ctx, std::filesystem::path path = {});

  VkPipelineCache get() const noexcept { return m_cache.get(); }
  /// True when valid data was read from the file.
  bool loaded() const noexcept { return m_loaded; }
  /// Why the file was ignored; empty when it was loaded or absent.
  const std::string& warning() const noexcept { return m_warning; }
  /// Writes the cache to its file (no-op without a path); throws EnvironmentError when it cannot.
  void save() const;

  /// What this library writes before the driver's data.
  static constexpr std::array<char, 8> magic{'P', 'R', 'Y', 'C', 'A', 'C', 'H', '1'};

  /// FNV-1a over the bytes: cheap, and enough to catch truncation and corruption.
  static std::uint64_t checksum(const std::uint8_t* data, std::size_t size) {
    std::uint64_t h = 1469598103934665603ull;
    for (std::size_t i = 0; i < size; ++i) h = (h ^ data[i]) * 1099511628211ull;
    return h;
  }

 private:
  std::vector<std::uint8_t> read_valid(std::string& why) const;

  const Context* m_ctx;
  std::filesystem::path m_path;
  DeviceHandle<VkPipelineCache> m_cache;
  bool m_loaded = false;
  std::string m_warning;
};

}  // namespace proceduray::vk

#include "proceduray/vk/pipeline_cache-inl.hpp"  // the bodies (config.hpp)
