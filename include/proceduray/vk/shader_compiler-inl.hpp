// The bodies of proceduray/vk/shader_compiler.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/shader_compiler.hpp"

#if PROCEDURAY_BODIES
#include <fstream>
#include <sstream>
#include <mutex>
#include <cstdlib>
#include <algorithm>

// glslang is read only where the bodies are compiled.
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

namespace proceduray::vk {

namespace detail {

/// Resolves #include "x" against the includer's folder, then the include folders.
class Includer final : public glslang::TShader::Includer {
 public:
  Includer(std::vector<std::filesystem::path> dirs, std::vector<IncludedFile>* included)
      : m_dirs(std::move(dirs)), m_included(included) {}

  IncludeResult* includeLocal(const char* header, const char* includer, size_t) override {
    std::vector<std::filesystem::path> candidates;
    if (includer != nullptr && *includer != '\0') {
      candidates.push_back(std::filesystem::path(includer).parent_path() / header);
    }
    for (const auto& dir : m_dirs) candidates.push_back(dir / header);
    for (const auto& path : candidates) {
      std::error_code ec;
      if (!std::filesystem::is_regular_file(path, ec)) continue;
      auto* text = new std::string(read_text_file(path));
      if (m_included != nullptr) m_included->push_back({path, *text});
      return new IncludeResult(path.string(), text->data(), text->size(), text);
    }
    return nullptr;  // glslang reports "could not be found" with the line
  }
  IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override {
    return includeLocal(header, includer, depth);
  }
  void releaseInclude(IncludeResult* result) override {
    if (result == nullptr) return;
    delete static_cast<std::string*>(result->userData);
    delete result;
  }

 private:
  std::vector<std::filesystem::path> m_dirs;
  std::vector<IncludedFile>* m_included;
};

}  // namespace detail

PROCEDURAY_DECL bool traces_rays(std::span<const std::uint32_t> spirv) noexcept {
  bool found = false;
  detail::each_spirv_instruction(spirv, [&](std::uint32_t op, std::span<const std::uint32_t>) {
    found = op == detail::op_trace_ray;
    return !found;
  });
  return found;
}

PROCEDURAY_DECL TraceInfo trace_info(std::span<const std::uint32_t> spirv) {
  std::vector<std::pair<std::uint32_t, std::string>> names;  // (id, OpName)
  std::vector<std::uint32_t> payloads;                       // ids passed to OpTraceRayKHR
  TraceInfo out;
  const auto each = [&](std::uint32_t op, std::span<const std::uint32_t> words) {
    if (op == detail::op_name && words.size() >= 3) {
      std::string name;  // a nul-terminated UTF-8 literal, four bytes a word
      for (std::uint32_t w : words.subspan(2)) {
        for (int b = 0; b < 4 && ((w >> (8 * b)) & 0xFFu) != 0; ++b) {
          name += static_cast<char>((w >> (8 * b)) & 0xFFu);
        }
      }
      names.emplace_back(words[1], std::move(name));
    }
    if (op == detail::op_trace_ray && words.size() >= 12) payloads.push_back(words[11]);
    if (op == detail::op_execute_callable) out.calls = true;
    return true;
  };
  out.unnamed = !detail::each_spirv_instruction(spirv, each);
  for (std::uint32_t id : payloads) {
    const auto it = std::find_if(names.begin(), names.end(), [&](const auto& n) { return n.first == id; });
    if (it == names.end() || it->second.empty()) {
      out.unnamed = true;
    } else if (std::find(out.payloads.begin(), out.payloads.end(), it->second) == out.payloads.end()) {
      out.payloads.push_back(it->second);
    }
  }
  return out;
}

PROCEDURAY_DECL std::filesystem::path library_shader_dir() {
  if (const char* env = std::getenv("PROCEDURAY_SHADER_DIR"); env != nullptr && *env != '\0') return env;
#ifdef PROCEDURAY_SHADER_DIR
  return PROCEDURAY_SHADER_DIR;
#else
  return {};
#endif
}

PROCEDURAY_DECL std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw EnvironmentError("read_text_file: cannot open '" + path.string() + "'; check the path" +
                           (path.is_relative() ? " (relative to " + std::filesystem::current_path().string() + ")"
                                               : std::string()));
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace proceduray::vk

namespace proceduray::vk::detail {

PROCEDURAY_DECL EShLanguage glslang_stage(ShaderStage s) {
  switch (s) {
    case ShaderStage::raygen: return EShLangRayGen;
    case ShaderStage::miss: return EShLangMiss;
    case ShaderStage::closest_hit: return EShLangClosestHit;
    case ShaderStage::any_hit: return EShLangAnyHit;
    case ShaderStage::intersection: return EShLangIntersect;
    case ShaderStage::callable: return EShLangCallable;
    case ShaderStage::compute: return EShLangCompute;
  }
  return EShLangRayGen;
}

/// glslang needs one process-wide initialisation before any compile.
PROCEDURAY_DECL void ensure_glslang() {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
}

}  // namespace proceduray::vk::detail

namespace proceduray::vk {

PROCEDURAY_DECL std::vector<std::uint32_t> compile_glsl(const ShaderSource& source, std::vector<IncludedFile>* included) {
  detail::ensure_glslang();
  const EShLanguage stage = detail::glslang_stage(source.stage);
  glslang::TShader shader(stage);
  const char* text = source.code.c_str();
  const char* name = source.name.c_str();
  shader.setStringsWithLengthsAndNames(&text, nullptr, &name, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientVulkan, 460);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_4);
  shader.setEntryPoint("main");
  const std::string preamble = "#extension GL_GOOGLE_include_directive : require\n" + source.preamble;
  shader.setPreamble(preamble.c_str());

  std::vector<std::filesystem::path> dirs = source.include_dirs;
  if (auto lib = library_shader_dir(); !lib.empty()) dirs.push_back(lib);
  detail::Includer includer(dirs, included);
  const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
  if (!shader.parse(GetDefaultResources(), 460, false, messages, includer)) {
    std::string log = shader.getInfoLog();
    // glslang numbers the preamble as string -1: an error there is in generated (or extra)
    // declarations, not at that line of the user's file, which may not even have it.
    if (const std::size_t at = log.find("ERROR: -1:"); at != std::string::npos) {
      const int line = std::atoi(log.c_str() + at + 10);
      std::istringstream lines(preamble);
      std::string text;
      for (int i = 0; i < line && std::getline(lines, text); ++i) {
      }
      throw ShaderCompileError(source.name, log,
                               "the generated declarations, then the extra ones; its line " + std::to_string(line - 1) +
                                   ": `" + text + "`");
    }
    throw ShaderCompileError(source.name, log);
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) {
    std::string log = program.getInfoLog();
    throw ShaderCompileError(source.name, log);
  }
  std::vector<std::uint32_t> spirv;
  glslang::SpvOptions options;
  options.validate = false;
  glslang::GlslangToSpv(*program.getIntermediate(stage), spirv, &options);
  return spirv;
}

PROCEDURAY_DECL std::vector<std::uint32_t> compile_glsl_file(ShaderStage stage, const std::filesystem::path& path,
                                                             std::string preamble) {
  return compile_glsl({stage, path.string(), read_text_file(path), {}, std::move(preamble)});
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
