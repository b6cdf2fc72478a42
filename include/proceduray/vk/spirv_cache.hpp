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

#if PROCEDURAY_BODIES

#include <glslang/build_info.h>
#include <fstream>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <unistd.h>

namespace proceduray::vk {

PROCEDURAY_DECL std::filesystem::path default_cache_dir() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg != '\0') {
    return std::filesystem::path(xdg) / "proceduray";
  }
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') {
    return std::filesystem::path(home) / ".cache" / "proceduray";
  }
  return {};
}

PROCEDURAY_DECL std::uint64_t fnv1a(std::string_view bytes, std::uint64_t h) {
  for (const char c : bytes) h = (h ^ static_cast<std::uint8_t>(c)) * 1099511628211ull;
  return h;
}

PROCEDURAY_DECL std::uint64_t SpirvCache::key(const ShaderSource& source) {
  std::uint64_t h = fnv1a(proceduray::version);
  h = fnv1a(GLSLANG_VERSION_FLAVOR, fnv1a(std::to_string(GLSLANG_VERSION_MAJOR) + "." +
                                              std::to_string(GLSLANG_VERSION_MINOR) + "." +
                                              std::to_string(GLSLANG_VERSION_PATCH), h));
  h = fnv1a(std::to_string(static_cast<std::uint32_t>(source.stage)), h);
  // Lengths between the parts: "ab" + "c" and "a" + "bc" must not key alike.
  for (std::string_view part : {std::string_view(source.name), std::string_view(source.code),
                                std::string_view(source.preamble)}) {
    h = fnv1a(part, fnv1a(std::to_string(part.size()) + ":", h));
  }
  for (const auto& dir : source.include_dirs) h = fnv1a(dir.string() + "\n", h);
  if (const auto lib = library_shader_dir(); !lib.empty()) h = fnv1a(lib.string(), h);
  return h;
}

PROCEDURAY_DECL std::filesystem::path SpirvCache::entry(const ShaderSource& source) const {
  char name[32];
  std::snprintf(name, sizeof name, "%016llx.spv", static_cast<unsigned long long>(key(source)));
  return m_dir / name;
}

PROCEDURAY_DECL std::vector<std::uint32_t> SpirvCache::compile(const ShaderSource& source) {
  if (m_dir.empty()) {
    ++m_misses;
    return compile_glsl(source);
  }
  const std::uint64_t k = key(source);
  const std::filesystem::path file = entry(source);
  std::vector<std::uint32_t> spirv;
  if (load(file, k, spirv)) {
    ++m_hits;
    return spirv;
  }
  ++m_misses;
  std::vector<IncludedFile> included;
  spirv = compile_glsl(source, &included);
  if (!m_unwritable) store(file, k, included, spirv);
  return spirv;
}

// Layout: magic, key, checksum of the rest, include count, per include (path length, path, text
// hash), word count, words.
PROCEDURAY_DECL bool SpirvCache::load(const std::filesystem::path& file, std::uint64_t k, std::vector<std::uint32_t>& spirv) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) return false;
  std::ifstream in(file, std::ios::binary);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto corrupt = [&](const char* why) {
    warn("SPIR-V cache entry '" + file.string() + "' ignored (" + why + "); the shader is compiled and the entry rewritten");
    return false;
  };
  std::size_t at = sizeof magic;
  std::uint64_t stored_key = 0, sum = 0;
  if (bytes.size() < sizeof magic || std::memcmp(bytes.data(), magic, sizeof magic) != 0) return corrupt("not an entry");
  if (!detail::take(bytes, at, stored_key) || !detail::take(bytes, at, sum)) return corrupt("truncated");
  if (sum != fnv1a(std::string_view(bytes.data() + at, bytes.size() - at))) return corrupt("its checksum does not match");
  if (stored_key != k) return corrupt("written for other inputs");
  std::uint32_t includes = 0;
  if (!detail::take(bytes, at, includes)) return corrupt("truncated");
  for (std::uint32_t i = 0; i < includes; ++i) {
    std::uint32_t length = 0;
    std::uint64_t hash = 0;
    if (!detail::take(bytes, at, length) || bytes.size() - at < length) return corrupt("truncated");
    const std::string path(bytes.data() + at, length);
    at += length;
    if (!detail::take(bytes, at, hash)) return corrupt("truncated");
    std::ifstream included(path, std::ios::binary);
    if (!included) return false;  // an included file went away: compile (and report it) again
    const std::string text((std::istreambuf_iterator<char>(included)), std::istreambuf_iterator<char>());
    if (fnv1a(text) != hash) return false;  // edited since: stale, not corrupt
  }
  std::uint32_t words = 0;
  if (!detail::take(bytes, at, words) || bytes.size() - at != std::size_t{words} * 4 || words == 0) {
    return corrupt("truncated");
  }
  spirv.resize(words);
  std::memcpy(spirv.data(), bytes.data() + at, std::size_t{words} * 4);
  return true;
}

PROCEDURAY_DECL void SpirvCache::store(const std::filesystem::path& file, std::uint64_t k,
                              const std::vector<IncludedFile>& included, const std::vector<std::uint32_t>& spirv) {
  std::string body;
  const auto put = [&](const auto& value) { body.append(reinterpret_cast<const char*>(&value), sizeof value); };
  put(static_cast<std::uint32_t>(included.size()));
  for (const IncludedFile& f : included) {
    const std::string path = f.path.string();
    put(static_cast<std::uint32_t>(path.size()));
    body += path;
    put(fnv1a(f.text));
  }
  put(static_cast<std::uint32_t>(spirv.size()));
  body.append(reinterpret_cast<const char*>(spirv.data()), spirv.size() * 4);
  // Beside it under a name of this process's own, then renamed: parallel runs never read half a file.
  static std::atomic<std::uint32_t> serial{0};
  const std::filesystem::path tmp =
      file.string() + "." + std::to_string(::getpid()) + "." + std::to_string(serial.fetch_add(1)) + ".tmp";
  std::error_code ec;
  std::filesystem::create_directories(m_dir, ec);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out.write(magic, sizeof magic);
    const std::uint64_t sum = fnv1a(body);
    out.write(reinterpret_cast<const char*>(&k), 8);
    out.write(reinterpret_cast<const char*>(&sum), 8);
    out.write(body.data(), static_cast<std::streamsize>(body.size()));
    if (!out) {
      m_unwritable = true;
      warn("SPIR-V cache folder '" + m_dir.string() + "' cannot be written" +
           (ec ? " (" + ec.message() + ")" : std::string()) +
           "; shaders are compiled at every start. Choose a writable folder (RendererOptions::cache_dir, "
           "XDG_CACHE_HOME) or turn the cache off (RendererOptions::cache = false)");
      std::filesystem::remove(tmp, ec);
      return;
    }
  }
  std::filesystem::rename(tmp, file, ec);
  if (ec) std::filesystem::remove(tmp, ec);
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
