// The bodies of proceduray/vk/pipeline_cache.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/pipeline_cache.hpp"

#if PROCEDURAY_BODIES
#include <fstream>
#include <iterator>
#include <unistd.h>
#include <cstdio>

namespace proceduray::vk {

PROCEDURAY_DECL std::string default_pipeline_cache_name(const Context& ctx) {
  const VkPhysicalDeviceProperties& p = ctx.properties();
  char name[96];
  int n = std::snprintf(name, sizeof name, "pipeline-%04x-%04x-", p.vendorID, p.deviceID);
  for (std::uint8_t b : p.pipelineCacheUUID) n += std::snprintf(name + n, sizeof name - static_cast<std::size_t>(n), "%02x", b);
  return std::string(name) + ".bin";
}

PROCEDURAY_DECL PipelineCache::PipelineCache(const Context& ctx, std::filesystem::path path)
    : m_ctx(&ctx), m_path(std::move(path)) {
  std::vector<std::uint8_t> data;
  if (!m_path.empty() && std::filesystem::exists(m_path)) {
    data = read_valid(m_warning);
    if (!m_warning.empty()) {
      std::fprintf(stderr, "proceduray: warning: pipeline cache '%s' ignored (%s); it will be rebuilt\n",
                   m_path.string().c_str(), m_warning.c_str());
    }
  }
  auto info = make<VkPipelineCacheCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO);
  info.initialDataSize = data.size();
  info.pInitialData = data.empty() ? nullptr : data.data();
  VkPipelineCache cache = VK_NULL_HANDLE;
  check(vkCreatePipelineCache(ctx.device(), &info, nullptr, &cache), "vkCreatePipelineCache");
  m_cache = own(ctx, cache, vkDestroyPipelineCache);
  m_loaded = !data.empty();
}

PROCEDURAY_DECL std::vector<std::uint8_t> PipelineCache::read_valid(std::string& why) const {
  std::ifstream in(m_path, std::ios::binary);
  const std::vector<std::uint8_t> file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  constexpr std::size_t head = magic.size() + 16;
  if (file.size() < head || std::memcmp(file.data(), magic.data(), magic.size()) != 0) {
    why = "not a proceduray pipeline cache";
    return {};
  }
  std::uint64_t size = 0, sum = 0;
  std::memcpy(&size, file.data() + magic.size(), 8);
  std::memcpy(&sum, file.data() + magic.size() + 8, 8);
  if (size != file.size() - head || checksum(file.data() + head, size) != sum) {
    why = "truncated or corrupt: its checksum does not match";
    return {};
  }
  std::vector<std::uint8_t> data(file.begin() + head, file.end());
  // The driver's own header (VkPipelineCacheHeaderVersionOne) must name this device.
  const VkPhysicalDeviceProperties& p = m_ctx->properties();
  std::uint32_t header[4] = {};
  if (data.size() < 32) {
    why = "its driver data is too short";
    return {};
  }
  std::memcpy(header, data.data(), sizeof header);
  if (header[1] != VK_PIPELINE_CACHE_HEADER_VERSION_ONE || header[2] != p.vendorID || header[3] != p.deviceID ||
      std::memcmp(data.data() + 16, p.pipelineCacheUUID, VK_UUID_SIZE) != 0) {
    why = "written by another device or driver than " + m_ctx->name();
    return {};
  }
  return data;
}

PROCEDURAY_DECL void PipelineCache::save() const {
  if (m_path.empty()) return;
  std::size_t size = 0;
  check(vkGetPipelineCacheData(m_ctx->device(), m_cache.get(), &size, nullptr), "vkGetPipelineCacheData");
  std::vector<std::uint8_t> data(size);
  check(vkGetPipelineCacheData(m_ctx->device(), m_cache.get(), &size, data.data()), "vkGetPipelineCacheData");
  data.resize(size);
  const std::uint64_t size64 = size, sum = checksum(data.data(), data.size());
  // Write beside it under this process's own name and rename: a run killed mid-write, or two runs
  // at once, leave a whole file, never half of one.
  const std::filesystem::path tmp = m_path.string() + "." + std::to_string(::getpid()) + ".tmp";
  std::error_code ec;
  if (m_path.has_parent_path()) std::filesystem::create_directories(m_path.parent_path(), ec);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out.write(magic.data(), magic.size());
    out.write(reinterpret_cast<const char*>(&size64), 8);
    out.write(reinterpret_cast<const char*>(&sum), 8);
    out.write(reinterpret_cast<const char*>(data.data()), static_cast<std::streamsize>(data.size()));
    if (!out) {
      std::filesystem::remove(tmp, ec);
      throw EnvironmentError("PipelineCache::save: cannot write '" + tmp.string() +
                             "'; choose a cache path in a writable folder");
    }
  }
  std::filesystem::rename(tmp, m_path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw EnvironmentError("PipelineCache::save: cannot replace '" + m_path.string() + "'; choose a cache path in a writable folder");
  }
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
