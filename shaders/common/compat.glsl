// One source, two compilers, two precisions: macros that let a distance function written in
// plain GLSL also compile as C++ against GLM, in float and in double, so a CPU reference runs
// the very same code as the GPU, and a double-precision run of it measures the float error.
//
//   #include "../common/compat.glsl"
//   PROCEDURAY_CONST real bailout = R(16.0);
//   PROCEDURAY_INLINE real f(real3 p, PROCEDURAY_OUT(real) grad_len) { ... R(0.5) * length(p) ... }
//
// Rules for shared files:
//   - scalars and vectors of the surface's precision are `real`, `real2`, `real3`, `real4`;
//     in GLSL they are float, vec2, vec3, vec4 (macros below), so the SPIR-V is what plain
//     float code gives. int, uint and bool stay as they are.
//   - literals are R(1.0): the bare literal in GLSL (a float there), and in C++ exactly the
//     float literal `1.0f` in a float build (so the float build is bit for bit the old code)
//     or the double literal `1.0` in a double build (so the reference is not silently float).
//     Write R(...) with a decimal point and no sign: R(0.5), -R(2.0), R(1.0e-30).
//   - no swizzles (GLM's need anonymous unions, which -Wpedantic rejects), no GLSL-only
//     built-ins (gl_*, floatBitsToInt) outside `#ifndef __cplusplus`, out/inout parameters
//     through PROCEDURAY_OUT / PROCEDURAY_INOUT, functions PROCEDURAY_INLINE, file-scope
//     constants PROCEDURAY_CONST, and no prototypes in C++ (see below).
//
// In C++ the includer binds `real` (and real2..4, uint, GLM's names) and chooses the scope.
// examples/common/glsl_cpp.hpp gives both ways:
//   namespace mine { using namespace proceduray_glsl_cpp;       // float, as before
//   #include "primitives/julia.glsl"
//   }
//   template <class T> struct julia {                           // float and double from one
//     PROCEDURAY_GLSL_CPP_SCALAR(T)                             // inclusion: julia<double>::...
//   #include "primitives/julia.glsl"
//   };
// Why a class template and not one namespace per scalar: every file has an include guard, so
// a translation unit can include it once; inside a class template that one inclusion yields
// both precisions (julia<float>, julia<double>), and only what is called is instantiated. Hence
// in C++ functions are `static inline` (members, or internal-linkage functions in a namespace)
// and constants `static constexpr`. Shared files keep no state: a function gets what it reads
// as parameters (a marcher its distance's field, marching/marcher.glsl), so they run on every core.
// R is a function-like macro in C++ too: `#undef R` after the last GLSL inclusion if later
// headers use the name (GLM's _vectorize.hpp does, and is included by glm/glm.hpp first).
#ifndef PROCEDURAY_COMMON_COMPAT_GLSL
#define PROCEDURAY_COMMON_COMPAT_GLSL

#ifdef __cplusplus
#define PROCEDURAY_INLINE static inline
#define PROCEDURAY_CONST static constexpr
#define PROCEDURAY_OUT(T) T&
#define PROCEDURAY_INOUT(T) T&
#else
#define PROCEDURAY_INLINE
#define PROCEDURAY_CONST const
#define PROCEDURAY_OUT(T) out T
#define PROCEDURAY_INOUT(T) inout T
#define real float
#define real2 vec2
#define real3 vec3
#define real4 vec4
#endif


/// Token pasting for generated names (marching/marcher.glsl): PROCEDURAY_CAT(bulb, _trace) is bulb_trace.
#define PROCEDURAY_CAT_(a, b) a##b
#define PROCEDURAY_CAT(a, b) PROCEDURAY_CAT_(a, b)

#endif

// Outside the guard, so that including any shared file again restores it after an #undef R.
#ifndef R
#ifdef __cplusplus
// The float literal widened to double is exact, so the float build gets exactly x##f.
#define R(x) (static_cast<real>(sizeof(real) == sizeof(float) ? x##f : x))
#else
#define R(x) x
#endif
#endif
