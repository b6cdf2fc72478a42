// Where an example finds its files: its shaders, and the GLSL declarations the build wrote.
//
//   std::filesystem::path shaders = examples::examples_dir() / "02_paper_scene" / "shaders";
//   std::filesystem::path glsl = examples::generated_glsl_dir(PAPER_GLSL_DIR);
//
// Both can be overridden from the environment, so binaries carried to another machine (the GPU
// runs) find the files that travelled with them; installed tools find their prefix's.
#pragma once

#include <cstdlib>
#include <filesystem>

namespace examples {

/// Where an example's own files (shaders) are: $PROCEDURAY_EXAMPLES_DIR, else beside an installed
/// tool (<prefix>/share/proceduray/examples, what cmake --install puts there), else the source tree's.
inline std::filesystem::path examples_dir() {
  if (const char* env = std::getenv("PROCEDURAY_EXAMPLES_DIR"); env != nullptr && *env != '\0') return env;
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::filesystem::path installed = exe.parent_path() / ".." / "share" / "proceduray" / "examples";
  if (!ec && std::filesystem::exists(installed / "02_paper_scene" / "shaders", ec)) {
    return std::filesystem::weakly_canonical(installed, ec);
  }
#ifdef PROCEDURAY_EXAMPLES_DIR
  return PROCEDURAY_EXAMPLES_DIR;
#else
  return std::filesystem::current_path();
#endif
}

/// Where the build wrote a scene's GLSL declarations (`built`, a path compiled in); the
/// environment variable PROCEDURAY_GLSL_DIR overrides it, for binaries carried to another machine.
inline std::filesystem::path generated_glsl_dir(const char* built) {
  if (const char* env = std::getenv("PROCEDURAY_GLSL_DIR"); env != nullptr && *env != '\0') return env;
  return built;
}

}  // namespace examples
