// GLSL written to shaders/common/compat.glsl's rules, compiled as C++ against GLM: the CPU runs
// the very code the GPU runs, in float and, as a reference, in double. The library's shader
// folder is on the include path (the proceduray target, Meson dependency and pkg-config file
// add it), so a C++ file includes a GLSL file with the line a shader uses.
//
//   namespace mine {
//   using namespace proceduray::glsl_cpp;
//   template <class T> struct sdf {                   // float and double from one inclusion
//     PROCEDURAY_GLSL_CPP_SCALAR(T)
//   #include "primitives/sdf.glsl"                    // pr_real sdf_sphere(pr_real3 p, pr_real r) ...
//   };
//   }
//   double d = mine::sdf<double>::sdf_sphere(glm::dvec3(0.5), 1.0);
//   float f = mine::sdf<float>::sdf_sphere(glm::vec3(0.5f), 1.0f);   // what the GPU computes
//
// At namespace scope, without the class template, a file compiles in float only, as free
// functions: `namespace mine { using namespace proceduray::glsl_cpp;`, the #include line, `}`.
//
// Rules for the GLSL (compat.glsl says why): scalars and vectors of the surface's precision are
// pr_real, pr_real2..4; literals PR(0.5); functions PROCEDURAY_INLINE, file constants
// PROCEDURAY_CONST, out parameters PROCEDURAY_OUT(T); no swizzles, no prototypes, no gl_*
// outside `#ifndef __cplusplus`. Include each guarded file once per translation unit, inside a
// scope of its own (GLSL has no namespaces): a header that includes one owns it for every file
// that includes the header (proceduray/march/glsl_mirror.hpp owns the library's primitives).
// marching/marcher.glsl has no guard: each inclusion generates one distance function's marcher.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>

namespace proceduray::glsl_cpp {
using namespace glm;
using uint = std::uint32_t;
/// The float binding of compat.glsl's types, for files included at namespace scope.
using pr_real = float;
using pr_real2 = glm::vec2;
using pr_real3 = glm::vec3;
using pr_real4 = glm::vec4;
}  // namespace proceduray::glsl_cpp

/// Binds compat.glsl's types to scalar T inside a class (template) that includes shared GLSL.
#define PROCEDURAY_GLSL_CPP_SCALAR(T) \
  using pr_real = T;                  \
  using pr_real2 = glm::vec<2, T>;    \
  using pr_real3 = glm::vec<3, T>;    \
  using pr_real4 = glm::vec<4, T>;
