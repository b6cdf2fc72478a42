#include "proceduray/scene/shader_data.hpp"

#include <doctest/doctest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "proceduray/shader/field_list.hpp"

using namespace proceduray;

namespace {
struct Registered { float a[4]; std::uint32_t b; };
PROCEDURAY_STRUCT(Registered, scalar, a, b);
struct Unregistered { float a[4]; std::uint32_t b; };
struct SmallHit { glm::vec3 normal; float t; };
PROCEDURAY_STRUCT(SmallHit, scalar, normal, t);
struct LargeHit { glm::vec4 normal; glm::vec4 tangent; float t; };
PROCEDURAY_STRUCT(LargeHit, scalar, normal, tangent, t);
struct WithString { std::string s; };
struct Virtual { virtual ~Virtual() = default; };
}  // namespace

static_assert(RecordData<Registered>);
static_assert(PayloadData<Registered>);
static_assert(AttributeData<SmallHit>);
static_assert(!RecordData<Unregistered>, "a plain struct without a field list has no checked GLSL twin");
static_assert(!PayloadData<Unregistered>);
static_assert(!AttributeData<Unregistered>);
static_assert(RecordData<LargeHit> && !AttributeData<LargeHit>, "hit attributes are at most 32 bytes");
static_assert(!AttributeData<float>, "a scalar is not a registered struct");
static_assert(!RecordData<WithString>, "bytes of a std::string mean nothing to a shader");
static_assert(!RecordData<Virtual>);
static_assert(!RecordData<Registered*>, "a host pointer is not a device address");
static_assert(!RecordData<std::vector<int>>);

TEST_CASE("shader_data accepts registered structs only") {
  CHECK(RecordData<Registered>);
  CHECK_FALSE(RecordData<Unregistered>);
  CHECK_FALSE(RecordData<WithString>);
}

TEST_CASE("shader_data attributes fit the guaranteed hit attribute size") {
  CHECK(sizeof(SmallHit) == max_hit_attribute_size / 2);
  CHECK(AttributeData<SmallHit>);
  CHECK(sizeof(LargeHit) > max_hit_attribute_size);
  CHECK_FALSE(AttributeData<LargeHit>);
}
