// The bodies of proceduray/scene/outputs_glsl.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/outputs_glsl.hpp"

#if PROCEDURAY_BODIES
namespace proceduray::detail {

PROCEDURAY_DECL std::string output_store(Output o) {
  const std::string image = "output_" + std::string(name(o)) + "_image", at = "ivec2(gl_LaunchIDEXT.xy)";
  switch (o) {
    case Output::t: return "imageStore(" + image + ", " + at + ", vec4(v, 0.0, 0.0, 0.0));";
    case Output::normal: return "imageStore(" + image + ", " + at + ", vec4(v, 0.0));";
    case Output::ids: return "imageStore(" + image + ", " + at + ", uvec4(v, 0u));";
    case Output::steps: return "imageAtomicAdd(" + image + ", " + at + ", v);";
    case Output::flags: return "imageAtomicOr(" + image + ", " + at + ", v);";
  }
  return {};
}

PROCEDURAY_DECL const char* output_parameter(Output o) {
  switch (o) {
    case Output::t: return "float";
    case Output::normal: return "vec3";
    case Output::ids: return "uvec3";
    case Output::steps:
    case Output::flags: return "uint";
  }
  return "";
}

}  // namespace proceduray::detail

namespace proceduray {

PROCEDURAY_DECL std::string glsl_outputs(std::span<const PlannedOutput> planned) {
  std::string out = "#define output_flag_nan " + std::to_string(output_flag_nan) + "u\n" +
                    "#define output_flag_exhausted " + std::to_string(output_flag_exhausted) + "u\n" +
                    "#define output_flag_started_inside " + std::to_string(output_flag_started_inside) + "u\n" +
                    "#define output_flag_depth " + std::to_string(output_flag_depth) + "u\n";
  if (!planned.empty()) out += "#define PROCEDURAY_OUTPUTS 1\n";
  for (std::uint32_t i = 0; i < output_count; ++i) {
    const Output o = static_cast<Output>(i);
    const std::string helper = "output_" + std::string(name(o));
    const PlannedOutput* p = nullptr;
    for (const PlannedOutput& q : planned) {
      if (q.output == o) p = &q;
    }
    if (p == nullptr) {
      out += "#define " + helper + "(v)\n";
      continue;
    }
    const OutputFormat f = format_of(o);
    out += "layout(set = 0, binding = " + std::to_string(p->binding) + ", " + std::string(f.glsl) + ") uniform " +
           (f.unsigned_int ? "uimage2D " : "image2D ") + helper + "_image;\n";
    out += "void " + helper + "(" + detail::output_parameter(o) + " v) { " + detail::output_store(o) + " }\n";
  }
  return out;
}

PROCEDURAY_DECL std::string glsl_output_hit(std::span<const PlannedOutput> planned) {
  bool any = false;
  for (const PlannedOutput& p : planned) any = any || p.output == Output::t || p.output == Output::normal || p.output == Output::ids;
  if (!any) return "#define output_hit(n)\n";
  return "void output_hit(vec3 n) { output_t(gl_HitTEXT); output_normal(n); "
         "output_ids(uvec3(gl_InstanceCustomIndexEXT, gl_GeometryIndexEXT, gl_PrimitiveID)); }\n";
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
