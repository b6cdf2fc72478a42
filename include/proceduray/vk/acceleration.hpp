// Bottom-level (AABB) and top-level acceleration structures, built on the device and waited for.
//
//   VkAabbPositionsKHR box{-1, -1, -1, 1, 1, 1};
//   const proceduray::vk::AabbGeometry boxes{.boxes = {&box, 1}};
//   auto blas = proceduray::vk::build_blas(ctx, {&boxes, 1});
//   std::vector<proceduray::vk::Instance> instances{
//       {.blas = &blas, .transform = glm::translate(glm::mat4(1), {-1.5f, 0, 0}), .sbt_offset = 0},
//       {.blas = &blas, .transform = glm::translate(glm::mat4(1), {+1.5f, 0, 0}), .sbt_offset = 1}};
//   auto tlas = proceduray::vk::build_tlas(ctx, instances);
//
//   const glm::vec3 quad[] = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
//   const std::uint32_t tris[] = {0, 1, 2, 0, 2, 3};
//   const proceduray::vk::TriangleGeometry mesh{.vertices = quad, .indices = tris};
//   auto plane = proceduray::vk::build_blas(ctx, {&mesh, 1});                             // triangles
//   proceduray::vk::Tlas moving(ctx, instances, {.allow_update = true});
//   instances[0].transform = moved;  moving.update(ctx, instances);                       // refit
//
// build_* record the build, submit it and wait: the result is ready to trace when they return.
// Static BLASes are compacted by default (BuildOptions::compact): the copy is what stays.
// Inputs are checked by the scene's rules (scene/geometry.hpp): a bad box, vertex or transform
// throws InvalidGeometryError, an index past 24 bits DeviceLimitError, other misuse UsageError.
#pragma once

#include <proceduray/scene/device_limits.hpp>
#include <proceduray/scene/geometry.hpp>
#include <proceduray/vk/buffer.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace proceduray::vk {

/// An acceleration structure and the buffer that stores it.
class AccelerationStructure {
 public:
  AccelerationStructure() = default;
  AccelerationStructure(const Context& ctx, VkAccelerationStructureTypeKHR type, VkDeviceSize size);

  VkAccelerationStructureKHR get() const noexcept { return m_handle.get(); }
  VkDeviceAddress address() const noexcept { return m_address; }
  VkDeviceSize size() const noexcept { return m_storage.size(); }

 private:
  Buffer m_storage;  // declared before the handle: the handle is destroyed first
  DeviceHandle<VkAccelerationStructureKHR> m_handle;
  VkDeviceAddress m_address = 0;
};

/// One geometry of a BLAS: axis-aligned boxes in object space, each one procedural primitive.
struct AabbGeometry {
  std::span<const VkAabbPositionsKHR> boxes;  ///< at least one box, min <= max, all finite
  bool opaque = true;                         ///< true: any-hit shaders are skipped
};

/// One geometry of a triangle BLAS: positions and a triangle list.
struct TriangleGeometry {
  std::span<const glm::vec3> vertices;     ///< positions, finite
  std::span<const std::uint32_t> indices;  ///< three per triangle, each < vertices.size()
  bool opaque = true;                      ///< true: any-hit shaders are skipped
};

/// How a structure is built.
struct BuildOptions {
  bool compact = true;        ///< compact after building (BLAS only; ignored with allow_update); default on
  bool allow_update = false;  ///< keep it refittable with update(); default off
  bool fast_trace = true;     ///< prefer trace speed over build speed; default on
};

/// One instance of a BLAS in the TLAS.
struct Instance {
  const AccelerationStructure* blas = nullptr;  ///< required
  glm::mat4 transform{1.0f};                    ///< object to world; the last row must be (0, 0, 0, 1)
  std::uint32_t custom_index = 0;               ///< gl_InstanceCustomIndexEXT, 24 bits
  std::uint32_t sbt_offset = 0;                 ///< instanceShaderBindingTableRecordOffset, 24 bits
  std::uint8_t mask = 0xFF;                     ///< visibility mask tested against the ray's cull mask
  VkGeometryInstanceFlagsKHR flags = 0;         ///< e.g. VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR
};

