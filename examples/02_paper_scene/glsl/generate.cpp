// The paper scene's GLSL declarations, written at build time with no device: the build runs
// this with the output folder (proceduray_generate_scene_glsl in examples/CMakeLists.txt, a
// custom_target in examples/meson.build), and 02_paper_scene compiles its shaders with them.
#include "../paper_scene.hpp"

#include <proceduray/scene/glsl_files.hpp>

int main(int argc, char** argv) { return proceduray::glsl_files_main(paper::PaperScene{}, argc, argv); }
