// Acceleration structures: the handle and its storage, the one build primitive (N builds or
// updates in one command), and bottom-level builds over boxes or triangles, alone or batched.
//
//   VkAabbPositionsKHR box{-1, -1, -1, 1, 1, 1};
//   const proceduray::vk::AabbGeometry boxes{.boxes = {&box, 1}};
//   auto blas = proceduray::vk::build_blas(ctx, {&boxes, 1});                              // boxes
//
//   const glm::vec3 quad[] = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
//   const std::uint32_t tris[] = {0, 1, 2, 0, 2, 3};
//   const proceduray::vk::TriangleGeometry mesh{.vertices = quad, .indices = tris};
//   auto plane = proceduray::vk::build_blas(ctx, {&mesh, 1}, {.compact = false});        // triangles
//   const proceduray::vk::BlasGeometries both[] = {{.boxes = {&boxes, 1}}, {.triangles = {&mesh, 1}}};
//   std::vector<proceduray::vk::AccelerationStructure> all = proceduray::vk::build_blases(ctx, both);
//   blas.address();                                 // for a TLAS instance (vk/tlas.hpp)
//
// build_blas(es) record the builds, submit and wait: the results are ready to trace when they
// return. Static BLASes are compacted by default (BuildOptions::compact): the copy is what stays.
// A batch costs two submits whatever its size (build and size query, then compaction); one
// without compaction. detail::record_builds is the primitive: the TLAS (tlas.hpp) and
// RefittableBlas record their builds and updates with it too.
// Geometry is checked by blas_input.hpp (InvalidGeometryError, UsageError).
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/vk/blas_input.hpp>
#include <proceduray/vk/buffer.hpp>

#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
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

/// How a structure is built.
struct BuildOptions {
  bool compact = true;        ///< compact after building (BLAS only; ignored with allow_update); default on
  bool allow_update = false;  ///< keep it refittable with update(); default off
  bool fast_trace = true;     ///< prefer trace speed over build speed; default on
  /// The input comes from a Plan (SceneAcceleration), whose boxes, meshes and transforms were
  /// checked where the user gave them: they are not checked again. Default off.
  bool planned = false;
};

namespace detail {

PROCEDURAY_DECL VkBuildAccelerationStructureFlagsKHR build_flags(const BuildOptions& options, bool may_compact);

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

/// Makes a recorded build's writes visible to `readers` (later builds that reference it, traces).
PROCEDURAY_DECL void after_build_barrier(VkCommandBuffer cmd, VkPipelineStageFlags readers);

/// One structure to build (or update) in a batch: its type, flags, geometries, and where it goes.
struct BuildCommand {
  VkAccelerationStructureTypeKHR type = VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR;
  VkBuildAccelerationStructureFlagsKHR flags = 0;
  VkBuildAccelerationStructureModeKHR mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
  std::span<const VkAccelerationStructureGeometryKHR> geometries;
  std::span<const std::uint32_t> counts;            ///< primitives (or instances) per geometry
  VkAccelerationStructureKHR dst = VK_NULL_HANDLE;  ///< an update reads and writes it in place
  VkDeviceAddress scratch = 0;                      ///< its own scratch: builds of one batch run together
};

/// Vulkan's description of `c`.
PROCEDURAY_DECL VkAccelerationStructureBuildGeometryInfoKHR geometry_info(const BuildCommand& c);

/// The structure and scratch sizes a build of `c` needs (its mode, destination and scratch ignored).
PROCEDURAY_DECL VkAccelerationStructureBuildSizesInfoKHR build_sizes(const Context& ctx, const BuildCommand& c);

/// The build primitive: records every build or update of `builds` with one
/// vkCmdBuildAccelerationStructuresKHR, then one barrier that makes them visible to `readers`.
/// Used by build_blas(es), build_tlas, Tlas and RefittableBlas.
PROCEDURAY_DECL void record_builds(const Context& ctx, VkCommandBuffer cmd, std::span<const BuildCommand> builds,
                                   VkPipelineStageFlags readers);

/// Scratch for every build of a batch in one buffer, each part aligned; `scratch(i)` is build i's.
struct BatchScratch {
  Scratch buffer;
  std::vector<VkDeviceSize> offsets;
  BatchScratch(const Context& ctx, std::span<const VkDeviceSize> sizes) {
    const VkDeviceSize align = ctx.scratch_alignment();
    VkDeviceSize total = 0;
    for (VkDeviceSize size : sizes) {
      offsets.push_back(total);
      total += (std::max<VkDeviceSize>(size, 1) + align - 1) / align * align;
    }
    buffer = Scratch(ctx, std::max<VkDeviceSize>(total, 1));
  }
  VkDeviceAddress scratch(std::size_t i) const { return buffer.address + offsets[i]; }
};

/// Copies each structure into one of its compacted size, in one submit; the caller's submit built
/// `built` and wrote their compacted sizes into `pool` (queries 0..n-1).
PROCEDURAY_DECL std::vector<AccelerationStructure> compact_all(const Context& ctx, std::span<const AccelerationStructure> built,
                                                               VkAccelerationStructureTypeKHR type, VkQueryPool pool);

/// Creates and builds one structure per command (all of one type and flags) in one submit and
/// waits. With ALLOW_COMPACTION the compacted sizes are queried in that submit and every
/// structure is compacted in a second: two submits for any number of structures.
PROCEDURAY_DECL std::vector<AccelerationStructure> build_structures(const Context& ctx, std::vector<BuildCommand> commands);

}  // namespace detail

/// The geometries of one BLAS of a batch: boxes or triangles (one of the two lists, not both).
struct BlasGeometries {
  std::span<const AabbGeometry> boxes;
  std::span<const TriangleGeometry> triangles;
};

/// Builds every BLAS of `blases` (geometry i of each gets gl_GeometryIndexEXT == i) and waits:
/// one submit builds them all and, with BuildOptions::compact, queries their compacted sizes;
/// a second compacts them all. Throws as build_blas does, naming the BLAS's index.
PROCEDURAY_DECL std::vector<AccelerationStructure> build_blases(const Context& ctx, std::span<const BlasGeometries> blases,
                                                                const BuildOptions& options = {});

/// Builds a BLAS of procedural geometries (geometry i gets gl_GeometryIndexEXT == i) and waits.
PROCEDURAY_DECL AccelerationStructure build_blas(const Context& ctx, std::span<const AabbGeometry> geometries,
                                                 const BuildOptions& options = {});

/// Builds a BLAS of triangle geometries (geometry i gets gl_GeometryIndexEXT == i) and waits.
PROCEDURAY_DECL AccelerationStructure build_blas(const Context& ctx, std::span<const TriangleGeometry> geometries,
                                                 const BuildOptions& options = {});

}  // namespace proceduray::vk

#include "proceduray/vk/acceleration-inl.hpp"  // the bodies (config.hpp)
