// Compiles shared GLSL files (shaders/, written to shaders/common/compat.glsl's rules) as C++
// against GLM, so the tests run the very code the GPU runs.
//
//   #include "shaders/glsl_cpp.hpp"
//   namespace mine {
//   using namespace proceduray_glsl_cpp;
//   #include "primitives/julia.glsl"
//   }
//   float d = mine::julia_distance(glm::vec3(2.0f), c, 10u);
//
// Include each file inside a namespace of its own per test file: the GLSL has no namespaces,
// and a file that expects the includer to define a function (sphere_trace.glsl's
// march_distance) gets a different one in each test.
#pragma once

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>

namespace proceduray_glsl_cpp {
using namespace glm;
using uint = std::uint32_t;
}  // namespace proceduray_glsl_cpp
