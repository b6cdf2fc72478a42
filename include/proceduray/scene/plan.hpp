// The plan: what compile(scene) derives, as one self-contained value with no pointer into the
// scene and no device in it: TLAS instances with their SBT offsets, every SBT record with its
// bytes, the pipeline plan (stages, groups, sizes, recursion depth) and each stage's GLSL
// declarations. Device limits and the SBT layout come after, in one place: layout(limits).
//
//   proceduray::Plan plan = proceduray::compile(scene);        // no device: runs at build time too
//   proceduray::SbtLayout layout = plan.layout(limits);  // throws DeviceLimitError (limits: Context::limits())
//   std::vector<std::byte> bytes(layout.size);
//   plan.write(layout, bytes, handles);   // handles: one per plan.pipeline().groups, in that order
//   auto hit = plan.resolve(shadow, pacman, 2);   // record index and the entry it holds
//
// Hit records are laid out per BLAS, in BLAS order: first one block shared by the instances
// without instance-specific entries, then one block per instance that has some. A block is
// geometry-major, ray-minor, so for every (ray r, geometry g, instance i):
//   record = instance_sbt_offset(i) + geometry_index(g) * ray_count() + r
//
//   hit region:  | BLAS 0 shared block        | BLAS 0 inst 3 block | BLAS 1 shared block | ...
//                | g0 r0 | g0 r1 | g1 r0 | g1 r1 | g0 r0 | g0 r1 | ...
#pragma once

#include <proceduray/config.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "proceduray/error.hpp"
#include "proceduray/scene/constants.hpp"
#include "proceduray/scene/device_limits.hpp"
#include "proceduray/scene/entry.hpp"
#include "proceduray/scene/errors.hpp"
#include "proceduray/scene/field.hpp"
#include "proceduray/scene/geometry.hpp"
#include "proceduray/scene/global_signature.hpp"
#include "proceduray/scene/outputs.hpp"
#include "proceduray/scene/ids.hpp"
#include "proceduray/scene/pipeline_plan.hpp"
#include "proceduray/scene/sbt_layout.hpp"

