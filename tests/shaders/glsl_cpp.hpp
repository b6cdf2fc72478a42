// Compiles shared GLSL files (shaders/, written to shaders/common/compat.glsl's rules) as C++
// against GLM, so the tests run the very code the GPU runs, in float and, as a reference, in
// double.
//
//   #include "shaders/glsl_cpp.hpp"
//   namespace mine {                                 // float only, free functions
//   using namespace proceduray_glsl_cpp;
//   #include "primitives/julia.glsl"
//   }
//   float d = mine::julia_distance(glm::vec3(2.0f), c, 10u);
//
//   namespace mine2 {                                // float and double from one inclusion
//   using namespace proceduray_glsl_cpp;
//   template <class T> struct julia {
//     PROCEDURAY_GLSL_CPP_SCALAR(T)
//   #include "primitives/julia.glsl"
//   };
//   }
//   double d = mine2::julia<double>::julia_distance(glm::dvec3(2.0), glm::dvec4(c), 10u);
//
// Include each file once per test file (its include guard allows no more), inside a scope of
// its own: the GLSL has no namespaces, and a file that expects the includer to define a
// function (sphere_trace.glsl's march_distance) gets a different one in each test. Within a
// class template the includer may define that function as a static member, before or after.
// The class template must sit in a namespace that sees GLM's functions (`using namespace
// proceduray_glsl_cpp`): GLSL calls length(), max() ... unqualified.
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
