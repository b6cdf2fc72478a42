// The bodies of proceduray/scene/blas.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/blas.hpp"

#if PROCEDURAY_BODIES
namespace proceduray {

PROCEDURAY_DECL BlasSet::Join BlasSet::check(const GeometryDesc& desc, std::string_view id, std::string_view op) const {
  auto refuse = [&](const std::string& what) {
    return InvalidGeometryError(std::string(op) + ": geometry \"" + std::string(id) + "\" " + what);
  };
  if (desc.instances.empty() && (desc.mask != all_layers || !desc.instance_masks.empty())) {
    throw refuse("sets instance masks but declares no instances; masks belong to the instances: set them on "
                 "the geometry that declares them");
  }
  const auto it = desc.blas.empty() ? m_shared.end() : m_shared.find(desc.blas);
  if (it == m_shared.end()) return {static_cast<std::uint32_t>(m_blases.size()), true};
  const Blas& blas = m_blases[it->second];
  if (blas.kind != desc.kind) {
    throw refuse(std::string("is ") + to_string(desc.kind) + " but BLAS \"" + blas.name + "\" holds " +
                 to_string(blas.kind) + " geometry; a BLAS holds one kind: name another BLAS");
  }
  if (blas.update != desc.update) {
    throw refuse(std::string("is ") + to_string(desc.update) + " but BLAS \"" + blas.name + "\" is " +
                 to_string(blas.update) + "; geometries sharing a BLAS share its instances and its builds, "
                 "so declare the same update policy or name another BLAS");
  }
  if (!blas.instances.empty() && !desc.instances.empty()) {
    if (desc.instances != blas.instances) {
      throw refuse("declares " + std::to_string(desc.instances.size()) + " instances that differ from the " +
                   std::to_string(blas.instances.size()) + " of its BLAS \"" + blas.name +
                   "\"; instances belong to the BLAS: declare them once (others leave them empty)");
    }
    if (masks_of(desc) != blas.masks) {
      throw refuse("declares instance masks that differ from those of its BLAS \"" + blas.name +
                   "\"; masks belong to the instances: declare them once, with the instances");
    }
  }
  return {it->second, false};
}

PROCEDURAY_DECL std::uint32_t BlasSet::add(Join join, GeometryId geometry, GeometryDesc& desc, std::string_view id) {
  std::vector<std::uint8_t> masks = masks_of(desc);
  std::vector<InstanceTransform> instances = std::move(desc.instances);
  desc.instances.clear();
  if (join.new_blas) {
    const bool shared = !desc.blas.empty();
    if (shared) m_shared.emplace(desc.blas, join.blas);
    m_blases.push_back(Blas{shared ? desc.blas : std::string(id), desc.kind, {geometry}, std::move(instances),
                            std::move(masks), desc.update, shared});
    return 0;
  }
  Blas& blas = m_blases[join.blas];
  if (blas.instances.empty()) {
    blas.instances = std::move(instances);
    blas.masks = std::move(masks);
  }
  blas.geometries.push_back(geometry);
  return static_cast<std::uint32_t>(blas.geometries.size() - 1);
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
