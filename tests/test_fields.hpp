// The distance fields the field tests use, as the C++ their ground truth runs: the unit ball
// (tests/vk/shaders/fields/ball.glsl) and example 06's gyroid shell, each file compiled as C++
// (shader/glsl_cpp.hpp) in float or double.
//
//   double d = test_fields::ball_cpu(glm::dvec3(0.0, 0.0, 2.0));   // 1
//   double g = test_fields::gyroid<float>::gyroid_distance(glm::vec3(0.5f));
#pragma once

#include <proceduray/shader/glsl_cpp.hpp>

namespace test_fields {
using namespace proceduray::glsl_cpp;
template <class T>
struct ball {
  PROCEDURAY_GLSL_CPP_SCALAR(T)
#include "vk/shaders/fields/ball.glsl"
};
template <class T>
struct sized_ball {
  PROCEDURAY_GLSL_CPP_SCALAR(T)
#include "vk/shaders/fields/sized_ball.glsl"
};
template <class T>
struct gyroid {
  PROCEDURAY_GLSL_CPP_SCALAR(T)
#include "06_your_field/shaders/gyroid.glsl"
};

/// The fields in double: what FieldMeter and field_hit take.
inline double ball_cpu(glm::dvec3 p) { return ball<double>::ball_distance(p); }
inline double gyroid_cpu(glm::dvec3 p) { return gyroid<double>::gyroid_distance(p); }
}  // namespace test_fields
