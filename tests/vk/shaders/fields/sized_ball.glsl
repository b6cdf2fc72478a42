// The test's animated field: a ball whose radius is a parameter, read per frame from the scene's
// uniform (field_parameter). Exact; compiles as GLSL and as C++ (shader/glsl_cpp.hpp).
#include "common/compat.glsl"
PROCEDURAY_INLINE pr_real sized_ball_distance(pr_real3 p, pr_real radius) { return length(p) - radius; }
