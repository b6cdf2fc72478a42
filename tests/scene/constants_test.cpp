// Tests for proceduray/scene/constants.hpp: constants and defines declared on a scene reach every
// stage's declarations, typed, and their names are checked where they are declared.
#include "proceduray/scene/constants.hpp"

#include <doctest/doctest.h>

#include "proceduray/scene/compile.hpp"
#include "proceduray/scene/glsl_for.hpp"
#include "proceduray/shader/field_list.hpp"

#include <string>

using namespace proceduray;

namespace constants_test {
struct Light {
  glm::vec3 colour;
};
PROCEDURAY_STRUCT(Light, scalar, colour);
using TestScene = Scene<ShaderInterface<Payload<Light>, RootComponent<>, RootArguments<>, Attributes<>>>;

/// One ray, a triangle floor, a raygen: every stage gets the scene's constants.
TestScene floor_scene() {
  TestScene s;
  const auto light = s.add_ray<Light>("light", {.miss = "sky.rmiss"});
  const auto group = s.add_hit_group("floor", {.kind = HitGroupKind::triangles, .closest_hit = "floor.rchit"});
  s.add_geometry("floor", GeometryDesc::triangles({{{0, 0, 0}, {1, 0, 0}, {0, 0, 1}}, {0, 1, 2}}));
  s.add_raygen("main.rgen");
  s.set_default_hit(light, group);
  return s;
}

inline constexpr std::uint32_t flag_shadows = 1u, flag_mirror = 2u;
inline constexpr float exposure = 1.5f;
}  // namespace constants_test

using namespace constants_test;

TEST_CASE("scene constants of every type are declared in every stage, and a define switches code") {
  TestScene s = floor_scene();
  s.add_constant("depth_limit", std::uint32_t{3});
  s.add_constant("offset", std::int32_t{-2});
  s.add_constant("scale", 0.25f);
  s.add_constant("soft", true);
  s.add_constant("origin", glm::vec2(1.0f, -0.5f));
  s.add_constant("sky", glm::vec3(0.4f, 0.6f, 0.9f));
  s.add_constant("tint", glm::vec4(1.0f, 0.5f, 0.25f, 1.0f));
  s.add_define("ITERATIVE");
  PROCEDURAY_SCENE_CONSTANTS(s, flag_shadows, flag_mirror, exposure);
  const Plan plan = compile(s);
  REQUIRE(plan.constants().size() == 11);
  CHECK(plan.constants()[7] == SceneConstant{"ITERATIVE", {}, true});
  CHECK(plan.constants()[8] == SceneConstant{"flag_shadows", std::uint32_t{1}, false});
  for (const PlannedStage& stage : plan.pipeline().stages) {
    CAPTURE(stage.shader);
    const std::string& d = stage.declarations;
    CHECK(d.find("const uint depth_limit = 3u;\n") != std::string::npos);
    CHECK(d.find("const int offset = -2;\n") != std::string::npos);
    CHECK(d.find("const float scale = 0.25;\n") != std::string::npos);
    CHECK(d.find("const bool soft = true;\n") != std::string::npos);
    CHECK(d.find("const vec2 origin = vec2(1.0, -0.5);\n") != std::string::npos);
    CHECK(d.find("const vec3 sky = vec3(0.4, 0.6, 0.9);\n") != std::string::npos);
    CHECK(d.find("const vec4 tint = vec4(1.0, 0.5, 0.25, 1.0);\n") != std::string::npos);
    CHECK(d.find("#define ITERATIVE 1\n") != std::string::npos);
    CHECK(d.find("const uint flag_shadows = 1u;\n") != std::string::npos);
    CHECK(d.find("const uint flag_mirror = 2u;\n") != std::string::npos);
    CHECK(d.find("const float exposure = 1.5;\n") != std::string::npos);
  }
  // Constants are part of the plan's value.
  TestScene other = floor_scene();
  other.add_constant("depth_limit", std::uint32_t{4});
  CHECK(compile(other) != compile(floor_scene()));
}

TEST_CASE("scene constant names are checked where they are declared") {
  TestScene s = floor_scene();
  s.add_layer("casts_shadow");
  CHECK_THROWS_WITH_AS(s.add_constant("max depth", std::uint32_t{3}),
                       doctest::Contains("Scene::add_constant: \"max depth\" is no GLSL name (letters, digits and '_', "
                                         "not starting with a digit); use \"max_depth\""),
                       SceneError);
  CHECK_THROWS_WITH_AS(s.add_define(""), doctest::Contains("Scene::add_define: \"\" is no GLSL name"), SceneError);
  CHECK_THROWS_WITH_AS(s.add_constant("sample", 1.0f), doctest::Contains("a GLSL reserved word"), SceneError);
  CHECK_THROWS_WITH_AS(s.add_constant("payload", 1.0f), doctest::Contains("payload"), SceneError);
  // Names other entities declare: a ray's constants, a layer's bit.
  CHECK_THROWS_WITH_AS(s.add_constant("light_ray", std::uint32_t{7}), doctest::Contains("light_ray"), DuplicateIdError);
  CHECK_THROWS_WITH_AS(s.add_define("layer_casts_shadow"), doctest::Contains("layer_casts_shadow"), DuplicateIdError);
  s.add_constant("exposure", 2.0f);
  std::string what;
  try {
    s.add_define("exposure");
  } catch (const DuplicateIdError& e) {
    what = e.what();
  }
  CHECK_MESSAGE(what.find("Scene::add_define: define \"exposure\"") != std::string::npos, what);
  CHECK_MESSAGE(what.find("constant \"exposure\"") != std::string::npos, what);
  CHECK(s.constants().size() == 1);  // every refused name left the scene as it was
}

TEST_CASE("a ray registered after a constant of the same GLSL name is caught by compile") {
  TestScene s = floor_scene();
  s.add_constant("shadow_ray", std::uint32_t{9});
  const auto shadow = s.add_ray<Light>("shadow", {.miss = "shadow.rmiss"});  // declares shadow_ray too
  s.set_default_hit(shadow, s.hit_group_id("floor"));
  CHECK_THROWS_WITH_AS(compile(s), doctest::Contains("shadow_ray"), DuplicateIdError);
}