inline AccelerationStructure::AccelerationStructure(const Context& ctx, VkAccelerationStructureTypeKHR type,
                                                    VkDeviceSize size)
    : m_storage(ctx, size,
                VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                Buffer::device_local) {
  auto info = make<VkAccelerationStructureCreateInfoKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR);
  info.buffer = m_storage.get();
  info.size = size;
  info.type = type;
  VkAccelerationStructureKHR raw = VK_NULL_HANDLE;
  check(ctx.rt().create_acceleration_structure(ctx.device(), &info, nullptr, &raw), "vkCreateAccelerationStructureKHR");
  m_handle = own(ctx.device(), raw, ctx.rt().destroy_acceleration_structure);
  auto where = make<VkAccelerationStructureDeviceAddressInfoKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR);
  where.accelerationStructure = raw;
  m_address = ctx.rt().get_acceleration_structure_device_address(ctx.device(), &where);
}

namespace detail {

inline VkBuildAccelerationStructureFlagsKHR build_flags(const BuildOptions& options, bool may_compact) {
  VkBuildAccelerationStructureFlagsKHR flags = options.fast_trace ? VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR
                                                                  : VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_BUILD_BIT_KHR;
  if (options.allow_update) flags |= VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_UPDATE_BIT_KHR;
  else if (options.compact && may_compact) flags |= VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_COMPACTION_BIT_KHR;
  return flags;
}

/// A scratch buffer whose device address honours minAccelerationStructureScratchOffsetAlignment (128 on the H100).
struct Scratch {
  Buffer buffer;
  VkDeviceAddress address = 0;
  Scratch() = default;
  Scratch(const Context& ctx, VkDeviceSize size) {
    const VkDeviceSize align = ctx.scratch_alignment();
    buffer = Buffer(ctx, size + align, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                    Buffer::device_local);
    address = (buffer.address() + align - 1) / align * align;
  }
};

/// Copies `source` into a structure of its compacted size and returns the copy.
inline AccelerationStructure compact(const Context& ctx, const AccelerationStructure& source,
                                     VkAccelerationStructureTypeKHR type) {
  auto query_info = make<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
  query_info.queryType = VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR;
  query_info.queryCount = 1;
  VkQueryPool raw_pool = VK_NULL_HANDLE;
  check(vkCreateQueryPool(ctx.device(), &query_info, nullptr, &raw_pool), "vkCreateQueryPool");
  auto pool = own(ctx.device(), raw_pool, vkDestroyQueryPool);
  VkAccelerationStructureKHR handle = source.get();
  ctx.submit([&](VkCommandBuffer cmd) {
    vkCmdResetQueryPool(cmd, raw_pool, 0, 1);
    ctx.rt().cmd_write_acceleration_structures_properties(
        cmd, 1, &handle, VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR, raw_pool, 0);
  });
  VkDeviceSize compacted = 0;
  check(vkGetQueryPoolResults(ctx.device(), raw_pool, 0, 1, sizeof compacted, &compacted, sizeof compacted,
                              VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
        "vkGetQueryPoolResults", "compacted acceleration structure size");
  AccelerationStructure result(ctx, type, compacted);
  auto copy = make<VkCopyAccelerationStructureInfoKHR>(VK_STRUCTURE_TYPE_COPY_ACCELERATION_STRUCTURE_INFO_KHR);
  copy.src = source.get();
  copy.dst = result.get();
  copy.mode = VK_COPY_ACCELERATION_STRUCTURE_MODE_COMPACT_KHR;
  ctx.submit([&](VkCommandBuffer cmd) { ctx.rt().cmd_copy_acceleration_structure(cmd, &copy); });
  return result;
}

/// Makes a recorded build's writes visible to `readers` (later builds that reference it, traces).
inline void after_build_barrier(VkCommandBuffer cmd, VkPipelineStageFlags readers) {
  auto barrier = make<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
  barrier.srcAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;
  barrier.dstAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR, readers, 0, 1, &barrier, 0, nullptr,
                       0, nullptr);
}

/// Sizes the structure, creates it and a scratch buffer, builds it and waits; compacts when the flags allow.
inline AccelerationStructure build_acceleration_structure(const Context& ctx, VkAccelerationStructureTypeKHR type,
                                                          std::span<const VkAccelerationStructureGeometryKHR> geometries,
                                                          std::span<const std::uint32_t> primitive_counts,
                                                          VkBuildAccelerationStructureFlagsKHR flags) {
  auto build = make<VkAccelerationStructureBuildGeometryInfoKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR);
  build.type = type;
  build.flags = flags;
  build.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
  build.geometryCount = static_cast<std::uint32_t>(geometries.size());
  build.pGeometries = geometries.data();
  auto sizes = make<VkAccelerationStructureBuildSizesInfoKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR);
  ctx.rt().get_acceleration_structure_build_sizes(ctx.device(), VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &build,
                                                  primitive_counts.data(), &sizes);
  AccelerationStructure result(ctx, type, sizes.accelerationStructureSize);
  Scratch scratch(ctx, sizes.buildScratchSize);
  build.dstAccelerationStructure = result.get();
  build.scratchData.deviceAddress = scratch.address;
  std::vector<VkAccelerationStructureBuildRangeInfoKHR> ranges(primitive_counts.size());
  for (std::size_t i = 0; i < ranges.size(); ++i) ranges[i].primitiveCount = primitive_counts[i];
  const VkAccelerationStructureBuildRangeInfoKHR* range_ptr = ranges.data();
  ctx.submit([&](VkCommandBuffer cmd) { ctx.rt().cmd_build_acceleration_structures(cmd, 1, &build, &range_ptr); });
  if ((flags & VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_COMPACTION_BIT_KHR) != 0) return compact(ctx, result, type);
  return result;
}

}  // namespace detail

