// The bodies of proceduray/scene/plan.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/plan.hpp"

#if PROCEDURAY_BODIES
namespace proceduray {

PROCEDURAY_DECL Plan::Plan() = default;
PROCEDURAY_DECL Plan::~Plan() = default;
PROCEDURAY_DECL Plan::Plan(const Plan&) = default;
PROCEDURAY_DECL Plan::Plan(Plan&&) noexcept = default;
PROCEDURAY_DECL Plan& Plan::operator=(const Plan&) = default;
PROCEDURAY_DECL Plan& Plan::operator=(Plan&&) noexcept = default;

PROCEDURAY_DECL const std::string& Plan::declarations(ShaderStage stage, std::string_view shader) const {
  for (const PlannedStage& s : m_pipeline.stages) {
    if (s.stage == stage && s.shader == shader) return s.declarations;
  }
  std::string known;
  for (const PlannedStage& s : m_pipeline.stages) known += (known.empty() ? "" : ", ") + detail::quote_id(s.shader);
  throw UnknownIdError("glsl_for: the plan has no " + std::string(to_string(stage)) + " stage \"" + std::string(shader) +
                       "\" (its stages: " + (known.empty() ? std::string("none") : known) +
                       "); name a shader the scene's entries use, as the stage they use it in");
}

PROCEDURAY_DECL SbtLayout Plan::layout(const DeviceLimits& limits) const {
  const std::string device = limits.device.empty() ? std::string("the device") : limits.device;
  auto refuse = [&](const std::string& what, std::uint64_t value, std::uint64_t limit, const char* name,
                    const std::string& fix) {
    return DeviceLimitError("Plan::layout: " + what + " is " + std::to_string(value) + ", " + device + " allows " +
                            std::to_string(limit) + " (" + name + "); " + fix);
  };
  if (m_pipeline.max_recursion_depth > limits.max_ray_recursion_depth) {
    const std::string& path = m_pipeline.recursion_path;
    throw refuse("the scene's max recursion depth" + (path.empty() ? std::string() : " (" + path + ")"),
                 m_pipeline.max_recursion_depth, limits.max_ray_recursion_depth, "maxRayRecursionDepth",
                 "trace iteratively from raygen instead (nested rays cost a level each)");
  }
  for (const PlannedBlas& b : m_blases) {
    if (b.geometries.size() > limits.max_geometry_count) {
      throw refuse("the geometry count of BLAS \"" + b.name + "\"", b.geometries.size(), limits.max_geometry_count,
                   "maxGeometryCount", "split it");
    }
  }
  if (m_instances.size() > limits.max_instance_count) {
    throw refuse("the scene's instance count", m_instances.size(), limits.max_instance_count, "maxInstanceCount",
                 "merge geometry into fewer instances");
  }
  if (m_global && m_global->push_bytes() > limits.max_push_constants_size) {
    throw refuse("the push constant block (bytes) the global signature declares", m_global->push_bytes(),
                 limits.max_push_constants_size, "maxPushConstantsSize; every device allows 128",
                 "move the rest to a uniform");
  }
  for (const PlannedGroup& g : m_pipeline.groups) {
    if (g.attribute_size > limits.max_ray_hit_attribute_size) {
      throw refuse("the hit attribute size (bytes) of hit group \"" + g.name + "\"", g.attribute_size,
                   limits.max_ray_hit_attribute_size, "maxRayHitAttributeSize", "shrink the attribute struct");
    }
  }
  std::array<SbtRegionRecords, 4> counts;
  for (std::uint32_t k = 0; k < 4; ++k) {
    counts[k] = {static_cast<std::uint32_t>(m_records[k].size()), m_pipeline.max_root_arguments_size[k]};
  }
  return layout_sbt(limits.sbt, counts);
}

PROCEDURAY_DECL void Plan::write(const SbtLayout& layout, std::span<std::byte> buffer, std::span<const std::byte> handles,
                                 std::span<const MeshAddresses> meshes) const {
  const std::uint32_t handle = layout.properties.handle_size;
  if (buffer.size() < layout.size) {
    throw UsageError("Plan::write: buffer has " + std::to_string(buffer.size()) + " bytes, the table needs " +
                     std::to_string(layout.size) + "; allocate layout.size bytes");
  }
  if (handles.size() < std::uint64_t{handle} * m_pipeline.groups.size()) {
    throw UsageError("Plan::write: " + std::to_string(handles.size()) + " bytes of group handles, need " +
                     std::to_string(m_pipeline.groups.size()) + " groups x " + std::to_string(handle) +
                     " bytes; fetch handles for every planned group");
  }
  std::memset(buffer.data(), 0, layout.size);
  for (std::uint32_t k = 0; k < 4; ++k) {
    const auto kind = static_cast<SbtRegionKind>(k);
    const auto& list = m_records[k];
    for (std::uint32_t i = 0; i < list.size(); ++i) {
      const std::uint64_t at = layout.record_offset(kind, i);
      if (list[i].group != no_index) {
        std::memcpy(buffer.data() + at, handles.data() + std::uint64_t{list[i].group} * handle, handle);
      }
      const auto data = root_arguments(list[i]);
      if (!data.empty()) std::memcpy(buffer.data() + at + handle, data.data(), data.size());
      if (list[i].mesh_offset == no_index) continue;
      if (list[i].geometry >= meshes.size()) {
        throw UsageError("Plan::write: hit record " + std::to_string(i) + " reads geometry \"" +
                         m_geometries[list[i].geometry].name + "\"'s mesh (a MeshRef), but " +
                         std::to_string(meshes.size()) + " mesh addresses were given; pass one per geometry "
                         "(vk::MeshBuffers::addresses)");
      }
      static_assert(sizeof(MeshAddresses) == 16, "a MeshRef is two 8-byte addresses");
      std::memcpy(buffer.data() + at + handle + list[i].mesh_offset, &meshes[list[i].geometry], sizeof(MeshAddresses));
    }
  }
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
