// A vec3 after a float is at offset 20 in C++ but 32 under std430.
// expect: static assertion failed: Bad::d: the C++ offset or inner layout differs from the std430 layout
#include <proceduray/shader/field_list.hpp>

namespace demo {
struct Bad {
  glm::vec3 a;
  float b;
  float c;
  glm::vec3 d;
};
PROCEDURAY_STRUCT(Bad, std430, a, b, c, d);
}  // namespace demo
