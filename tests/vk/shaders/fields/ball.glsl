// The test's distance field: a unit ball, exact (compiles as GLSL and as C++: shader/glsl_cpp.hpp).
#include "common/compat.glsl"
PROCEDURAY_INLINE pr_real ball_distance(pr_real3 p) { return length(p) - PR(1.0); }
