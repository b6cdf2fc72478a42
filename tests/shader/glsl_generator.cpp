// The tiny build-time generator Meson builds (CMake's proceduray_generate_glsl writes its own).
#include "test_types.hpp"

#include <proceduray/shader/glsl_generator_main.hpp>

int main(int argc, char** argv) { return proceduray::glsl_generator_main<shader_test::Interface>(argc, argv); }