namespace detail {

/// A BLAS's inputs on the device: boxes or vertices (and indices), described for a build.
/// Host-visible, so a refit rewrites them in place.
struct BlasInput {
  Buffer data;     ///< VkAabbPositionsKHR, or vertices
  Buffer indices;  ///< triangles only
  std::vector<VkAccelerationStructureGeometryKHR> geometries;
  std::vector<std::uint32_t> counts;  ///< primitives per geometry
};

/// The scene's box for Vulkan's (same six floats, same order).
inline Aabb to_aabb(const VkAabbPositionsKHR& b) { return {{b.minX, b.minY, b.minZ}, {b.maxX, b.maxY, b.maxZ}}; }

/// Throws UsageError for an empty list, InvalidGeometryError for a geometry without boxes or a box
/// that is not one (the scene's rule, proceduray::validate(Aabb)).
inline void check_aabbs(std::span<const AabbGeometry> geometries, std::string_view operation) {
  if (geometries.empty()) {
    throw UsageError(std::string(operation) + ": no geometries given; pass at least one AabbGeometry");
  }
  for (std::size_t g = 0; g < geometries.size(); ++g) {
    if (geometries[g].boxes.empty()) {
      throw InvalidGeometryError(std::string(operation) + ": geometry " + std::to_string(g) +
                                 " has no boxes; give it at least one AABB");
    }
    for (std::size_t i = 0; i < geometries[g].boxes.size(); ++i) {
      const Aabb box = to_aabb(geometries[g].boxes[i]);
      if (!proceduray::detail::valid_box(box)) {
        proceduray::validate(box, std::string(operation) + ": geometry " + std::to_string(g) + " box " +
                                      std::to_string(i));  // throws
      }
    }
  }
}

/// Throws UsageError for an empty list, InvalidGeometryError for a bad triangle list or a non-finite vertex.
inline void check_triangles(std::span<const TriangleGeometry> geometries, std::string_view operation) {
  if (geometries.empty()) {
    throw UsageError(std::string(operation) + ": no geometries given; pass at least one TriangleGeometry");
  }
  for (std::size_t g = 0; g < geometries.size(); ++g) {
    const TriangleGeometry& t = geometries[g];
    auto which = [&] { return std::string(operation) + ": triangle geometry " + std::to_string(g); };
    if (t.indices.empty() || t.indices.size() % 3 != 0) {
      throw InvalidGeometryError(which() + " has " + std::to_string(t.indices.size()) +
                                 " indices; a triangle list needs a non-zero multiple of 3");
    }
    for (std::uint32_t i : t.indices) {
      if (i >= t.vertices.size()) {
        throw InvalidGeometryError(which() + " indexes vertex " + std::to_string(i) + " but has " +
                                   std::to_string(t.vertices.size()) + " vertices; fix the index buffer");
      }
    }
    for (const glm::vec3& v : t.vertices) {
      if (!proceduray::detail::finite(v)) {
        throw InvalidGeometryError(which() + " has a non-finite vertex; give finite positions");
      }
    }
  }
}

/// Writes boxes into `input` (laid out by aabb_input for the same counts).
inline void write_aabbs(BlasInput& input, std::span<const AabbGeometry> geometries) {
  VkDeviceSize offset = 0;
  for (const AabbGeometry& g : geometries) {
    input.data.write(g.boxes, offset);
    offset += g.boxes.size_bytes();
  }
}

/// Writes vertices into `input` (laid out by triangle_input for the same counts).
inline void write_vertices(BlasInput& input, std::span<const TriangleGeometry> geometries) {
  VkDeviceSize offset = 0;
  for (const TriangleGeometry& t : geometries) {
    input.data.write(t.vertices, offset);
    offset += t.vertices.size_bytes();
  }
}

/// Checks, uploads and describes procedural geometries.
inline BlasInput aabb_input(const Context& ctx, std::span<const AabbGeometry> geometries, std::string_view operation) {
  check_aabbs(geometries, operation);
  std::size_t total = 0;
  for (const AabbGeometry& g : geometries) total += g.boxes.size();
  BlasInput in;
  in.data = Buffer(ctx, total * sizeof(VkAabbPositionsKHR),
                   VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
                       VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT);
  write_aabbs(in, geometries);
  VkDeviceSize offset = 0;
  for (const AabbGeometry& g : geometries) {
    auto geometry = make<VkAccelerationStructureGeometryKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR);
    geometry.geometryType = VK_GEOMETRY_TYPE_AABBS_KHR;
    geometry.flags = g.opaque ? VK_GEOMETRY_OPAQUE_BIT_KHR : 0;
    geometry.geometry.aabbs = make<VkAccelerationStructureGeometryAabbsDataKHR>(
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_AABBS_DATA_KHR);
    geometry.geometry.aabbs.data.deviceAddress = in.data.address() + offset;
    geometry.geometry.aabbs.stride = sizeof(VkAabbPositionsKHR);
    in.geometries.push_back(geometry);
    in.counts.push_back(static_cast<std::uint32_t>(g.boxes.size()));
    offset += g.boxes.size_bytes();
  }
  return in;
}

