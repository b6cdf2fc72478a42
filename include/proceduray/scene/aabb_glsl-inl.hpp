// The bodies of proceduray/scene/aabb_glsl.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/aabb_glsl.hpp"

#if PROCEDURAY_BODIES
namespace proceduray::detail {

PROCEDURAY_DECL std::string glsl_vec3(glm::vec3 v) {
  const std::string line = glsl_const("v", v);
  const std::size_t begin = line.find("= ") + 2;
  return line.substr(begin, line.rfind(';') - begin);
}

PROCEDURAY_DECL std::string glsl_corners(const std::string& name, const std::vector<Aabb>& boxes, bool max) {
  if (boxes.size() == 1) return glsl_const(name, max ? boxes[0].max : boxes[0].min);
  std::string list;
  for (const Aabb& b : boxes) list += (list.empty() ? "" : ", ") + glsl_vec3(max ? b.max : b.min);
  return "const vec3 " + name + "[" + std::to_string(boxes.size()) + "] = vec3[](" + list + ");\n";
}

}  // namespace proceduray::detail

namespace proceduray {

PROCEDURAY_DECL std::string glsl_aabb_consts(const detail::SceneCore& scene) {
  std::string out;
  for (std::uint32_t g = 0; g < scene.geometries().size(); ++g) {
    const GeometryDesc& desc = scene.geometry(GeometryId(g)).desc;
    if (desc.kind != GeometryKind::procedural) continue;
    const std::string name = glsl_identifier(scene.geometries().name(g));
    if (desc.aabbs.size() > 1) out += glsl_const(name + "_aabb_count", static_cast<std::uint32_t>(desc.aabbs.size()));
    out += detail::glsl_corners(name + "_aabb_min", desc.aabbs, false);
    out += detail::glsl_corners(name + "_aabb_max", desc.aabbs, true);
  }
  if (out.empty()) return out;
  return "#ifndef PROCEDURAY_AABB_CONSTS\n#define PROCEDURAY_AABB_CONSTS\n" + out + "#endif\n";
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
