// The bodies of proceduray/vk/tlas.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/tlas.hpp"

#if PROCEDURAY_BODIES
namespace proceduray::vk::detail {

PROCEDURAY_DECL void check_instance(const Instance& in, std::size_t i, std::string_view operation) {
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

PROCEDURAY_DECL void pack_instances(std::span<const Instance> instances, std::span<VkAccelerationStructureInstanceKHR> packed,
                                    std::string_view operation, bool check) {
  for (std::size_t i = 0; i < instances.size(); ++i) {
    const Instance& in = instances[i];
    if (check) check_instance(in, i, operation);
    VkAccelerationStructureInstanceKHR& out = packed[i];
    out = {};
    static_assert(sizeof(out.transform) == sizeof(in.transform), "InstanceTransform is VkTransformMatrixKHR's layout");
    std::memcpy(&out.transform, &in.transform, sizeof(out.transform));  // rows as they are: no conversion
    out.instanceCustomIndex = in.custom_index;
    out.mask = in.mask;
    out.instanceShaderBindingTableRecordOffset = in.sbt_offset;
    out.flags = in.flags;
    out.accelerationStructureReference = in.blas->address();
  }
}

}  // namespace proceduray::vk::detail

namespace proceduray::vk {

PROCEDURAY_DECL AccelerationStructure build_tlas(const Context& ctx, std::span<const Instance> instances) {
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
  return std::move(detail::build_structures(ctx, {{.type = VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR,
                                                   .flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR,
                                                   .geometries = {&geometry, 1}, .counts = {&count, 1}}})[0]);
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
