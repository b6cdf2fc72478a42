// The built shader binding table (pass two): the SBT layout, every record, the TLAS
// instances with their library-assigned SBT offsets, the pipeline plan, and resolution.
//
//   proceduray::ShaderBindingTable sbt = table.build(limits);
//   for (const auto& inst : sbt.instances()) {
//     // VkAccelerationStructureInstanceKHR: transform = sbt.transform(inst),
//     // instanceShaderBindingTableRecordOffset = inst.sbt_offset, instanceCustomIndex = index,
//     // accelerationStructureReference = address of BLAS inst.blas
//   }
//   std::vector<std::byte> bytes(sbt.layout().size);
//   sbt.write(bytes, handles);   // handles: vkGetRayTracingShaderGroupHandlesKHR over plan().groups
//   auto hit = sbt.resolve(shadow, pacman, 2);   // record index and the entry it holds
//
// Hit records are laid out per BLAS, in BLAS order: first one block shared by the instances
// without instance-specific entries, then one block per instance that has some. A block is
// geometry-major, ray-minor, so for every (ray r, geometry g, instance i):
//   record = instance_sbt_offset(i) + geometry_index(g) * ray_count() + r
//
//   hit region:  | BLAS 0 shared block        | BLAS 0 inst 3 block | BLAS 1 shared block | ...
//                | g0 r0 | g0 r1 | g1 r0 | g1 r1 | g0 r0 | g0 r1 | ...
// The Scene and ShaderTable it was built from must outlive it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "proceduray/scene/ids.hpp"
#include "proceduray/scene/pipeline_plan.hpp"
#include "proceduray/scene/sbt_layout.hpp"
#include "proceduray/scene/scene.hpp"

namespace proceduray {

/// Marks an absent index in records and entries.
inline constexpr std::uint32_t no_index = 0xFFFF'FFFFu;

/// One shader-table entry as added in pass one; indices refer to the scene's registries.
struct ShaderTableEntry {
  SbtRegionKind region = SbtRegionKind::hit;  ///< raygen, miss or hit
  std::uint32_t ray = no_index;               ///< ray index (miss, hit); no_index for raygen and defaults' geometry
  std::uint32_t hit_group = no_index;         ///< hit group index (hit)
  std::uint32_t local_signature = no_index;   ///< local signature index; no_index = no record data
  std::uint32_t geometry = no_index;          ///< geometry index (hit); no_index for a default entry
  std::uint32_t instance = no_index;          ///< instance of the geometry's BLAS; no_index = all instances
  std::uint32_t shader = no_index;            ///< raygen: index into ShaderTable::raygen_shaders(); callable: its index
  std::uint32_t data_size = 0;                ///< record data bytes
  std::uint64_t data_offset = 0;              ///< where they are in ShaderTable::data()
  bool is_default = false;                    ///< a per-(ray, kind) default hit entry
};

/// One SBT record; fields that do not apply are no_index.
struct SbtRecord {
  std::uint32_t group = no_index;     ///< index into PipelinePlan::groups; no_index = null handle
  std::uint32_t entry = no_index;     ///< the entry it holds; no_index for a miss record without an entry
  std::uint32_t ray = no_index;       ///< ray index (miss, hit)
  std::uint32_t geometry = no_index;  ///< geometry registry index (hit)
  std::uint32_t instance = no_index;  ///< BLAS instance (hit); no_index = shared by instances without own entries
};

/// One TLAS instance; its position in instances() is its instanceCustomIndex.
struct TlasInstance {
  std::uint32_t blas = 0;        ///< index into Scene::blases()
  std::uint32_t instance = 0;    ///< index into that BLAS's instances
  std::uint32_t sbt_offset = 0;  ///< instanceShaderBindingTableRecordOffset
  std::uint8_t mask = 0xFF;      ///< instance mask (GeometryDesc::mask or instance_masks)
};

/// The answer of ShaderBindingTable::resolve.
struct HitResolution {
  std::uint32_t record = 0;                  ///< hit-region record index
  const SbtRecord* sbt_record = nullptr;     ///< the record
  const ShaderTableEntry* entry = nullptr;   ///< the entry it holds
};

class ShaderTable;

/// A built shader binding table; made by ShaderTable::build.
class ShaderBindingTable {
 public:
  /// Offsets, strides and sizes of the four regions.
  const SbtLayout& layout() const { return m_layout; }
  /// Stages, groups and sizes for the pipeline.
  const PipelinePlan& plan() const { return m_plan; }
  /// Records of a region, in record order.
  std::span<const SbtRecord> records(SbtRegionKind region) const { return m_records[static_cast<std::uint32_t>(region)]; }
  /// TLAS instances: BLAS order, then instance order.
  std::span<const TlasInstance> instances() const { return m_instances; }
  /// Position of a BLAS's first instance in instances().
  std::uint32_t first_instance(std::uint32_t blas) const { return m_blas_first_instance.at(blas); }
  /// The transform of a TLAS instance.
  const InstanceTransform& transform(const TlasInstance& instance) const {
    return m_scene->blases()[instance.blas].instances[instance.instance];
  }
  /// traceRayEXT's sbtRecordStride: the number of ray types.
  std::uint32_t ray_count() const { return m_ray_count; }
  /// Vulkan's geometryIndex of a geometry in its BLAS.
  std::uint32_t geometry_index(GeometryId geometry) const { return m_scene->geometry(geometry).geometry_index; }
  /// instanceShaderBindingTableRecordOffset of instance `instance` of a geometry's BLAS; throws SceneError.
  std::uint32_t instance_sbt_offset(GeometryId geometry, std::uint32_t instance) const {
    return m_instances[tlas_index(geometry, instance, "ShaderBindingTable::instance_sbt_offset")].sbt_offset;
  }
  /// The TLAS instance index (instanceCustomIndex) of instance `instance` of a geometry's BLAS.
  std::uint32_t tlas_index(GeometryId geometry, std::uint32_t instance, std::string_view operation = "ShaderBindingTable::tlas_index") const {
    const Geometry& g = m_scene->geometry(geometry);
    const Blas& blas = m_scene->blases()[g.blas];
    if (instance >= blas.instances.size()) {
      throw SceneError(std::string(operation) + ": geometry \"" + m_scene->geometries().name(geometry.index()) +
                       "\" has " + std::to_string(blas.instances.size()) + " instances, no instance " +
                       std::to_string(instance) + "; use an index below the count");
    }
    return m_blas_first_instance[g.blas] + instance;
  }

