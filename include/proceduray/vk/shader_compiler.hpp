// GLSL ray-tracing shaders compiled to SPIR-V at run time with the glslang library.
//
//   proceduray::vk::ShaderSource src{.stage = proceduray::vk::ShaderStage::intersection,
//                                    .name = "sphere.rint", .code = glsl_text};
//   std::vector<std::uint32_t> spirv = proceduray::vk::compile_glsl(src);
//
// `#include "primitives/sphere.glsl"` resolves against the including file's folder, then the
// include folders, then the library's shaders/ folder (PROCEDURAY_SHADER_DIR, at build time
// or in the environment). The target is Vulkan 1.2 / SPIR-V 1.4, which ray tracing needs.
// A failed compile throws ShaderCompileError with glslang's log, the shader's name, and the file
// (an #include resolved) and line of the first error.
//
//   proceduray::vk::traces_rays(spirv);   // true when the shader calls traceRayEXT (OpTraceRayKHR)
//   proceduray::vk::trace_info(spirv);    // the payload variables it traces with, whether it calls callables
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/error.hpp>
#include <proceduray/scene/shader_stage.hpp>

#include <cstdint>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace proceduray::vk {

using proceduray::ShaderStage;

/// One shader to compile: its stage, a name for messages (a file name), and its GLSL text.
struct ShaderSource {
  ShaderStage stage = ShaderStage::raygen;
  std::string name;                               ///< shown in errors; also the base for relative #includes
  std::string code;                               ///< GLSL starting with #version 460
  std::vector<std::filesystem::path> include_dirs;  ///< searched after the file's folder; default none
  std::string preamble;  ///< text inserted after #version (defines, generated declarations); default empty
};

/// A file an #include resolved to, and the text read from it (what a SPIR-V cache checks).
struct IncludedFile {
  std::filesystem::path path;
  std::string text;
};

/// A shader that did not compile: what() holds the shader, where the first error is (the file
/// an #include resolved to, and its line), glslang's message there, and glslang's whole log.
class ShaderCompileError : public UsageError {
 public:
  /// `preamble`: where in the preamble the error is, when it is there (line is then 0).
  /// `context`: who uses the shader (the renderer adds stage and scene entities), put first.
  /// `hint`: what the library knows about the cause (a generated name that does not exist), put after it.
  ShaderCompileError(std::string name, const std::string& log, std::string preamble = {}, std::string context = {},
                     std::string hint = {})
      : ShaderCompileError(std::move(name), log, std::move(preamble), std::move(context), std::move(hint), locate(log)) {}

  const std::string& name() const noexcept { return m_name; }
  /// The file the first error is in: the shader, or a file it #includes ("" when glslang named none).
  const std::string& file() const noexcept { return m_file; }
  /// Line of file() the first error is on; 0 when glslang named none, or it is in the preamble.
  int line() const noexcept { return m_line; }
  /// glslang's message for the first error, e.g. "'x' : undeclared identifier".
  const std::string& message() const noexcept { return m_message; }
  const std::string& log() const noexcept { return m_log; }
  const std::string& context() const noexcept { return m_context; }
  const std::string& hint() const noexcept { return m_hint; }
  /// The same error with `context` (and a hint, when there is one) in what().
  ShaderCompileError with_context(std::string context, std::string hint = {}) const {
    return ShaderCompileError(m_name, m_log, m_preamble, std::move(context), std::move(hint));
  }

