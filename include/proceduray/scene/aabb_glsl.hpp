// The local AABBs of a scene's procedural geometry as GLSL constants, for intersection shaders
// that clip their ray to their own box.
//
//   scene.add_geometry("julia", proceduray::GeometryDesc::procedural({{glm::vec3(-1.5f), glm::vec3(1.5f)}}));
//   std::string glsl = proceduray::glsl_aabb_consts(scene);
//   // const vec3 julia_aabb_min = vec3(-1.5, -1.5, -1.5);
//   // const vec3 julia_aabb_max = vec3(1.5, 1.5, 1.5);
//   // a geometry of n > 1 boxes: const uint <id>_aabb_count = n; const vec3 <id>_aabb_min[n] = vec3[](...); max too
//
// Why: the boxes are already in the scene; writing them again as GLSL constants by hand is a second
// copy that drifts (a shader clipping to a smaller box than the BLAS's cuts the object, a larger one
// wastes steps). Names are the geometry id made a GLSL identifier; values print as glsl_const does,
// so they read back as the same floats. compile() puts them in every stage's declarations
// (glsl_for.hpp); the text is guarded by PROCEDURAY_AABB_CONSTS, so a shader that includes a
// second copy declares nothing twice.
#pragma once

#include <proceduray/config.hpp>

#include <string>
#include <string_view>
#include <vector>

#include "proceduray/scene/geometry.hpp"
#include "proceduray/scene/glsl_names.hpp"
#include "proceduray/scene/scene.hpp"
#include "proceduray/shader/glsl_codegen.hpp"

namespace proceduray {

namespace detail {
/// `vec3(x, y, z)` as glsl_const prints it.
PROCEDURAY_DECL std::string glsl_vec3(glm::vec3 v);
/// One corner of every box: a constant for one box, an array for several.
PROCEDURAY_DECL std::string glsl_corners(const std::string& name, const std::vector<Aabb>& boxes, bool max);
}  // namespace detail

/// `<id>_aabb_min` and `<id>_aabb_max` of every procedural geometry (arrays and `<id>_aabb_count`
/// for a geometry of several boxes), in registration order, inside an #ifndef guard; "" when
/// there is none.
PROCEDURAY_DECL std::string glsl_aabb_consts(const detail::SceneCore& scene);

}  // namespace proceduray

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
