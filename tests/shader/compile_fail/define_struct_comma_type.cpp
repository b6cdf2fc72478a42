// A member type with a comma splits the (type, name) pair: the macro says so and names the fix.
// expect: static assertion failed: Weights: member (std::array<float, 4>, w) is not (type, name)
// expect: give a type with a comma an alias first
#include <proceduray/shader/define_struct.hpp>

#include <array>

PROCEDURAY_DEFINE_STRUCT(Weights, scalar, (float, a), (std::array<float, 4>, w));