 private:
  struct Where {
    std::string file, message;
    int line = 0;
  };
  /// The first "ERROR: file:line: message" of a log; glslang names the preamble "-1". Read by
  /// hand, at the first ":<digits>:" after "ERROR: ": <regex> costs every includer seconds.
  static Where locate(const std::string& log) {
    for (std::size_t at = log.find("ERROR: "); at != std::string::npos; at = log.find("ERROR: ", at + 1)) {
      const std::size_t begin = at + 7;
      const std::size_t eol = std::min(log.find('\n', begin), log.size());
      for (std::size_t colon = log.find(':', begin); colon < eol; colon = log.find(':', colon + 1)) {
        std::size_t digits = colon + 1;
        while (digits < eol && log[digits] >= '0' && log[digits] <= '9') ++digits;
        if (digits == colon + 1 || digits >= eol || log[digits] != ':') continue;
        Where w{log.substr(begin, colon - begin), {}, std::stoi(log.substr(colon + 1, digits - colon - 1))};
        std::size_t text = digits + 1;
        while (text < eol && log[text] == ' ') ++text;
        w.message = log.substr(text, eol - text);
        while (!w.message.empty() && w.message.back() == ' ') w.message.pop_back();
        if (w.file == "-1") w = {"", w.message, 0};
        return w;
      }
    }
    return {};
  }
  ShaderCompileError(std::string name, std::string log, std::string preamble, std::string context, std::string hint,
                     Where where)
      : UsageError(
            (context.empty() ? std::string("compile_glsl: shader '") + name + "'" : context) + " failed to compile" +
            (where.line > 0 ? (where.file == name ? " at line " : " at " + where.file + ":") + std::to_string(where.line)
                            : std::string()) +
            (preamble.empty() ? std::string() : " in its preamble (" + preamble + ")") +
            (where.message.empty() ? std::string() : ": " + where.message) + (hint.empty() ? "" : "\n" + hint) +
            "\nglslang's log:\n" + log),
        m_name(std::move(name)), m_file(std::move(where.file)), m_line(where.line), m_message(std::move(where.message)),
        m_log(std::move(log)), m_preamble(std::move(preamble)), m_context(std::move(context)), m_hint(std::move(hint)) {}

  std::string m_name, m_file;
  int m_line;
  std::string m_message, m_log, m_preamble, m_context, m_hint;
};

namespace detail {
/// Calls `f(opcode, instruction words)` for each instruction after the 5-word header until `f`
/// returns false; returns false when the module is truncated or malformed (a zero word count).
template <class F>
bool each_spirv_instruction(std::span<const std::uint32_t> spirv, F&& f) {
  constexpr std::size_t header_words = 5;  // magic, version, generator, bound, schema
  for (std::size_t at = header_words; at < spirv.size();) {
    const std::uint32_t word_count = spirv[at] >> 16;
    if (word_count == 0 || at + word_count > spirv.size()) return false;
    if (!f(spirv[at] & 0xFFFFu, spirv.subspan(at, word_count))) return true;
    at += word_count;
  }
  return true;
}
constexpr std::uint32_t op_name = 5, op_trace_ray = 4445, op_execute_callable = 4446;
}  // namespace detail

/// Whether a SPIR-V module calls traceRayEXT (an OpTraceRayKHR instruction, opcode 4445): a
/// non-raygen stage that does needs a pipeline recursion depth >= 2. executeCallableEXT
/// (OpExecuteCallableKHR, 4446) is not a trace. A truncated or malformed module gives false.
PROCEDURAY_DECL bool traces_rays(std::span<const std::uint32_t> spirv) noexcept;

/// What a SPIR-V module traces and calls, before the payloads are matched to rays.
struct TraceInfo {
  std::vector<std::string> payloads;  ///< debug names of the payload variables OpTraceRayKHR passes
  bool unnamed = false;               ///< a payload without a name (or a malformed module)
  bool calls = false;                 ///< calls executeCallableEXT (OpExecuteCallableKHR)
};

/// The payload variables a SPIR-V module's traceRayEXT calls pass, by their OpName. SPIR-V has no
/// Location on ray payloads (GLSL's location only picks the variable), so the name is what ties a
/// trace to a ray: glsl_for declares ray r's outgoing payload under the ray's id and the incoming
/// one as `payload` (scene_pipeline.hpp maps them).
PROCEDURAY_DECL TraceInfo trace_info(std::span<const std::uint32_t> spirv);

/// The library's GLSL folder: $PROCEDURAY_SHADER_DIR, else the one known at build time.
PROCEDURAY_DECL std::filesystem::path library_shader_dir();

/// Reads a text file; throws EnvironmentError naming the path when it cannot.
PROCEDURAY_DECL std::string read_text_file(const std::filesystem::path& path);

/// Compiles one shader to SPIR-V (entry point "main"); throws ShaderCompileError on failure.
/// `included`, when given, receives every file an #include read.
PROCEDURAY_DECL std::vector<std::uint32_t> compile_glsl(const ShaderSource& source, std::vector<IncludedFile>* included = nullptr);

/// Reads and compiles a GLSL file; its folder is searched first for #includes.
PROCEDURAY_DECL std::vector<std::uint32_t> compile_glsl_file(ShaderStage stage, const std::filesystem::path& path,
                                                             std::string preamble = {});

}  // namespace proceduray::vk

#include "proceduray/vk/shader_compiler-inl.hpp"  // the bodies (config.hpp)
