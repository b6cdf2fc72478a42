// The bodies of proceduray/scene/object.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/object.hpp"

#if PROCEDURAY_BODIES
namespace proceduray::detail {

PROCEDURAY_DECL std::string object_group_name(const detail::SceneCore& scene, std::string_view id, std::uint32_t r) {
  return r == 0 ? std::string(id) : std::string(id) + "_" + scene.rays().name(r);
}

PROCEDURAY_DECL std::string shader_of(const detail::SceneCore& scene, const std::vector<RayShader>& list, std::uint32_t ray,
                                      std::string_view id, const char* what) {
  std::string found;
  bool seen = false;
  for (const RayShader& s : list) {
    scene.rays().check_index(s.ray.index(), std::string("add_object: object \"") + std::string(id) + "\" " + what);
    if (s.ray.index() != ray) continue;
    if (seen) {
      throw DuplicateIdError("add_object: object \"" + std::string(id) + "\" lists ray \"" + scene.rays().name(ray) +
                             "\" twice in " + what + "; give each ray type one shader");
    }
    seen = true;
    found = s.shader;
  }
  return found;
}

PROCEDURAY_DECL std::size_t object_instances(const detail::SceneCore& scene, const GeometryDesc& g) {
  if (!g.instances.empty() || g.blas.empty()) return g.instances.size();
  const Blas* shared = scene.find_shared_blas(g.blas);
  return shared != nullptr ? shared->instances.size() : 0;
}

}  // namespace proceduray::detail
#endif  // PROCEDURAY_BODIES