/// Checks, uploads and describes triangle geometries.
inline BlasInput triangle_input(const Context& ctx, std::span<const TriangleGeometry> geometries,
                                std::string_view operation) {
  check_triangles(geometries, operation);
  std::size_t vertex_count = 0, index_count = 0;
  for (const TriangleGeometry& t : geometries) {
    vertex_count += t.vertices.size();
    index_count += t.indices.size();
  }
  constexpr VkBufferUsageFlags usage = VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
                                       VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
  BlasInput in;
  in.data = Buffer(ctx, vertex_count * sizeof(glm::vec3), usage);
  in.indices = Buffer(ctx, index_count * sizeof(std::uint32_t), usage);
  write_vertices(in, geometries);
  VkDeviceSize vertex_offset = 0, index_offset = 0;
  for (const TriangleGeometry& t : geometries) {
    in.indices.write(t.indices, index_offset);
    auto geometry = make<VkAccelerationStructureGeometryKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR);
    geometry.geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
    geometry.flags = t.opaque ? VK_GEOMETRY_OPAQUE_BIT_KHR : 0;
    auto& tri = geometry.geometry.triangles;
    tri = make<VkAccelerationStructureGeometryTrianglesDataKHR>(
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR);
    tri.vertexFormat = VK_FORMAT_R32G32B32_SFLOAT;
    tri.vertexData.deviceAddress = in.data.address() + vertex_offset;
    tri.vertexStride = sizeof(glm::vec3);
    tri.maxVertex = static_cast<std::uint32_t>(t.vertices.size() - 1);
    tri.indexType = VK_INDEX_TYPE_UINT32;
    tri.indexData.deviceAddress = in.indices.address() + index_offset;
    in.geometries.push_back(geometry);
    in.counts.push_back(static_cast<std::uint32_t>(t.indices.size() / 3));
    vertex_offset += t.vertices.size_bytes();
    index_offset += t.indices.size_bytes();
  }
  return in;
}

}  // namespace detail

/// Builds a BLAS of procedural geometries (geometry i gets gl_GeometryIndexEXT == i).
inline AccelerationStructure build_blas(const Context& ctx, std::span<const AabbGeometry> geometries,
                                        const BuildOptions& options = {}) {
  const detail::BlasInput in = detail::aabb_input(ctx, geometries, "build_blas");
  return detail::build_acceleration_structure(ctx, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, in.geometries,
                                              in.counts, detail::build_flags(options, true));
}

/// Builds a BLAS of triangle geometries (geometry i gets gl_GeometryIndexEXT == i).
inline AccelerationStructure build_blas(const Context& ctx, std::span<const TriangleGeometry> geometries,
                                        const BuildOptions& options = {}) {
  const detail::BlasInput in = detail::triangle_input(ctx, geometries, "build_blas");
  return detail::build_acceleration_structure(ctx, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, in.geometries,
                                              in.counts, detail::build_flags(options, true));
}

