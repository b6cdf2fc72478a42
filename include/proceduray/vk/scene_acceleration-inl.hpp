// The bodies of proceduray/vk/scene_acceleration.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/scene_acceleration.hpp"

#if PROCEDURAY_BODIES

namespace proceduray::vk {

PROCEDURAY_DECL SceneAcceleration::SceneAcceleration(const Context& ctx, const proceduray::Plan& plan,
                                                     const BuildOptions& options)
    : m_ctx(&ctx), m_plan(&plan) {
  const auto blases = plan.blases();
  m_blases.resize(blases.size());
  build_static_blases(options);
  for (std::uint32_t b = 0; b < m_blases.size(); ++b) {
    if (blases[b].update == UpdatePolicy::DynamicGeometry) build_refittable_blas(b);
  }
  const auto instances = m_plan->instances();
  std::vector<Instance> list;
  for (std::uint32_t k = 0; k < instances.size(); ++k) {
    list.push_back({.blas = &m_blases[instances[k].blas].get(), .transform = instances[k].transform, .custom_index = k,
                    .sbt_offset = instances[k].sbt_offset, .mask = instances[k].mask});
  }
  m_instances = std::make_unique<SceneInstances>(*m_plan, std::move(list));
  // Always refittable, so showing and hiding instances (a mask) is an update, never a rebuild.
  m_tlas = Tlas(*m_ctx, m_instances->list(), {.allow_update = true, .planned = true});
}

PROCEDURAY_DECL std::uint32_t SceneAcceleration::add_instance(GeometryId geometry, const glm::mat4& object_to_world,
                                                             std::uint32_t mask, std::string_view op) {
  const PlannedGeometry& g = m_plan->geometry(geometry, op);
  const std::uint32_t instance = m_instances->add(geometry, object_to_world, mask, m_blases[g.blas].get(), op);
  const auto count = static_cast<std::uint32_t>(m_instances->list().size());
  if (count > m_tlas.capacity()) {
    // Twice the room, so a run of adds replaces the TLAS a logarithmic number of times.
    m_tlas = Tlas(*m_ctx, m_instances->list(), {.allow_update = true, .planned = true}, std::max<std::uint32_t>(16, 2 * count));
    m_tlas_replaced = true;
  }
  return instance;
}

PROCEDURAY_DECL void SceneAcceleration::build_static_blases(const BuildOptions& options) {
  const auto blases = m_plan->blases();
  std::vector<std::uint32_t> which;
  std::vector<std::vector<AabbGeometry>> boxes;         // straight from the plan: Static data is not copied
  std::vector<std::vector<TriangleGeometry>> meshes;
  std::vector<BlasGeometries> batch;
  for (std::uint32_t b = 0; b < blases.size(); ++b) {
    if (blases[b].update == UpdatePolicy::DynamicGeometry) continue;
    which.push_back(b);
    boxes.emplace_back();
    meshes.emplace_back();
    for (std::uint32_t g : blases[b].geometries) {
      const PlannedGeometry& desc = m_plan->geometries()[g];
      if (blases[b].kind == GeometryKind::procedural) {
        boxes.back().push_back(
            {std::span(reinterpret_cast<const VkAabbPositionsKHR*>(desc.aabbs.data()), desc.aabbs.size()), desc.opaque});
      } else {
        meshes.back().push_back({desc.mesh.vertices, desc.mesh.indices, desc.opaque});
      }
    }
  }
  for (std::size_t i = 0; i < which.size(); ++i) batch.push_back({boxes[i], meshes[i]});
  // One submit builds every Static BLAS and queries the compacted sizes, a second compacts them all.
  BuildOptions planned = options;
  planned.planned = true;  // checked when the scene registered the geometry
  std::vector<AccelerationStructure> built = build_blases(*m_ctx, batch, planned);
  for (std::size_t i = 0; i < which.size(); ++i) m_blases[which[i]].fixed = std::move(built[i]);
}

PROCEDURAY_DECL void SceneAcceleration::build_refittable_blas(std::uint32_t b) {
  const PlannedBlas& blas = m_plan->blases()[b];
  BlasSlot& slot = m_blases[b];
  for (std::uint32_t g : blas.geometries) {
    const PlannedGeometry& desc = m_plan->geometries()[g];
    if (blas.kind == GeometryKind::procedural) {
      const auto* first = reinterpret_cast<const VkAabbPositionsKHR*>(desc.aabbs.data());
      slot.boxes.emplace_back(first, first + desc.aabbs.size());
    } else {
      slot.meshes.push_back(desc.mesh);  // the renderer's own copy: set_vertices and set_mesh change it
    }
  }
  if (blas.kind == GeometryKind::procedural) {
    slot.dynamic = std::make_unique<RefittableBlas>(*m_ctx, std::span<const AabbGeometry>(aabb_geometries(b)), true, true);
  } else {
    slot.dynamic = std::make_unique<RefittableBlas>(*m_ctx, std::span<const TriangleGeometry>(triangle_geometries(b)), true, true);
  }
}

PROCEDURAY_DECL std::vector<AabbGeometry> SceneAcceleration::aabb_geometries(std::uint32_t b) const {
  const PlannedBlas& blas = m_plan->blases()[b];
  std::vector<AabbGeometry> out;
  for (std::size_t g = 0; g < blas.geometries.size(); ++g) {
    out.push_back({m_blases[b].boxes[g], m_plan->geometries()[blas.geometries[g]].opaque});
  }
  return out;
}

PROCEDURAY_DECL std::vector<TriangleGeometry> SceneAcceleration::triangle_geometries(std::uint32_t b) const {
  const PlannedBlas& blas = m_plan->blases()[b];
  std::vector<TriangleGeometry> out;
  for (std::size_t g = 0; g < blas.geometries.size(); ++g) {
    const TriangleMesh& mesh = m_blases[b].meshes[g];
    out.push_back({mesh.vertices, mesh.indices, m_plan->geometries()[blas.geometries[g]].opaque});
  }
  return out;
}

PROCEDURAY_DECL const PlannedBlas& SceneAcceleration::dynamic_geometry(GeometryId geometry, GeometryKind kind,
                                                                         std::string_view operation) const {
  const PlannedGeometry& g = m_plan->geometry(geometry, operation);
  const PlannedBlas& blas = m_plan->blases()[g.blas];
  const std::string& name = g.name;
  if (blas.update != UpdatePolicy::DynamicGeometry) {
    throw UsageError(std::string(operation) + ": geometry \"" + name + "\" is " + to_string(blas.update) +
                                ", so its BLAS was built not to change; declare it with "
                                "update = UpdatePolicy::DynamicGeometry");
  }
  if (blas.kind != kind) {
    throw UsageError(std::string(operation) + ": geometry \"" + name + "\" is " + to_string(blas.kind) +
                                (kind == GeometryKind::procedural ? "; change its vertices with set_vertices or set_mesh"
                                                                  : "; change its boxes with set_aabbs"));
  }
  return blas;
}

PROCEDURAY_DECL void SceneAcceleration::set_aabbs(GeometryId geometry, std::span<const Aabb> boxes, std::string_view op) {
  dynamic_geometry(geometry, GeometryKind::procedural, op);
  const PlannedGeometry& g = m_plan->geometry(geometry, op);
  const std::string where = std::string(op) + ": geometry \"" + g.name + "\"";
  if (boxes.empty()) throw InvalidGeometryError(where + " given no boxes; give it at least one AABB");
  std::vector<VkAabbPositionsKHR> list;
  list.reserve(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    if (!proceduray::detail::valid_box(boxes[i])) validate(boxes[i], where + " AABB " + std::to_string(i));  // throws
    const Aabb& a = boxes[i];
    list.push_back({a.min.x, a.min.y, a.min.z, a.max.x, a.max.y, a.max.z});
  }
  BlasSlot& slot = m_blases[g.blas];
  slot.boxes[g.geometry_index] = std::move(list);
  slot.changed = true;
}

PROCEDURAY_DECL void SceneAcceleration::set_vertices(GeometryId geometry, std::span<const glm::vec3> vertices,
                                                     std::string_view op) {
  dynamic_geometry(geometry, GeometryKind::triangles, op);
  const PlannedGeometry& g = m_plan->geometry(geometry, op);
  TriangleMesh mesh = m_blases[g.blas].meshes[g.geometry_index];
  if (vertices.size() != mesh.vertices.size()) {
    throw InvalidGeometryError(std::string(op) + ": geometry \"" + g.name +
                               "\" has " + std::to_string(mesh.vertices.size()) + " vertices, " +
                               std::to_string(vertices.size()) + " given; new positions keep the count: "
                               "call set_mesh to change the topology");
  }
  mesh.vertices.assign(vertices.begin(), vertices.end());
  set_mesh(geometry, std::move(mesh), op);
}

PROCEDURAY_DECL void SceneAcceleration::set_mesh(GeometryId geometry, TriangleMesh mesh, std::string_view op) {
  dynamic_geometry(geometry, GeometryKind::triangles, op);
  const PlannedGeometry& g = m_plan->geometry(geometry, op);
  GeometryDesc check = GeometryDesc::triangles(mesh, {});
  validate(check, g.name, op);  // throws InvalidGeometryError naming the geometry
  if (g.vertex_type != nullptr && mesh.vertices.size() != g.vertex_count) {
    throw UsageError(std::string(op) + ": geometry \"" + g.name + "\" has vertex data for " + std::to_string(g.vertex_count) +
                     " vertices (" + std::string(g.vertex_type->glsl_name) + ", uploaded once at the build), not " +
                     std::to_string(mesh.vertices.size()) + "; keep the vertex count, or give the new mesh its own "
                     "geometry");
  }
  BlasSlot& slot = m_blases[g.blas];
  slot.meshes[g.geometry_index] = std::move(mesh);
  slot.changed = true;
}

PROCEDURAY_DECL void SceneAcceleration::record_refit(VkCommandBuffer cmd, std::uint32_t b) {
  RefittableBlas& blas = *m_blases[b].dynamic;
  if (m_plan->blases()[b].kind == GeometryKind::procedural) {
    blas.record_refit(*m_ctx, cmd, std::span<const AabbGeometry>(aabb_geometries(b)));
  } else {
    blas.record_refit(*m_ctx, cmd, std::span<const TriangleGeometry>(triangle_geometries(b)));
  }
}

PROCEDURAY_DECL std::vector<std::uint32_t> SceneAcceleration::prepare_blases(FrameWork& work) {
  std::vector<std::uint32_t> refits;
  for (std::uint32_t b = 0; b < m_blases.size(); ++b) {
    BlasSlot& slot = m_blases[b];
    if (!slot.changed) continue;
    slot.changed = false;
    const bool procedural = m_plan->blases()[b].kind == GeometryKind::procedural;
    const auto boxes = procedural ? aabb_geometries(b) : std::vector<AabbGeometry>{};
    const auto meshes = procedural ? std::vector<TriangleGeometry>{} : triangle_geometries(b);
    const bool refit = procedural ? slot.dynamic->same_topology(std::span<const AabbGeometry>(boxes))
                                  : slot.dynamic->same_topology(std::span<const TriangleGeometry>(meshes));
    if (refit) {
      refits.push_back(b);
      ++work.blas_refits;
      m_instances->blas_refit();  // the TLAS holds the old bounds: refit it
    } else {
      // A new structure (the old one is freed whole, handle before memory); its instances point at it.
      // Checked by set_aabbs, set_vertices or set_mesh when given (planned: not again).
      slot.dynamic = procedural ? std::make_unique<RefittableBlas>(*m_ctx, std::span<const AabbGeometry>(boxes), true, true)
                                : std::make_unique<RefittableBlas>(*m_ctx, std::span<const TriangleGeometry>(meshes), true, true);
      m_instances->blas_rebuilt(b, slot.dynamic->structure());
      ++work.blas_builds;
    }
  }
  return refits;
}

PROCEDURAY_DECL FrameWork SceneAcceleration::record(VkCommandBuffer cmd) {
  FrameWork work;
  const std::vector<std::uint32_t> refits = prepare_blases(work);
  for (std::uint32_t b : refits) record_refit(cmd, b);  // each ends with a barrier for the TLAS build
  switch (m_instances->take()) {
    case TlasWork::build:
      m_tlas.record_build(*m_ctx, cmd, m_instances->list());
      ++work.tlas_builds;
      break;
    case TlasWork::update:
      m_tlas.record_update(*m_ctx, cmd, m_instances->list());
      ++work.tlas_updates;
      break;
    case TlasWork::none:
      break;
  }
  return work;
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
