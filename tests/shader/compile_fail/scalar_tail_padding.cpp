// Under scalar, GLSL puts the next member in this struct's 4 bytes of C++ tail padding.
// expect: static assertion failed: Tail: sizeof differs from the scalar struct size; list every member and add explicit trailing padding members
#include <proceduray/shader/field_list.hpp>

namespace demo {
struct Tail {
  double d;
  float f;
};
PROCEDURAY_STRUCT(Tail, scalar, d, f);
}  // namespace demo
