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

#include "proceduray/scene/aabb_glsl-inl.hpp"  // the bodies (config.hpp)
