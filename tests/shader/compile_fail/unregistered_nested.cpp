// A nested struct must be registered before the struct that contains it.
// expect: static assertion failed: Outer::inner: the member's struct type is not registered; add PROCEDURAY_STRUCT for it before Outer
// expect-gcc: [with T = demo::Inner]
// expect-clang: (aka 'demo::Inner') does not satisfy 'RegisteredIfStruct'
#include <proceduray/shader/field_list.hpp>

namespace demo {
struct Inner {
  float x;
};
struct Outer {
  Inner inner;
  float y;
};
PROCEDURAY_STRUCT(Outer, scalar, inner, y);
}  // namespace demo
