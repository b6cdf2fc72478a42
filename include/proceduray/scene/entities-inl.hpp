// The bodies of proceduray/scene/entities.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/entities.hpp"

#if PROCEDURAY_BODIES
#include <algorithm>
#include <atomic>
#include <bit>

namespace proceduray {

PROCEDURAY_DECL std::uint32_t detail::next_scene_serial() {
  static std::atomic<std::uint32_t> serial{0};
  return ++serial;
}

PROCEDURAY_DECL Entities::Entities() = default;
PROCEDURAY_DECL Entities::~Entities() = default;
PROCEDURAY_DECL Entities::Entities(const Entities&) = default;
PROCEDURAY_DECL Entities::Entities(Entities&&) noexcept = default;
PROCEDURAY_DECL Entities& Entities::operator=(const Entities&) = default;
PROCEDURAY_DECL Entities& Entities::operator=(Entities&&) noexcept = default;

PROCEDURAY_DECL GeometryId Entities::add_geometry(std::string id, GeometryDesc desc) {
  constexpr std::string_view op = "Scene::add_geometry";
  validate(desc, id, op);
  // Every check comes before the first change, so a throw leaves the scene as it was.
  const BlasSet::Join join = m_blases.check(desc, id, op);
  m_geometries.check_new(op, id);
  const GeometryId gid(static_cast<std::uint32_t>(m_geometries.size()), m_serial);
  const std::uint32_t index = m_blases.add(join, gid, desc, id);
  m_geometries.add(op, std::move(id), Geometry{std::move(desc), join.blas, index});
  return gid;
}

PROCEDURAY_DECL std::uint8_t Entities::add_layer(std::string name) {
  const auto known = m_layers.names();
  if (!name.empty() && std::find(known.begin(), known.end(), name) == known.end()) {
    check_glsl_names("Scene::add_layer", glsl_names(), layer_glsl_names(name));
  }
  return m_layers.add(std::move(name), "Scene::add_layer");
}

PROCEDURAY_DECL GlobalSignatureId Entities::add_global_signature(std::string id, GlobalSignatureDesc desc) {
  validate(desc, id, "Scene::add_global_signature");
  for (const Binding& b : desc.bindings) check_root_component(b.type, "binding \"" + b.name + "\"");
  check_root_component(desc.push_constants.type, "push constant block \"" + desc.push_constants.name + "\"");
  m_global_signatures.check_new("Scene::add_global_signature", id);
  check_glsl_names("Scene::add_global_signature", glsl_names(), signature_glsl_names(desc));
  return GlobalSignatureId(m_global_signatures.add("Scene::add_global_signature", std::move(id),
                                                   GlobalSignature{std::move(desc)}),
                           m_serial);
}

PROCEDURAY_DECL std::vector<GlslName> Entities::glsl_names() const {
  std::vector<GlslName> out;
  for (const std::string& r : m_rays.names()) for (GlslName& n : ray_glsl_names(r)) out.push_back(std::move(n));
  for (const std::string& l : m_layers.names()) for (GlslName& n : layer_glsl_names(l)) out.push_back(std::move(n));
  for (const std::string& c : m_callables.names()) for (GlslName& n : callable_glsl_names(c)) out.push_back(std::move(n));
  return out;
}

PROCEDURAY_DECL std::vector<GlslName> Entities::signature_glsl_names(const GlobalSignatureDesc& desc) {
  std::vector<GlslName> out;
  for (const Binding& b : desc.bindings) for (GlslName& n : binding_glsl_names(b.name, "binding")) out.push_back(std::move(n));
  for (GlslName& n : binding_glsl_names(desc.push_constants.name, "push constant block")) out.push_back(std::move(n));
  return out;
}

PROCEDURAY_DECL void Entities::reserve_geometries(std::size_t count) {
  m_geometries.reserve(count);
  m_blases.reserve(count);
}

PROCEDURAY_DECL void Entities::check_type(std::type_index have, std::type_index want, std::string_view op,
                                          std::string_view kind, std::string_view id, std::string_view what) {
  if (have != want) {
    throw TypeMismatchError(std::string(op) + ": " + std::string(kind) + " \"" + std::string(id) + "\" has " +
                            std::string(what) + " type " + have.name() + ", not the requested " + want.name() +
                            "; ask for the type it was registered with");
  }
}

PROCEDURAY_DECL void Entities::check_root_component(const TypeOps* type, const std::string& what) const {
  if (type == nullptr) return;
  for (const TypeOps* t : m_vocabulary) {
    if (t == type || (t->cpp_name != nullptr && type->cpp_name != nullptr && t->cpp_name() == type->cpp_name())) return;
  }
  const std::string name = type->cpp_name != nullptr ? std::string(type->cpp_name()) : std::string(type->glsl_name);
  throw TypeMismatchError("Scene::add_global_signature: " + what + " holds " + name + ", which is not an alternative "
                          "of the scene's interface; add it to its RootComponent<...> category");
}

PROCEDURAY_DECL void Entities::validate_ray(const RayDesc& desc, std::string_view id, std::string_view op) {
  const auto bits = static_cast<std::uint32_t>(desc.flags);
  const auto count = [&](std::uint32_t mask) { return std::popcount(bits & mask); };
  const std::string where = std::string(op) + ": ray \"" + std::string(id) + "\"";
  if ((bits & ~0xFFu) != 0) {
    throw SceneError(where + " has unknown ray flag bits 0x" + detail::hex(bits & ~0xFFu) +
                     "; combine the RayFlags values only");
  }
  if (count(0x01 | 0x02 | 0x40 | 0x80) > 1) {
    throw SceneError(where + " combines more than one of opaque, no_opaque, cull_opaque and cull_no_opaque (flags 0x" +
                     detail::hex(bits) + "); Vulkan allows one of them per ray: keep one");
  }
  if (count(0x10 | 0x20) > 1) {
    throw SceneError(where + " culls both back- and front-facing triangles (flags 0x" + detail::hex(bits) +
                     "); it could never hit a triangle: keep one of the two");
  }
  if (desc.cull_mask == 0) {
    throw SceneError(where + " has cull mask 0, which no instance passes (mask & cull_mask != 0); use "
                     "scene.layer_mask({...}) or 0xFF for all");
  }
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
