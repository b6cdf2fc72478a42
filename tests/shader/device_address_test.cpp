// Tests for proceduray/shader/device_address.hpp.
#include <proceduray/shader/device_address.hpp>

#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <type_traits>

// The layout the GPU reads is fixed at compile time: eight bytes, eight-aligned, copyable as bytes.
static_assert(sizeof(proceduray::DeviceAddress<float>) == 8);
static_assert(alignof(proceduray::DeviceAddress<float>) == 8);
static_assert(std::is_trivially_copyable_v<proceduray::DeviceAddress<float>>);
static_assert(std::is_standard_layout_v<proceduray::DeviceAddress<float>>);

TEST_CASE("a device address's bytes are its value's as a buffer_reference reads them") {
  const std::uint64_t value = 0x0123'4567'89ab'cdefull;
  proceduray::DeviceAddress<float> a;
  a.value = value;
  unsigned char bytes[8];
  std::memcpy(bytes, &a, sizeof a);
  CHECK(std::memcmp(bytes, &value, sizeof value) == 0);
  proceduray::DeviceAddress<float> back;
  std::memcpy(&back, bytes, sizeof back);
  CHECK(back.value == value);
}

TEST_CASE("a device address is null by default and compares by value") {
  proceduray::DeviceAddress<int> a;
  CHECK_FALSE(static_cast<bool>(a));
  a.value = 64;
  CHECK(static_cast<bool>(a));
  CHECK(a == proceduray::DeviceAddress<int>{64});
  CHECK(a < proceduray::DeviceAddress<int>{128});
}
