// A scene's GLSL declarations as files, written at build time by a small program with no
// device (compile(scene) needs none): the text a Renderer gives each stage at run time, for
// shaders compiled ahead of time (glslangValidator) or read by an editor. The files are exactly
// Plan::declarations, one per pipeline stage.
//
//   proceduray::write_glsl_files(proceduray::compile(scene), "build/paper_glsl");   // one file per stage
//   proceduray::glsl_file_name(proceduray::ShaderStage::closest_hit, "shade.rchit");   // "shade.rchit.closest_hit.glsl"
//
// The generator is one line (examples/02_paper_scene/glsl/generate.cpp), built and run by
// proceduray_generate_scene_glsl() (cmake/ProcedurayGlsl.cmake) or a Meson custom_target:
//   int main(int argc, char** argv) { return proceduray::glsl_files_main(paper::PaperScene{}, argc, argv); }
// The same program answers "what can this shader use?": `generator --names closest_hit shade.rchit`
// prints glsl_summary of that stage's declarations (trace_<ray>, <callable>_call, payload, hit,
// arguments, the bindings and constants), and `generator --names` lists the stages.
#pragma once

#include <proceduray/config.hpp>

#include <string>
#include <string_view>
#include <vector>

#include "proceduray/error.hpp"
#include "proceduray/scene/compile.hpp"
#include "proceduray/scene/glsl_for.hpp"

namespace proceduray {

/// The file the declarations of `shader` as `stage` go to: "<shader>.<stage>.glsl", '/' made '_'.
PROCEDURAY_DECL std::string glsl_file_name(ShaderStage stage, std::string_view shader);

/// Writes one file per pipeline stage of `plan` into `dir` (made if missing) and returns their
/// names; throws EnvironmentError naming a file it cannot write. Folders are strings here (a
/// std::filesystem::path converts): the scene layer's declarations stay free of <filesystem>,
/// which costs a file that includes them 0.3 s.
PROCEDURAY_DECL std::vector<std::string> write_glsl_files(const Plan& plan, const std::string& dir);

/// The body of a build-time generator: compiles `scene` and writes its declarations into the
/// folder argv[1], then the list of files into argv[1]/files.txt and, when given, argv[2] (a file
/// a build system tracks as the output, e.g. Meson's custom_target). Returns 0, or 1 with a message.
namespace detail {
PROCEDURAY_DECL int glsl_files_main_core(const SceneCore& scene, int argc, char** argv);
}  // namespace detail
template <class Interface>
int glsl_files_main(const Scene<Interface>& scene, int argc, char** argv) {
  return detail::glsl_files_main_core(scene, argc, argv);
}

}  // namespace proceduray

#include "proceduray/scene/glsl_files-inl.hpp"  // the bodies (config.hpp)