namespace proceduray {

struct StageTraces;  // recursion.hpp

/// One SBT record; fields that do not apply are no_index.
struct SbtRecord {
  std::uint32_t group = no_index;     ///< index into PipelinePlan::groups; no_index = null handle
  std::uint32_t entry = no_index;     ///< the entry it holds; no_index for a record without one
  std::uint32_t ray = no_index;       ///< ray index (miss, hit)
  std::uint32_t geometry = no_index;  ///< geometry registry index (hit)
  std::uint32_t instance = no_index;  ///< BLAS instance (hit); no_index = shared by instances without own entries
  std::uint32_t mesh_offset = no_index;  ///< hit: where in the root arguments the MeshRef is; no_index = none
  friend bool operator==(const SbtRecord&, const SbtRecord&) = default;
};

/// Device addresses of one geometry's vertex and triangle buffers: what a MeshRef holds.
struct MeshAddresses {
  std::uint64_t vertices = 0;   ///< VertexData's bytes
  std::uint64_t triangles = 0;  ///< TriangleMesh::indices, three per triangle
};

/// One TLAS instance; its position in Plan::instances() is its instanceCustomIndex.
struct TlasInstance {
  std::uint32_t blas = 0;        ///< index into Plan::blases()
  std::uint32_t instance = 0;    ///< index among that BLAS's instances
  std::uint32_t sbt_offset = 0;  ///< instanceShaderBindingTableRecordOffset
  std::uint8_t mask = 0xFF;      ///< instance mask (GeometryDesc::mask or instance_masks)
  InstanceTransform transform = identity_transform();  ///< rows of the 3x4 matrix, as VkTransformMatrixKHR
  friend bool operator==(const TlasInstance&, const TlasInstance&) = default;
};

/// A distance field as the plan knows it: field i of the settings buffer.
struct PlannedField {
  DistanceField field;     ///< as declared (checked)
  GeometryId geometry;     ///< its geometry (the object's)
  MarchCapabilities caps;  ///< what its knobs may be (field_capabilities), with the defaults (the pick, if any)
  /// The setting the scene's error budget picked (its knobs, predicted errors and cost), if one was set.
  std::optional<CalibrationRow> pick;
  std::string pick_device;  ///< the device the pick's table was measured on
  std::string pick_source;  ///< the table's source (Calibration::source), "" when not recorded
  friend bool operator==(const PlannedField& a, const PlannedField& b) {
    return a.field == b.field && a.geometry == b.geometry;  // caps follow from the field
  }
};

/// A geometry as the plan knows it, with the bytes its BLAS and mesh buffers are built from
/// (checked when the scene registered it: the backend takes them as they are).
struct PlannedGeometry {
  std::string name;                  ///< its id
  std::uint32_t blas = 0;            ///< index into Plan::blases()
  std::uint32_t geometry_index = 0;  ///< Vulkan's geometryIndex in its BLAS
  bool opaque = true;                ///< VK_GEOMETRY_OPAQUE_BIT
  const TypeOps* vertex_type = nullptr;  ///< GeometryDesc::vertex_data's struct; nullptr: none
  std::uint32_t vertex_count = 0;        ///< its vertices
  std::vector<Aabb> aabbs;               ///< procedural: its boxes, object space
  TriangleMesh mesh;                     ///< triangles: positions and indices
  std::vector<std::byte> vertex_bytes;   ///< GeometryDesc::vertex_data's bytes (vertex_count vertices)
  friend bool operator==(const PlannedGeometry&, const PlannedGeometry&) = default;
};

/// A BLAS as the plan knows it; its instances are consecutive in Plan::instances().
struct PlannedBlas {
  std::string name;                            ///< shared BLAS name, or its only geometry's id
  GeometryKind kind = GeometryKind::procedural;  ///< of all its geometries
  UpdatePolicy update = UpdatePolicy::Static;  ///< of all its geometries
  std::vector<std::uint32_t> geometries;       ///< geometry indices, in geometry-index order
  std::uint32_t first_instance = 0;            ///< its first TLAS instance
  std::uint32_t instance_count = 0;            ///< how many
  /// The hit records of instances without entries of their own and of instances added at run
  /// time; no_index when every instance has its own and no geometry set may_add_instances.
  std::uint32_t shared_sbt_offset = no_index;
  friend bool operator==(const PlannedBlas&, const PlannedBlas&) = default;
};

/// The answer of Plan::resolve.
struct HitResolution {
  std::uint32_t record = 0;           ///< hit-region record index
  const SbtRecord* sbt_record = nullptr;  ///< the record
  const Entry* entry = nullptr;       ///< the entry it holds
};

/// What compile(scene) derived; a value: copy it, keep it, compare it.
class Plan {
 public:
  // Out of line so that a program compiles the members' copies and destruction once.
  Plan();
  ~Plan();
  Plan(const Plan&);
  Plan(Plan&&) noexcept;
  Plan& operator=(const Plan&);
  Plan& operator=(Plan&&) noexcept;

