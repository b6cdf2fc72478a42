// One source, two compilers: macros that let a distance function written in plain GLSL also
// compile as C++ against GLM, so a CPU reference runs the very same code.
//
//   #include "../common/compat.glsl"
//   PROCEDURAY_INLINE float f(vec3 p, PROCEDURAY_OUT(float) grad_len) { ... }
//
// Rules for shared files: float literals carry `f` (GLM's operators do not mix float and
// double), no swizzles (GLM's need anonymous unions, which -Wpedantic rejects), no GLSL-only
// built-ins (gl_*, floatBitsToInt), out/inout parameters through the macros below.
// In C++ the includer brings GLM into scope first (see tests/shaders/glsl_cpp.hpp):
//   namespace mine { using namespace proceduray_glsl_cpp;
//   #include "primitives/julia.glsl"
//   }
#ifndef PROCEDURAY_COMMON_COMPAT_GLSL
#define PROCEDURAY_COMMON_COMPAT_GLSL

#ifdef __cplusplus
#define PROCEDURAY_INLINE inline
#define PROCEDURAY_OUT(T) T&
#define PROCEDURAY_INOUT(T) T&
#else
#define PROCEDURAY_INLINE
#define PROCEDURAY_OUT(T) out T
#define PROCEDURAY_INOUT(T) inout T
#endif

#endif
