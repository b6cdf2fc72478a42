// The bodies of proceduray/vk/spirv_cache.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/spirv_cache.hpp"

#if PROCEDURAY_BODIES
#include <glslang/build_info.h>
#include <spirv-tools/libspirv.h>
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

namespace detail {
/// Why SPIRV-Tools' parser refuses `words` as Vulkan 1.2 SPIR-V, or empty: what a cache entry
/// must pass before a driver sees it (a driver handed bad SPIR-V may crash rather than fail).
/// The parser checks the header, every instruction's opcode, length and operands against the
/// grammar, and every id against the bound: about 0.6 ms for a 100 KB stage. The full validator
/// (spirv-val) takes 40-60 ms for the same stage, more than a whole warm start may cost.
inline std::string spirv_problem(const std::vector<std::uint32_t>& words) {
  // The parser leaves ids past the header's bound to the validator: checked here, per operand.
  struct Ids {
    std::uint32_t bound = 0;
    std::string why;
  } ids;
  const auto header = [](void* user, spv_endianness_t, std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t bound,
                         std::uint32_t) -> spv_result_t {
    static_cast<Ids*>(user)->bound = bound;
    return SPV_SUCCESS;
  };
  const auto instruction = [](void* user, const spv_parsed_instruction_t* in) -> spv_result_t {
    Ids& ids = *static_cast<Ids*>(user);
    for (std::uint16_t i = 0; i < in->num_operands; ++i) {
      const spv_parsed_operand_t& op = in->operands[i];
      const bool id = op.type == SPV_OPERAND_TYPE_ID || op.type == SPV_OPERAND_TYPE_TYPE_ID ||
                      op.type == SPV_OPERAND_TYPE_RESULT_ID || op.type == SPV_OPERAND_TYPE_MEMORY_SEMANTICS_ID ||
                      op.type == SPV_OPERAND_TYPE_SCOPE_ID;
      if (id && in->words[op.offset] >= ids.bound) {
        ids.why = "id " + std::to_string(in->words[op.offset]) + " is not below the module's bound " +
                  std::to_string(ids.bound);
        return SPV_ERROR_INVALID_ID;
      }
    }
    return SPV_SUCCESS;
  };
  const spv_context context = spvContextCreate(SPV_ENV_VULKAN_1_2);
  spv_diagnostic diagnostic = nullptr;
  const spv_result_t result = spvBinaryParse(context, &ids, words.data(), words.size(), header, instruction, &diagnostic);
  std::string why = ids.why;
  if (result != SPV_SUCCESS && why.empty()) {
    why = diagnostic != nullptr && diagnostic->error != nullptr ? diagnostic->error : "the parser gave no reason";
    if (diagnostic != nullptr) why += " (word " + std::to_string(diagnostic->position.index) + ")";
  }
  spvDiagnosticDestroy(diagnostic);
  spvContextDestroy(context);
  return why;
}
}  // namespace detail

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
  const auto corrupt = [&](const std::string& why) {
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
  // The checksum catches damage on disk, not an entry written wrong with a right checksum.
  if (const std::string why = detail::spirv_problem(spirv); !why.empty()) {
    spirv.clear();
    return corrupt("its SPIR-V does not parse: " + why);
  }
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
