#include "proceduray/scene/shader_data.hpp"

#include <doctest/doctest.h>

#include <string>
#include <vector>

using namespace proceduray;

namespace {
struct Plain { float a[4]; unsigned b; };
struct WithString { std::string s; };
struct Virtual { virtual ~Virtual() = default; };
}  // namespace

static_assert(RecordData<Plain>);
static_assert(PayloadData<Plain>);
static_assert(AttributeData<float>);
static_assert(!RecordData<WithString>, "bytes of a std::string mean nothing to a shader");
static_assert(!RecordData<Virtual>);
static_assert(!RecordData<Plain*>, "a host pointer is not a device address");
static_assert(!RecordData<std::vector<int>>);

TEST_CASE("shader_data accepts plain structs only") {
  CHECK(RecordData<Plain>);
  CHECK_FALSE(RecordData<WithString>);
}
