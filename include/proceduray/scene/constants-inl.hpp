// The bodies of proceduray/scene/constants.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/constants.hpp"

#if PROCEDURAY_BODIES
namespace proceduray {

PROCEDURAY_DECL std::string glsl_constant(const SceneConstant& c) {
  if (c.define) return "#define " + c.name + " 1\n";
  return std::visit(
      [&]<class T>(const T& v) -> std::string {
        if constexpr (std::is_same_v<T, std::uint32_t> || std::is_same_v<T, float> || std::is_same_v<T, glm::vec3>) {
          return glsl_const(c.name, v);
        } else if constexpr (std::is_same_v<T, std::int32_t>) {
          return "const int " + c.name + " = " + std::to_string(v) + ";\n";
        } else if constexpr (std::is_same_v<T, bool>) {
          return "const bool " + c.name + (v ? " = true;\n" : " = false;\n");
        } else {
          std::string out = "const vec" + std::to_string(T::length()) + " " + c.name + " = vec" +
                            std::to_string(T::length()) + "(";
          for (int i = 0; i < T::length(); ++i) {
            const std::string one = glsl_const("x", v[i]);  // "const float x = <value>;\n"
            out += (i > 0 ? ", " : "") + one.substr(16, one.size() - 18);
          }
          return out + ");\n";
        }
      },
      c.value);
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
