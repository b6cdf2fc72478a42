// A qualified name would print as `const uint ns::flag`, which GLSL rejects: it does not compile.
// expect: PROCEDURAY_GLSL_CONSTS: not a plain GLSL name
#include <proceduray/shader/glsl_consts.hpp>

#include <cstdint>
#include <string>

namespace ns {
inline constexpr std::uint32_t flag = 1u;
}

std::string declarations() { return PROCEDURAY_GLSL_CONSTS(ns::flag); }