  /// Records of a region, in record order.
  std::span<const SbtRecord> records(SbtRegionKind region) const { return m_records[static_cast<std::uint32_t>(region)]; }
  /// TLAS instances: BLAS order, then instance order.
  std::span<const TlasInstance> instances() const { return m_instances; }
  /// BLASes in the scene's order.
  std::span<const PlannedBlas> blases() const { return m_blases; }
  /// Stages, groups, sizes and recursion depth for the pipeline.
  const PipelinePlan& pipeline() const { return m_pipeline; }
  /// The global signature the pipeline uses, or nullptr.
  const GlobalSignatureDesc* global_signature() const { return m_global ? &*m_global : nullptr; }
  /// The per-pixel outputs the scene asked for, in Output order, with their bindings in set 0
  /// (also in global_signature() as BindingKind::output_image).
  std::span<const PlannedOutput> outputs() const { return m_outputs; }
  /// The binding (set 0) of the image that counts how deep each pixel's rays nest, so that the
  /// generated trace_<ray> functions refuse to pass the declared depth (glsl_for.hpp); no_index
  /// when the scene declares no depth (a derived depth is exact) or names no TLAS to trace.
  std::uint32_t depth_binding() const { return m_depth_binding; }
  /// The distance fields (Scene::fields), in order: field i reads proceduray_fields.data[i].
  std::span<const PlannedField> fields() const { return m_fields; }
  /// The binding (set 0) of the fields' settings buffer (FieldSettings[]); no_index without fields.
  std::uint32_t field_binding() const { return m_field_binding; }
  /// The constants and defines the scene declared (Scene::add_constant), in every stage's declarations.
  std::span<const SceneConstant> constants() const { return m_constants; }
  /// traceRayEXT's sbtRecordStride: the number of ray types.
  std::uint32_t ray_count() const { return static_cast<std::uint32_t>(m_ray_names.size()); }
  /// A ray type's id.
  const std::string& ray_name(std::uint32_t ray) const { return m_ray_names.at(ray); }
  /// Every geometry, in registration order.
  std::span<const PlannedGeometry> geometries() const { return m_geometries; }
  /// Fixes the recursion depth from what each compiled stage traces (`traces`: one per
  /// pipeline().stages, recursion.hpp): the derived depth when none was declared, else the
  /// declared one. Throws UsageError, naming `operation` and the chain of rays, for a declared depth
  /// below what the stages nest, or a cycle (reflections) with no declared depth, and
  /// DeviceLimitError for a derived depth past `limits` (layout() checks a declared one).
  void settle_recursion(std::span<const StageTraces> traces, const DeviceLimits& limits,
                        std::string_view operation = "Plan::settle_recursion");
  /// A geometry of this plan; throws UnknownIdError for an id the plan does not have, naming `operation`.
  const PlannedGeometry& geometry(GeometryId id, std::string_view operation = "Plan::geometry") const {
    if (id.scene() != 0 && id.scene() != m_scene) {
      throw UnknownIdError(std::string(operation) + ": geometry #" + std::to_string(id.index()) + " was issued by "
                           "scene #" + std::to_string(id.scene()) + ", but this plan (and a renderer built from it) "
                           "was compiled from scene #" + std::to_string(m_scene) + "; use an id of that scene");
    }
    if (!id.valid()) {
      throw UnknownIdError(std::string(operation) + ": a default-constructed GeometryId names no geometry; use the id "
                           "Scene::add_geometry (or add_object, add_distance_field) returned");
    }
    if (id.index() >= m_geometries.size()) {
      throw UnknownIdError(std::string(operation) + ": geometry #" + std::to_string(id.index()) + " is not in the "
                           "compiled scene (it has " + std::to_string(m_geometries.size()) + " geometries); "
                           "compile the scene again after adding geometry");
    }
    return m_geometries[id.index()];
  }
  /// Vulkan's geometryIndex of a geometry in its BLAS.
  std::uint32_t geometry_index(GeometryId id) const { return geometry(id).geometry_index; }
  /// The TLAS instance index (instanceCustomIndex) of instance `instance` of a geometry's BLAS;
  /// throws InvalidGeometryError naming `operation`, the geometry and the index.
  std::uint32_t tlas_index(GeometryId id, std::uint32_t instance, std::string_view operation = "Plan::tlas_index") const {
    const PlannedGeometry& g = geometry(id, operation);
    const PlannedBlas& blas = m_blases[g.blas];
    if (instance >= blas.instance_count) {
      throw InvalidGeometryError(std::string(operation) + ": geometry \"" + g.name + "\" has " +
                                 std::to_string(blas.instance_count) + " instances, no instance " +
                                 std::to_string(instance) + "; pass an instance index below " +
                                 std::to_string(blas.instance_count) + " (the order of GeometryDesc::instances)");
    }
    return blas.first_instance + instance;
  }
  /// instanceShaderBindingTableRecordOffset of instance `instance` of a geometry's BLAS.
  std::uint32_t instance_sbt_offset(GeometryId id, std::uint32_t instance) const {
    return m_instances[tlas_index(id, instance, "Plan::instance_sbt_offset")].sbt_offset;
  }
  /// Applies the Vulkan index rule to (ray, geometry, instance): the hit record and its entry.
  HitResolution resolve(RayId<> ray, GeometryId id, std::uint32_t instance) const {
    if (ray.index() >= ray_count()) {
      throw UnknownIdError("Plan::resolve: ray #" + std::to_string(ray.index()) + " is not in the compiled scene (" +
                           std::to_string(ray_count()) + " ray types); pass a ray id of this scene");
    }
    const std::uint32_t record = instance_sbt_offset(id, instance) + geometry_index(id) * ray_count() + ray.index();
    const SbtRecord& r = m_records[2].at(record);
    return {record, &r, &m_entries[r.entry]};
  }
  /// The entry a record holds, or nullptr.
  const Entry* entry(const SbtRecord& record) const { return record.entry == no_index ? nullptr : &m_entries[record.entry]; }
  /// The root arguments bytes of a record (empty when it has none).
  std::span<const std::byte> root_arguments(const SbtRecord& record) const {
    const Entry* e = entry(record);
    if (e == nullptr || e->arguments_size == 0) return {};
    return std::span<const std::byte>(m_data).subspan(e->arguments_offset, e->arguments_size);
  }
  /// The GLSL declarations compile() derived for `shader` as `stage`; throws UnknownIdError if
  /// the plan has no such stage.
  const std::string& declarations(ShaderStage stage, std::string_view shader) const;

