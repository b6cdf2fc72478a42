// The body of a tiny build-time program that writes a ShaderInterface's GLSL declarations to a file,
// so shaders compiled ahead of time (glslangValidator, CMake or Meson) #include the same text that
// run-time compiles prepend.
//
//   // glsl_generator.cpp
//   #include "my_types.hpp"                                   // registers types, defines Interface
//   #include <proceduray/shader/glsl_generator_main.hpp>
//   int main(int argc, char** argv) { return proceduray::glsl_generator_main<my::Interface>(argc, argv); }
//
// and a build step that runs it:
//   CMake: include(ProcedurayGlsl)   # installed with the package; writes that program for you
//          proceduray_generate_glsl(my_glsl HEADER my_types.hpp INTERFACE my::Interface OUTPUT my_types.glsl)
//   Meson: gen = executable('gen', 'glsl_generator.cpp', dependencies: proceduray_dep)
//          custom_target('my_glsl', output: 'my_types.glsl', command: [gen, '@OUTPUT@'], build_by_default: true)
#pragma once

#include <proceduray/shader/glsl_codegen.hpp>

#include <exception>
#include <fstream>
#include <iostream>

namespace proceduray {

/// Writes glsl_declarations<Interface>() to the file argv[1]; returns 0, or 1 with a message on stderr.
template <class Interface>
int glsl_generator_main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "glsl_generator_main: expected one argument, the output .glsl path; got " << (argc - 1) << "\n";
    return 1;
  }
  try {
    const std::string text = glsl_declarations<Interface>();
    std::ofstream out(argv[1], std::ios::binary | std::ios::trunc);
    out << text;
    if (!out.good()) {
      std::cerr << "glsl_generator_main: cannot write " << argv[1] << "; check that its folder exists\n";
      return 1;
    }
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace proceduray
