// Tests for proceduray/shader/device_address.hpp.
#include <proceduray/shader/device_address.hpp>

#include <doctest/doctest.h>

#include <type_traits>

TEST_CASE("a device address is eight aligned bytes") {
  static_assert(sizeof(proceduray::DeviceAddress<float>) == 8);
  CHECK(alignof(proceduray::DeviceAddress<float>) == 8);
  CHECK(std::is_trivially_copyable_v<proceduray::DeviceAddress<float>>);
  CHECK(std::is_standard_layout_v<proceduray::DeviceAddress<float>>);
}

TEST_CASE("a device address is null by default and compares by value") {
  proceduray::DeviceAddress<int> a;
  CHECK_FALSE(static_cast<bool>(a));
  a.value = 64;
  CHECK(static_cast<bool>(a));
  CHECK(a == proceduray::DeviceAddress<int>{64});
  CHECK(a < proceduray::DeviceAddress<int>{128});
}