  /// Checks the plan against a device's limits and lays out the SBT for it; throws
  /// DeviceLimitError naming the limit, the value and the device.
  SbtLayout layout(const DeviceLimits& limits) const;
  /// Writes every record into `buffer` (at least layout.size bytes, placed at a multiple of
  /// base_alignment): the handle of its group from `group_handles` (handle_size bytes per
  /// planned group), then its root arguments, with `meshes[geometry]` (by geometry index) in
  /// the MeshRef of those that hold one. Padding and null handles are zeroed. Throws UsageError
  /// when a MeshRef's geometry has no entry in `meshes`.
  void write(const SbtLayout& layout, std::span<std::byte> buffer, std::span<const std::byte> group_handles,
             std::span<const MeshAddresses> meshes = {}) const;
  /// True when some hit record holds a MeshRef (write needs the geometries' mesh addresses).
  bool reads_meshes() const {
    for (const SbtRecord& r : records(SbtRegionKind::hit)) {
      if (r.mesh_offset != no_index) return true;
    }
    return false;
  }

  friend bool operator==(const Plan&, const Plan&) = default;

 private:
  friend struct PlanBuilder;  // compile.hpp fills the plan
  std::vector<std::string> m_ray_names;
  /// Serial of the scene compiled (Entities::serial); not part of a plan's value, so two scenes
  /// built alike compile to equal plans.
  struct SceneSerial {
    std::uint32_t value = 0;
    operator std::uint32_t() const { return value; }
    friend bool operator==(SceneSerial, SceneSerial) { return true; }
  };
  SceneSerial m_scene;
  std::vector<PlannedGeometry> m_geometries;
  std::vector<PlannedBlas> m_blases;
  std::vector<TlasInstance> m_instances;
  std::array<std::vector<SbtRecord>, 4> m_records;
  std::vector<Entry> m_entries;
  std::vector<std::byte> m_data;
  PipelinePlan m_pipeline;
  std::optional<GlobalSignatureDesc> m_global;
  std::vector<PlannedOutput> m_outputs;
  std::vector<SceneConstant> m_constants;
  std::vector<PlannedField> m_fields;
  std::uint32_t m_field_binding = no_index;
  std::uint32_t m_depth_binding = no_index;
};

}  // namespace proceduray

#include "proceduray/scene/plan-inl.hpp"  // the bodies (config.hpp)
#include "proceduray/scene/recursion.hpp"  // StageTraces, and settle_recursion's body
