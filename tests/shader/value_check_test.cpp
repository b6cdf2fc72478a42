// Tests for proceduray/shader/value_check.hpp: validators found by argument-dependent lookup run
// on every member at any depth, a failure names the path to the member, and types without
// validators are not walked. Also enums as members: GLSL uint, the layout of their underlying type.
#include "proceduray/shader/value_check.hpp"

#include <doctest/doctest.h>

#include "proceduray/shader/field_list.hpp"
#include "proceduray/shader/glsl_codegen.hpp"
#include "proceduray/shader/layout.hpp"

#include <cstdint>
#include <string>
#include <string_view>

namespace value_check_test {
enum class Mode : std::uint32_t { off, on };
struct Gain {
  float value;
  Mode mode;
};
void proceduray_validate(const Gain& g, std::string_view where) {
  if (!(g.value >= 0.0f)) throw proceduray::UsageError(std::string(where) + ": value must be >= 0");
}
PROCEDURAY_STRUCT(Gain, scalar, value, mode);
struct Mixer {
  glm::vec4 tint;
  Gain gains[3];
  Gain master;
};
PROCEDURAY_STRUCT(Mixer, scalar, tint, gains, master);
struct Plain {
  glm::vec4 tint;
  std::uint32_t count;
};
PROCEDURAY_STRUCT(Plain, scalar, tint, count);
}  // namespace value_check_test

using namespace value_check_test;
using proceduray::type_ops;

static_assert(type_ops<Gain>.checked);
static_assert(type_ops<Mixer>.checked && type_ops<Mixer>.validate == nullptr);  // through its members
static_assert(type_ops<Gain[3]>.checked);
static_assert(!type_ops<Plain>.checked && !type_ops<Mode>.checked);
static_assert(type_ops<Mode>.kind == proceduray::TypeKind::scalar && type_ops<Mode>.glsl_name == "uint");

TEST_CASE("check_value runs the validators of members and array elements and names the path") {
  const Gain bad{-1.0f, Mode::on};
  CHECK_THROWS_WITH_AS(type_ops<Gain>.validate(&bad, "gain"), "gain: value must be >= 0", proceduray::UsageError);  // its own
  Mixer m{glm::vec4(1.0f), {{1.0f, Mode::on}, {0.5f, Mode::off}, {2.0f, Mode::on}}, {1.0f, Mode::on}};
  CHECK_NOTHROW(proceduray::check_value(m, "mixer"));
  m.gains[2].value = -1.0f;
  CHECK_THROWS_WITH_AS(proceduray::check_value(m, "mixer"), "mixer.gains[2]: value must be >= 0", proceduray::UsageError);
  m.gains[2].value = 2.0f;
  m.master.value = -0.5f;
  int built = 0;
  CHECK_THROWS_WITH_AS(proceduray::check_value(m, [&] { ++built; return std::string("uniform 'mixer'"); }),
                       "uniform 'mixer'.master: value must be >= 0", proceduray::UsageError);
  CHECK(built == 1);  // the name is built for the failure only
  m.master.value = 1.0f;
  CHECK_NOTHROW(proceduray::check_value(m, [&] { ++built; return std::string("unused"); }));
  CHECK(built == 1);
}

TEST_CASE("an enum member is the GLSL type of its underlying integer, at the same offset") {
  const std::string glsl = proceduray::glsl_declarations(std::span<const proceduray::TypeOps* const>(
                                                             std::array{&type_ops<Gain>}),
                                                         false);
  CHECK(glsl.find("struct Gain {\n    float value;\n    uint mode;\n};") != std::string::npos);
  CHECK(proceduray::matches_host(type_ops<Gain>, proceduray::LayoutRule::scalar));
}