  /// Applies the Vulkan index rule to (ray, geometry, instance): the hit record and its entry.
  HitResolution resolve(RayId<> ray, GeometryId geometry, std::uint32_t instance) const {
    m_scene->rays().check_index(ray.index(), "ShaderBindingTable::resolve");
    const std::uint32_t offset = instance_sbt_offset(geometry, instance);
    const std::uint32_t record = offset + geometry_index(geometry) * m_ray_count + ray.index();
    const SbtRecord& r = m_records[2].at(record);
    return {record, &r, &(*m_entries)[r.entry]};
  }

  /// The entry a record holds, or nullptr (a miss record with no entry).
  const ShaderTableEntry* entry(const SbtRecord& record) const {
    return record.entry == no_index ? nullptr : &(*m_entries)[record.entry];
  }
  /// The record data bytes of a record (empty when it has none).
  std::span<const std::byte> record_data(const SbtRecord& record) const {
    const ShaderTableEntry* e = entry(record);
    if (!e || e->data_size == 0) return {};
    return std::span<const std::byte>(*m_data).subspan(e->data_offset, e->data_size);
  }

  /// Writes every record into `buffer` (at least layout().size bytes, placed at a multiple of
  /// base_alignment): handle `group` from `group_handles` (handle_size bytes per planned group,
  /// in plan().groups order), then the record data. Padding and null handles are zeroed.
  void write(std::span<std::byte> buffer, std::span<const std::byte> group_handles) const {
    const std::uint32_t handle = m_layout.properties.handle_size;
    if (buffer.size() < m_layout.size) {
      throw std::invalid_argument(std::string("ShaderBindingTable::write: buffer has ") + std::to_string(buffer.size()) +
                                  " bytes, the table needs " + std::to_string(m_layout.size) +
                                  "; allocate layout().size bytes");
    }
    if (group_handles.size() < std::uint64_t{handle} * m_plan.groups.size()) {
      throw std::invalid_argument(std::string("ShaderBindingTable::write: ") + std::to_string(group_handles.size()) +
                                  " bytes of group handles, need " + std::to_string(m_plan.groups.size()) +
                                  " groups x " + std::to_string(handle) + " bytes; fetch handles for every planned group");
    }
    std::memset(buffer.data(), 0, m_layout.size);
    for (std::uint32_t k = 0; k < 4; ++k) {
      const auto kind = static_cast<SbtRegionKind>(k);
      const auto& records = m_records[k];
      for (std::uint32_t i = 0; i < records.size(); ++i) {
        const std::uint64_t at = m_layout.record_offset(kind, i);
        if (records[i].group != no_index) {
          std::memcpy(buffer.data() + at, group_handles.data() + std::uint64_t{records[i].group} * handle, handle);
        }
        const auto data = record_data(records[i]);
        if (!data.empty()) std::memcpy(buffer.data() + at + handle, data.data(), data.size());
      }
    }
  }

  /// The scene it was built from.
  const Scene& scene() const { return *m_scene; }

 private:
  friend class ShaderTable;
  const Scene* m_scene = nullptr;
  const std::vector<ShaderTableEntry>* m_entries = nullptr;
  const std::vector<std::byte>* m_data = nullptr;
  SbtLayout m_layout;
  PipelinePlan m_plan;
  std::array<std::vector<SbtRecord>, 4> m_records;
  std::vector<TlasInstance> m_instances;
  std::vector<std::uint32_t> m_blas_first_instance;
  std::uint32_t m_ray_count = 0;
};

}  // namespace proceduray
