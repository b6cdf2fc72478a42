// Tests for proceduray/scene/field.hpp: a field's checks name the value and the fix, what it
// accepts follows its bound, and the generated intersection shader calls the user's function
// with the bound it declared.
#include "proceduray/scene/field.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

using namespace proceduray;

namespace field_test {

DistanceField gyroid() {
  return {.id = "gyroid", .glsl = "gyroid.glsl", .aabb = {glm::vec3(-1.0f), glm::vec3(1.0f)}, .lipschitz = 1.75f};
}

/// The message validate() throws for `f`, or "" when it accepts it.
std::string refusal(const DistanceField& f) {
  try {
    validate(f, "add_distance_field");
  } catch (const UsageError& e) {
    return e.what();
  }
  return {};
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace field_test

using namespace field_test;

TEST_CASE("field: a valid field passes; the function defaults to <id>_distance") {
  CHECK(refusal(gyroid()).empty());
  CHECK(field_function(gyroid()) == "gyroid_distance");
  DistanceField f = gyroid();
  f.function = "my_field";
  CHECK(field_function(f) == "my_field");
  DistanceField exact{.id = "ball", .glsl = "ball.glsl", .exact = true};
  CHECK(refusal(exact).empty());
  CHECK(field_lipschitz(exact) == 1.0f);
  CHECK(field_lipschitz(gyroid()) == 1.75f);
}

TEST_CASE("field: bad bounds, bounds and names are refused with the value and the fix") {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  DistanceField f = gyroid();
  f.aabb.min.y = nan;
  std::string m = refusal(f);
  CHECK(has(m, "add_distance_field: distance field \"gyroid\""));
  CHECK(has(m, "axis 1"));
  CHECK(has(m, "not finite"));
  f = gyroid();
  f.aabb.min.x = 2.0f;  // above max
  m = refusal(f);
  CHECK(has(m, "[2, 1]"));
  CHECK(has(m, "min must be below max"));
  f = gyroid();
  f.aabb.max.z = -1.0f;  // an empty axis
  CHECK(has(refusal(f), "axis 2"));
  for (float bad : {0.0f, -1.0f, nan, inf}) {
    f = gyroid();
    f.lipschitz = bad;
    m = refusal(f);
    CAPTURE(bad);
    CHECK(has(m, bad == 0.0f ? "has no Lipschitz bound" : "must be a finite number > 0"));
    CHECK(has(m, ".exact"));
  }
  f = gyroid();
  f.exact = true;  // and a bound of 1.75: which one?
  CHECK(has(refusal(f), "drop .exact or the bound"));
  f = gyroid();
  f.glsl = "";
  CHECK(has(refusal(f), "names no GLSL file"));
  f = gyroid();
  f.glsl = "a\"b.glsl";
  CHECK(has(refusal(f), "quote"));
  for (const char* bad : {"2field", "my-field", "sample", "gl_Field", "proceduray_field0"}) {
    f = gyroid();
    f.function = bad;
    CAPTURE(bad);
    CHECK(has(refusal(f), std::string("function '") + bad + "' is no GLSL function name"));
  }
  f = gyroid();
  f.id = "2d";  // the default name <id>_distance is no identifier either
  CHECK(has(refusal(f), "function '2d_distance'"));
  f = gyroid();
  f.iterations = march_max_iterations_limit + 1;
  CHECK(has(refusal(f), "iterations " + std::to_string(march_max_iterations_limit + 1)));
}

TEST_CASE("field: plain sphere steps only where the bound is at most 1; fractals take iterations") {
  const MarchCapabilities wide = field_capabilities(gyroid());
  for (MarchMethod m : wide.methods) CHECK(m != MarchMethod::sphere);
  CHECK(wide.methods.front() == MarchMethod::lipschitz);
  CHECK(wide.max_iterations == 0);
  CHECK_NOTHROW(validate(wide.defaults, wide, "gyroid"));
  MarchKnobs k = wide.defaults;
  k.method = MarchMethod::sphere;
  CHECK_THROWS_WITH_AS(validate(k, wide, "gyroid"), doctest::Contains("method sphere does not apply"), UsageError);
  DistanceField ball{.id = "ball", .glsl = "ball.glsl", .exact = true};
  bool sphere = false;
  for (MarchMethod m : field_capabilities(ball).methods) sphere = sphere || m == MarchMethod::sphere;
  CHECK(sphere);
  DistanceField bulb{.id = "bulb", .glsl = "bulb.glsl", .exact = true, .iterations = 8};
  const MarchCapabilities fractal = field_capabilities(bulb);
  CHECK(fractal.max_iterations == march_max_iterations_limit);
  CHECK(fractal.defaults.iterations == 8);
  CHECK_NOTHROW(validate(fractal.defaults, fractal, "bulb"));
}

TEST_CASE("field: the generated shader includes the file, calls the function and marches with the bound") {
  const std::string s = field_stage_source(gyroid(), 3);
  CHECK(field_stage_name(gyroid()) == "gyroid.field.rint");
  CHECK(s.starts_with("#version 460\n"));
  CHECK(has(s, "#include \"gyroid.glsl\""));
  CHECK(has(s, "#include \"marching/field.glsl\""));
  CHECK(has(s, "#include \"marching/marcher.glsl\""));
  CHECK(has(s, "return gyroid_distance(p);"));
  CHECK(has(s, "proceduray_fields.data[3]"));
  CHECK(has(s, "const float proceduray_field3_lipschitz = 1.75;"));
  CHECK(has(s, "proceduray_field3_lipschitz, fm)"));  // the bound reaches march_settings
  DistanceField bulb{.id = "bulb", .glsl = "bulb.glsl", .function = "bulb_de", .exact = true, .iterations = 8};
  const std::string b = field_stage_source(bulb, 0);
  CHECK(has(b, "return bulb_de(p, iterations);"));
  CHECK(has(b, "const float proceduray_field0_lipschitz = 1.0;"));
  CHECK(!has(b, "bulb_normal"));
  bulb.normal = "bulb_normal";  // the user's exact normal first, differences where it declines
  CHECK(has(field_stage_source(bulb, 0), "if (normal && !bulb_normal(p, iterations, n)) n = proceduray_march0_normal("));
}

TEST_CASE("field: the knobs become specialization constants, one per member, with their bits") {
  const std::string s = field_stage_source(gyroid(), 0);
  // The flag and every member of MarchKnobs, by the registered struct: a new knob needs no edit.
  CHECK(has(s, "layout(constant_id = 2000) const bool proceduray_knobs_specialized = false;"));
  const TypeOps& t = type_ops<MarchKnobs>;
  REQUIRE(t.field_count == sizeof(MarchKnobs) / 4);  // every member one 4-byte constant
  for (std::size_t i = 0; i < t.field_count; ++i) {
    const std::string name = "proceduray_knob_" + std::string(t.fields[i].name);
    CAPTURE(name);
    CHECK(has(s, "layout(constant_id = " + std::to_string(2001 + i) + ") const "));
    CHECK(has(s, " " + name + " = "));
    CHECK(has(s, "k." + std::string(t.fields[i].name) + " = " + name + ";"));
  }
  CHECK(has(s, "f.knobs = proceduray_field_knobs(f.knobs);"));  // before any use of the knobs
  CHECK(s.find("f.knobs = proceduray_field_knobs") < s.find("field_march_begin("));
  MarchKnobs k = march_base_knobs;
  k.method = MarchMethod::relaxed;
  k.relaxation = 1.25f;
  k.probe = 3.0f;
  const std::vector<SpecConstant> c = field_spec_constants(k);
  REQUIRE(c.size() == 1 + t.field_count);
  CHECK(c[0] == SpecConstant{field_spec_id, 1u});
  for (std::size_t i = 0; i < c.size(); ++i) CHECK(c[i].id == field_spec_id + i);
  CHECK(c[1].bits == static_cast<std::uint32_t>(MarchMethod::relaxed));  // method, the first member
  float relaxation = 0.0f, probe = 0.0f;
  std::memcpy(&relaxation, &c[7].bits, 4);  // relaxation, the 7th member
  std::memcpy(&probe, &c[15].bits, 4);      // probe, the last
  CHECK(relaxation == 1.25f);
  CHECK(probe == 3.0f);
}

TEST_CASE("field: a normal function needs a name of its own") {
  DistanceField f = gyroid();
  f.normal = "gyroid_normal";
  CHECK(refusal(f).empty());
  for (const char* bad : {"2n", "gl_Normal", "proceduray_n", "gyroid_distance", "in"}) {
    f.normal = bad;
    CAPTURE(bad);
    CHECK(has(refusal(f), std::string("normal function '") + bad + "' is no GLSL function name of its own"));
  }
}
