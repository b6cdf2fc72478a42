// SPIR-V kept on disk, so a second start skips glslang (0.1-0.45 s a scene), and where the
// library keeps its caches.
//
//   proceduray::vk::SpirvCache cache(proceduray::vk::default_cache_dir() / "spirv");
//   std::vector<std::uint32_t> spirv = cache.compile(source);   // from disk when nothing changed
//   cache.hits();                                               // stages served from disk so far
//
// An entry is keyed by everything the SPIR-V depends on: the source text, its name, the stage,
// the preamble (generated and extra declarations, defines), the include folders, the library's
// and glslang's versions; it also lists every file #included with a hash of its text, checked
// on every hit, so editing an included file recompiles. A file that is corrupt, truncated or not
// an entry is ignored with a warning and rewritten. A folder that cannot be written leaves the
// cache off with one warning: shaders are compiled as if there were none.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/version.hpp>
#include <proceduray/vk/shader_compiler.hpp>

#include <atomic>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace proceduray::vk {

/// Where the library keeps its caches: $XDG_CACHE_HOME/proceduray, else $HOME/.cache/proceduray;
/// empty when neither variable is set (no cache).
PROCEDURAY_DECL std::filesystem::path default_cache_dir();

/// FNV-1a, continued from `h`: cheap and enough to key and check entries.
PROCEDURAY_DECL std::uint64_t fnv1a(std::string_view bytes, std::uint64_t h = 1469598103934665603ull);

/// SPIR-V entries in one folder.
class SpirvCache {
 public:
  /// `dir` empty: off (compile() always compiles).
  explicit SpirvCache(std::filesystem::path dir) : m_dir(std::move(dir)) {}

  /// The shader's SPIR-V: from its entry when every input is unchanged, else compiled and stored.
  std::vector<std::uint32_t> compile(const ShaderSource& source);
  /// Stages served from disk / compiled so far.
  std::uint32_t hits() const noexcept { return m_hits; }
  std::uint32_t misses() const noexcept { return m_misses; }
  /// What went wrong with the folder or its files (also printed to stderr); empty when nothing did.
  const std::vector<std::string>& warnings() const noexcept { return m_warnings; }
  /// The entry file of a source (whether or not it exists).
  std::filesystem::path entry(const ShaderSource& source) const;

  static constexpr char magic[8] = {'P', 'R', 'Y', 'S', 'P', 'V', '0', '1'};

 private:
  static std::uint64_t key(const ShaderSource& source);
  bool load(const std::filesystem::path& file, std::uint64_t key, std::vector<std::uint32_t>& spirv);
  void store(const std::filesystem::path& file, std::uint64_t key, const std::vector<IncludedFile>& included,
             const std::vector<std::uint32_t>& spirv);
  void warn(std::string message) {
    std::fprintf(stderr, "proceduray: warning: %s\n", message.c_str());
    m_warnings.push_back(std::move(message));
  }

  std::filesystem::path m_dir;
  bool m_unwritable = false;
  std::uint32_t m_hits = 0, m_misses = 0;
  std::vector<std::string> m_warnings;
};

// ---------------------------------------------------------------------------------------------

namespace detail {
/// Reads a little-endian-as-written value at `at`, advancing it; false past the end.
template <class T>
bool take(const std::vector<char>& bytes, std::size_t& at, T& out) {
  if (at > bytes.size() || bytes.size() - at < sizeof(T)) return false;
  std::memcpy(&out, bytes.data() + at, sizeof(T));
  at += sizeof(T);
  return true;
}
}  // namespace detail

}  // namespace proceduray::vk

#include "proceduray/vk/spirv_cache-inl.hpp"  // the bodies (config.hpp)
