// One source, two compilers, two precisions: macros that let a distance function written in
// plain GLSL also compile as C++ against GLM, in float and in double, so a CPU reference runs
// the very same code as the GPU, and a double-precision run of it measures the float error.
//
//   #include "../common/compat.glsl"
//   PROCEDURAY_CONST pr_real bailout = PR(16.0);
//   PROCEDURAY_INLINE pr_real f(pr_real3 p, PROCEDURAY_OUT(pr_real) grad_len) { ... PR(0.5) * length(p) ... }
//
// Rules for shared files:
//   - scalars and vectors of the surface's precision are `pr_real`, `pr_real2`, `pr_real3`, `pr_real4`;
//     in GLSL they are float, vec2, vec3, vec4 (macros below), so the SPIR-V is what plain
//     float code gives. int, uint and bool stay as they are.
//   - literals are PR(1.0): the bare literal in GLSL (a float there), and in C++ exactly the
//     float literal `1.0f` in a float build (so the float build is bit for bit the old code)
//     or the double literal `1.0` in a double build (so the reference is not silently float).
//     Write PR(...) with a decimal point and no sign: PR(0.5), -PR(2.0), PR(1.0e-30).
//   - no swizzles (GLM's need anonymous unions, which -Wpedantic rejects), no GLSL-only
//     built-ins (gl_*, floatBitsToInt) outside `#ifndef __cplusplus`, out/inout parameters
//     through PROCEDURAY_OUT / PROCEDURAY_INOUT, functions PROCEDURAY_INLINE, file-scope
//     constants PROCEDURAY_CONST, and no prototypes in C++ (see below).
//
// In C++ the includer binds `pr_real` (and pr_real2..4, uint, GLM's names) and chooses the scope;
// the library's proceduray/shader/glsl_cpp.hpp gives both ways:
//   namespace mine { using namespace proceduray::glsl_cpp;      // float only, free functions
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
// Every name this file defines is prefixed (pr_, PR, PROCEDURAY_), so it takes no name from a
// user's GLSL or from GLM (whose headers use R and real as template parameters).
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
#define pr_real float
#define pr_real2 vec2
#define pr_real3 vec3
#define pr_real4 vec4
#endif


// The float literal widened to double is exact, so the float build gets exactly x##f.
#ifdef __cplusplus
#define PR(x) (static_cast<pr_real>(sizeof(pr_real) == sizeof(float) ? x##f : x))
#else
#define PR(x) x
#endif

/// Token pasting for generated names (marching/marcher.glsl): PROCEDURAY_CAT(bulb, _trace) is bulb_trace.
#define PROCEDURAY_CAT_(a, b) a##b
#define PROCEDURAY_CAT(a, b) PROCEDURAY_CAT_(a, b)

#endif