namespace detail {

/// Throws InvalidGeometryError for a non-finite or singular object-to-world matrix: the scene's
/// rule (proceduray::detail::check_transform_at), applied in place; `where` is built only on failure.
template <class Where>
void check_matrix(const glm::mat4& m, Where where) {
  const auto c = proceduray::detail::check_transform_at([&m](int r, int col) { return m[col][r]; });
  if (c.row >= 0 || c.singular) proceduray::validate(instance_transform(m), where());  // throws
}

/// Throws for an instance Vulkan cannot take: no BLAS (UsageError), indices past 24 bits
/// (DeviceLimitError), a non-finite or singular transform (InvalidGeometryError).
inline void check_instance(const Instance& in, std::size_t i, std::string_view operation = "build_tlas") {
  // Built only on failure: a refit checks every instance every frame.
  auto which = [&] { return std::string(operation) + ": instance " + std::to_string(i); };
  if (in.blas == nullptr || in.blas->get() == VK_NULL_HANDLE) {
    throw UsageError(which() + " has no BLAS; set Instance::blas to a built structure");
  }
  if (!fits_instance_field(in.custom_index) || !fits_instance_field(in.sbt_offset)) {
    throw DeviceLimitError(which() + " custom_index " + std::to_string(in.custom_index) + " or sbt_offset " +
                           std::to_string(in.sbt_offset) + " does not fit in 24 bits (at most " +
                           std::to_string(max_instance_sbt_offset) + ": instanceCustomIndex and "
                           "instanceShaderBindingTableRecordOffset are 24-bit fields); use fewer instances or records");
  }
  check_matrix(in.transform, [&] { return which() + " transform"; });
}

/// Packs instances into Vulkan's layout; throws for bad input (check_instance), naming the instance.
inline void pack_instances(std::span<const Instance> instances, std::span<VkAccelerationStructureInstanceKHR> packed,
                           std::string_view operation = "build_tlas") {
  for (std::size_t i = 0; i < instances.size(); ++i) {
    const Instance& in = instances[i];
    check_instance(in, i, operation);
    const glm::mat4& m = in.transform;
    VkAccelerationStructureInstanceKHR& out = packed[i];
    out = {};
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) out.transform.matrix[r][c] = m[c][r];  // glm is column-major, Vulkan row-major 3x4
    out.instanceCustomIndex = in.custom_index;
    out.mask = in.mask;
    out.instanceShaderBindingTableRecordOffset = in.sbt_offset;
    out.flags = in.flags;
    out.accelerationStructureReference = in.blas->address();
  }
}

}  // namespace detail

