// The C++ mirror of the library's escape-time fractals (shaders/primitives/mandelbulb.glsl and
// julia.glsl, whose knobs primitives.hpp describes): the functions the GPU runs, in float (what
// the shader computes) or double (a reference), pure, so a CPU reference runs them on every core.
//
//   double d = proceduray::glsl::mandelbulb<double>::mandelbulb_distance(glm::dvec3(0.5), 8u);
//   glm::vec4 c = proceduray::glsl::julia<float>::julia_animated_c(2.5f);    // at 2.5 s, as the paper scene's Julia field does
//   double j = proceduray::glsl::julia<double>::julia_distance(glm::dvec3(0.3), glm::dvec4(c), 10u);
//
// This header owns the two files for every translation unit that includes it (their include
// guards let each in once): a file that needs them includes this header, not the GLSL.
#pragma once

#include <proceduray/shader/glsl_cpp.hpp>

namespace proceduray::glsl {
using namespace proceduray::glsl_cpp;

/// The power-8 Mandelbulb: distance estimate and the report's animated iteration count.
template <class T>
struct mandelbulb {
  PROCEDURAY_GLSL_CPP_SCALAR(T)
#include "primitives/mandelbulb.glsl"
};

/// The quaternion Julia set: distance estimate, cut planes, the animated constant.
template <class T>
struct julia {
  PROCEDURAY_GLSL_CPP_SCALAR(T)
#include "primitives/julia.glsl"
};

}  // namespace proceduray::glsl
