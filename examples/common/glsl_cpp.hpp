// Compiles shared GLSL files (shaders/, written to shaders/common/compat.glsl's rules) as C++
// against GLM, so tests and example tools run the very code the GPU runs, in float and, as a
// reference, in double. Tests and examples have examples/ on their include path.
//
//   namespace mine {                                 // float and double from one inclusion
//   using namespace proceduray_glsl_cpp;
//   template <class T> struct julia {
//     PROCEDURAY_GLSL_CPP_SCALAR(T)
//     // #include "../../shaders/primitives/julia.glsl"   (path relative to the includer)
//     static real radius(real3 p) { return length(p); }  // what the .glsl file's functions look like
//   };
//   }
//   double r = mine::julia<double>::radius(glm::dvec3(2.0));   // julia<double>::julia_distance(...)
//
// At namespace scope, without the class template, a file compiles in float only, as free
// functions: `namespace mine { using namespace proceduray_glsl_cpp;`, the #include line, `}`,
// then mine::julia_distance(glm::vec3(2.0f), c, 10u).
//
// Include each file once per translation unit (its include guard allows no more), inside a
// scope of its own: the GLSL has no namespaces. marching/marcher.glsl has no guard: each
// inclusion generates one distance function's marcher (P_trace, P_normal, ...), in a class
// template as static members.
// The class template must sit in a namespace that sees GLM's functions (`using namespace
// proceduray_glsl_cpp`): GLSL calls length(), max() ... unqualified. A header that includes
// shared GLSL this way owns those files for every translation unit that includes it: others
// reuse its class templates (e.g. paper::glsl::bulb<float>) instead of including them again.
#pragma once

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>

namespace proceduray_glsl_cpp {
using namespace glm;
using uint = std::uint32_t;
/// The float binding of compat.glsl's types, for files included at namespace scope.
using real = float;
using real2 = glm::vec2;
using real3 = glm::vec3;
using real4 = glm::vec4;
}  // namespace proceduray_glsl_cpp

/// Binds compat.glsl's types to scalar T inside a class (template) that includes shared GLSL.
#define PROCEDURAY_GLSL_CPP_SCALAR(T) \
  using real = T;                     \
  using real2 = glm::vec<2, T>;       \
  using real3 = glm::vec<3, T>;       \
  using real4 = glm::vec<4, T>;
