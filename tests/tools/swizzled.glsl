// A field outside the portable subset: a swizzle compiles as GLSL, not as C++ (glsl_cpp.hpp).
#include "common/compat.glsl"
PROCEDURAY_INLINE pr_real swizzled_distance(pr_real3 p) {
  return length(p.xy) - PR(1.0);
}
