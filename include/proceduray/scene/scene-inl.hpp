// The bodies of proceduray/scene/scene.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/scene.hpp"

#if PROCEDURAY_BODIES
namespace proceduray {

PROCEDURAY_DECL EntryId detail::SceneCore::add_entry(std::string_view op, const Entry& e, const void* data, std::uint32_t size) {
  if (e.local_signature != no_index) local_signatures().check_index(e.local_signature, op);
  const auto same = [&](const Entry& other) {
    if (other.region != e.region) return false;
    if (e.region == SbtRegionKind::miss) return other.ray == e.ray;
    if (e.region == SbtRegionKind::callable) return other.shader == e.shader;
    return e.is_default && other.is_default && other.ray == e.ray &&
           hit_groups().entities()[other.hit_group].desc.kind == hit_groups().entities()[e.hit_group].desc.kind;
  };
  if (e.region == SbtRegionKind::miss) rays().check_index(e.ray, op);
  if (e.region == SbtRegionKind::callable) callables().check_index(e.shader, op);
  if (e.region == SbtRegionKind::hit) check_hit(op, e);
  for (const Entry& other : m_entries.all()) {
    if (!same(other)) continue;
    if (e.region == SbtRegionKind::miss) {
      throw DuplicateIdError(std::string(op) + ": ray \"" + rays().name(e.ray) +
                             "\" already has a miss entry; a ray has one miss record: add it once");
    }
    if (e.region == SbtRegionKind::callable) {
      throw DuplicateIdError(std::string(op) + ": callable \"" + callables().name(e.shader) +
                             "\" already has an entry; a callable has one record: add it once");
    }
    throw DuplicateIdError(std::string(op) + ": ray \"" + rays().name(e.ray) + "\" already has a default " +
                           to_string(hit_groups().entities()[e.hit_group].desc.kind) + " hit group (\"" +
                           hit_groups().name(other.hit_group) + "\"); declare one default per ray and kind");
  }
  return m_entries.push(e, data, size);
}

PROCEDURAY_DECL void detail::SceneCore::check_hit(std::string_view op, const Entry& e) const {
  rays().check_index(e.ray, op);
  const HitGroup& group = hit_groups().at(e.hit_group, op);
  if (e.is_default) return;
  const Geometry& g = geometries().at(e.geometry, op);
  const bool procedural = g.desc.kind == GeometryKind::procedural;
  if (procedural != (group.desc.kind == HitGroupKind::procedural)) {
    throw HitGroupKindError(std::string(op) + ": " + to_string(g.desc.kind) + " geometry \"" +
                            geometries().name(e.geometry) + "\" bound to " + to_string(group.desc.kind) +
                            " hit group \"" + hit_groups().name(e.hit_group) + "\"" +
                            (procedural ? ", which has no intersection shader; bind a procedural hit group"
                                        : ", which has an intersection shader; bind a triangles hit group"));
  }
  const auto count = blases()[g.blas].instances.size();
  if (e.instance != all_instances && e.instance >= count) {
    throw SceneError(std::string(op) + ": instance " + std::to_string(e.instance) + " of geometry \"" +
                     geometries().name(e.geometry) + "\" does not exist (it has " + std::to_string(count) +
                     " instances); use an index below the count, or all_instances");
  }
}

PROCEDURAY_DECL EntryId detail::SceneCore::add_raygen_entry(std::string shader, std::uint32_t signature, const void* data,
                                                std::uint32_t size) {
  if (shader.empty()) throw SceneError("Scene::add_raygen: empty raygen shader name; name the raygen shader");
  if (signature != no_index) local_signatures().check_index(signature, "Scene::add_raygen");
  const Entry e{.region = SbtRegionKind::raygen, .local_signature = signature,
                .shader = m_entries.add_raygen_shader(std::move(shader))};
  return m_entries.push(e, data, size);
}

PROCEDURAY_DECL GlobalSignatureId detail::SceneCore::set_global_signature(GlobalSignatureDesc desc, std::string id) {
  const GlobalSignatureId g = add_global_signature(std::move(id), std::move(desc));
  m_global_signature = g;
  return g;
}

PROCEDURAY_DECL void detail::SceneCore::set_global_signature(GlobalSignatureId id) {
  global_signatures().check_index(own(id, "Scene::set_global_signature"), "Scene::set_global_signature");
  m_global_signature = id;
}

PROCEDURAY_DECL void detail::SceneCore::add_constant(std::string name, ConstantValue value) {
  declare_constant("Scene::add_constant", {std::move(name), value, false});
}

PROCEDURAY_DECL void detail::SceneCore::add_define(std::string name) {
  declare_constant("Scene::add_define", {std::move(name), {}, true});
}

PROCEDURAY_DECL void detail::SceneCore::declare_constant(std::string_view op, SceneConstant c) {
  if (c.name.empty() || glsl_identifier(c.name) != c.name) {
    throw SceneError(std::string(op) + ": \"" + c.name + "\" is no GLSL name (letters, digits and '_', not starting "
                     "with a digit); use \"" + glsl_identifier(c.name) + "\"");
  }
  std::vector<GlslName> taken = glsl_names();
  for (const SceneConstant& k : m_constants) taken.push_back({k.name, quote_origin(k.define ? "define" : "constant", k.name)});
  check_glsl_names(op, taken, {{c.name, quote_origin(c.define ? "define" : "constant", c.name)}});
  m_constants.push_back(std::move(c));
}

PROCEDURAY_DECL void detail::SceneCore::set_max_recursion_depth(std::uint32_t depth) {
  if (depth == 0) {
    throw SceneError("Scene::set_max_recursion_depth: depth 0 allows no traceRayEXT at all; use >= 1");
  }
  m_max_recursion_depth = depth;
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