/// A top-level structure with its instance buffer; refittable when built with allow_update.
class Tlas {
 public:
  Tlas() = default;
  /// Builds over `instances` (an empty list gives a TLAS that every ray misses) and waits.
  Tlas(const Context& ctx, std::span<const Instance> instances, const BuildOptions& options = {})
      : m_count(static_cast<std::uint32_t>(instances.size())), m_flags(detail::build_flags(options, false)),
        m_instances(ctx, std::max<VkDeviceSize>(1, instances.size()) * sizeof(VkAccelerationStructureInstanceKHR),
                    VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
                        VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT) {
    write(instances, "Tlas");
    auto build = info(VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR);
    auto sizes = make<VkAccelerationStructureBuildSizesInfoKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR);
    ctx.rt().get_acceleration_structure_build_sizes(ctx.device(), VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR,
                                                    &build.first, &m_count, &sizes);
    m_structure = AccelerationStructure(ctx, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, sizes.accelerationStructureSize);
    // Kept for refits: an update needs scratch of updateScratchSize, a build of buildScratchSize.
    m_scratch = detail::Scratch(ctx, std::max(sizes.buildScratchSize, sizes.updateScratchSize));
    ctx.submit([&](VkCommandBuffer cmd) { record(ctx, cmd, VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR); });
  }

  const AccelerationStructure& structure() const noexcept { return m_structure; }
  VkAccelerationStructureKHR get() const noexcept { return m_structure.get(); }
  std::uint32_t instance_count() const noexcept { return m_count; }
  bool updatable() const noexcept { return (m_flags & VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_UPDATE_BIT_KHR) != 0; }

  /// Refits for new transforms (same instances, same BLASes): records into `cmd` with a barrier for tracing.
  void record_update(const Context& ctx, VkCommandBuffer cmd, std::span<const Instance> instances) {
    if (!updatable()) {
      throw UsageError("Tlas::update: this TLAS was built without BuildOptions::allow_update; build it with "
                       "allow_update = true to move instances");
    }
    if (instances.size() != m_count) {
      throw UsageError("Tlas::update: " + std::to_string(instances.size()) + " instances given, the TLAS has " +
                       std::to_string(m_count) + "; an update may move instances, not add or remove them "
                       "(build a new Tlas for that)");
    }
    write(instances, "Tlas::update");
    record(ctx, cmd, VK_BUILD_ACCELERATION_STRUCTURE_MODE_UPDATE_KHR);
  }
  /// Rebuilds in place for instances whose BLASes were replaced (same count): records into `cmd`.
  void record_build(const Context& ctx, VkCommandBuffer cmd, std::span<const Instance> instances) {
    if (instances.size() != m_count) {
      throw UsageError("Tlas::record_build: " + std::to_string(instances.size()) +
                       " instances given, the TLAS has " + std::to_string(m_count) +
                       "; build a new Tlas to add or remove instances");
    }
    write(instances, "Tlas::record_build");
    record(ctx, cmd, VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR);
  }
  /// Refits and waits.
  void update(const Context& ctx, std::span<const Instance> instances) {
    ctx.submit([&](VkCommandBuffer cmd) { record_update(ctx, cmd, instances); });
  }

 private:
  std::pair<VkAccelerationStructureBuildGeometryInfoKHR, VkAccelerationStructureGeometryKHR*> info(
      VkBuildAccelerationStructureModeKHR mode) {
    m_geometry = make<VkAccelerationStructureGeometryKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR);
    m_geometry.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
    m_geometry.geometry.instances = make<VkAccelerationStructureGeometryInstancesDataKHR>(
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR);
    m_geometry.geometry.instances.data.deviceAddress = m_instances.address();
    auto build = make<VkAccelerationStructureBuildGeometryInfoKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR);
    build.type = VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR;
    build.flags = m_flags;
    build.mode = mode;
    build.geometryCount = 1;
    build.pGeometries = &m_geometry;
    return {build, &m_geometry};
  }
  void write(std::span<const Instance> instances, std::string_view operation) {
    auto* packed = static_cast<VkAccelerationStructureInstanceKHR*>(m_instances.data());
    detail::pack_instances(instances, {packed, instances.size()}, operation);
  }
  void record(const Context& ctx, VkCommandBuffer cmd, VkBuildAccelerationStructureModeKHR mode) {
    auto build = info(mode).first;
    build.srcAccelerationStructure = mode == VK_BUILD_ACCELERATION_STRUCTURE_MODE_UPDATE_KHR ? m_structure.get()
                                                                                            : VK_NULL_HANDLE;
    build.dstAccelerationStructure = m_structure.get();
    build.scratchData.deviceAddress = m_scratch.address;
    VkAccelerationStructureBuildRangeInfoKHR range{m_count, 0, 0, 0};
    const VkAccelerationStructureBuildRangeInfoKHR* range_ptr = &range;
    ctx.rt().cmd_build_acceleration_structures(cmd, 1, &build, &range_ptr);
    detail::after_build_barrier(cmd, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR);  // traces read it
  }

  std::uint32_t m_count = 0;
  VkBuildAccelerationStructureFlagsKHR m_flags = 0;
  Buffer m_instances;
  AccelerationStructure m_structure;
  detail::Scratch m_scratch;
  VkAccelerationStructureGeometryKHR m_geometry{};
};

/// Builds a TLAS over `instances` and waits (see Tlas for refittable ones).
inline AccelerationStructure build_tlas(const Context& ctx, std::span<const Instance> instances) {
  std::vector<VkAccelerationStructureInstanceKHR> packed(instances.size());
  detail::pack_instances(instances, packed);
  Buffer buffer(ctx, std::max<VkDeviceSize>(1, packed.size()) * sizeof(VkAccelerationStructureInstanceKHR),
                VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
                    VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT);
  buffer.write(std::span<const VkAccelerationStructureInstanceKHR>(packed));
  auto geometry = make<VkAccelerationStructureGeometryKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR);
  geometry.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
  geometry.geometry.instances = make<VkAccelerationStructureGeometryInstancesDataKHR>(
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR);
  geometry.geometry.instances.data.deviceAddress = buffer.address();
  const std::uint32_t count = static_cast<std::uint32_t>(packed.size());
  return detail::build_acceleration_structure(ctx, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, {&geometry, 1},
                                              {&count, 1}, VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR);
}

}  // namespace proceduray::vk
