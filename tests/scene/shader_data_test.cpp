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

static_assert(RootArgumentsData<Registered>);
static_assert(PayloadData<Registered>);
static_assert(AttributeData<SmallHit>);
static_assert(!RootArgumentsData<Unregistered>, "a plain struct without a field list has no checked GLSL twin");
static_assert(!PayloadData<Unregistered>);
static_assert(!AttributeData<Unregistered>);
static_assert(RootArgumentsData<LargeHit> && !AttributeData<LargeHit>, "hit attributes are at most 32 bytes");
static_assert(!AttributeData<float>, "a scalar is not a registered struct");
static_assert(!RootArgumentsData<WithString>, "bytes of a std::string mean nothing to a shader");
static_assert(!RootArgumentsData<Virtual>);
static_assert(!RootArgumentsData<Registered*>, "a host pointer is not a device address");
static_assert(!RootArgumentsData<std::vector<int>>);

// Everything shader_data.hpp declares is a concept, so the static_asserts above are the test:
// a concept that accepted a wrong type, or refused a right one, stops this file compiling. What a
// user sees when an API refuses a type is checked by compile_fail/unregistered_root_arguments.cpp,
// unregistered_payload.cpp and oversized_attributes.cpp (each asserts the diagnostic text).
static_assert(sizeof(SmallHit) == max_hit_attribute_size / 2 && sizeof(LargeHit) > max_hit_attribute_size,
              "the two hit types straddle the 32-byte limit, so the AttributeData asserts test the bound");
