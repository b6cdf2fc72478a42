// `input` is a reserved GLSL word, so it cannot name the generated struct.
// expect: static assertion failed: input: the struct's name is a reserved GLSL word; rename the struct
#include <proceduray/shader/field_list.hpp>

namespace demo {
struct input {
  float x;
};
PROCEDURAY_STRUCT(input, scalar, x);
}  // namespace demo
