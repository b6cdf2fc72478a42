// A typed buffer device address: 8 bytes on the host, a GLSL `buffer_reference` on the device.
//
//   struct SphereRecord { proceduray::DeviceAddress<Sphere> spheres; uint32_t count; uint32_t pad; };
//   PROCEDURAY_STRUCT(SphereRecord, scalar, spheres, count, pad);
//   record.spheres = proceduray::DeviceAddress<Sphere>{buffer_address};   // from vkGetBufferDeviceAddress
//   // GLSL: layout(buffer_reference, scalar, buffer_reference_align = 4) buffer SphereRef { Sphere data[]; };
//   //       struct SphereRecord { SphereRef spheres; uint count; uint pad; };   ->  rec.spheres.data[i]
#pragma once

#include <compare>
#include <cstdint>

namespace proceduray {

/// Address of device memory holding an array of T (a registered struct or a GLSL scalar, vector or matrix); 0 = null.
template <class T>
struct alignas(8) DeviceAddress {
  using element_type = T;     ///< what the address points to
  std::uint64_t value = 0;    ///< the VkDeviceAddress; 0 = null

  /// True when the address is not null.
  constexpr explicit operator bool() const { return value != 0; }
  friend constexpr auto operator<=>(const DeviceAddress&, const DeviceAddress&) = default;
};

}  // namespace proceduray
