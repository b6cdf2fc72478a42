// Tests for proceduray/scene/aabb_glsl.hpp: the scene's boxes as GLSL constants, one copy of the numbers.
#include "proceduray/scene/aabb_glsl.hpp"

#include <doctest/doctest.h>

using namespace proceduray;
using TestSceneInterface = proceduray::ShaderInterface<proceduray::Payload<>, proceduray::RootComponent<>, proceduray::RootArguments<>,
                                   proceduray::Attributes<>>;
using TestScene = proceduray::Scene<TestSceneInterface>;

TEST_CASE("aabb glsl declares each procedural geometry's box under its id") {
  TestScene scene;
  scene.add_geometry("julia", GeometryDesc::procedural({{glm::vec3(-1.5f), glm::vec3(1.5f)}}));
  scene.add_geometry("floor", GeometryDesc::triangles({{{0, 0, 0}, {1, 0, 0}, {0, 0, 1}}, {0, 2, 1}}));
  const Aabb pacman{glm::vec3(-1.0f, -0.25f, -1.0f), glm::vec3(1.0f, 0.75f, 1.0f)};
  scene.add_geometry("pac-man", GeometryDesc::procedural({pacman}));
  CHECK(glsl_aabb_consts(scene) == "#ifndef PROCEDURAY_AABB_CONSTS\n#define PROCEDURAY_AABB_CONSTS\n"
                                   "const vec3 julia_aabb_min = vec3(-1.5, -1.5, -1.5);\n"
                                   "const vec3 julia_aabb_max = vec3(1.5, 1.5, 1.5);\n"
                                   "const vec3 pac_man_aabb_min = vec3(-1.0, -0.25, -1.0);\n"
                                   "const vec3 pac_man_aabb_max = vec3(1.0, 0.75, 1.0);\n"
                                   "#endif\n");
}

TEST_CASE("aabb glsl declares arrays for a geometry of several boxes") {
  TestScene scene;
  const Aabb first{glm::vec3(0.0f), glm::vec3(1.0f)}, second{glm::vec3(2.0f), glm::vec3(3.5f)};
  scene.add_geometry("balls", GeometryDesc::procedural({first, second}));
  CHECK(glsl_aabb_consts(scene) == "#ifndef PROCEDURAY_AABB_CONSTS\n#define PROCEDURAY_AABB_CONSTS\n"
                                   "const uint balls_aabb_count = 2u;\n"
                                   "const vec3 balls_aabb_min[2] = vec3[](vec3(0.0, 0.0, 0.0), vec3(2.0, 2.0, 2.0));\n"
                                   "const vec3 balls_aabb_max[2] = vec3[](vec3(1.0, 1.0, 1.0), vec3(3.5, 3.5, 3.5));\n"
                                   "#endif\n");
}

TEST_CASE("aabb glsl prints floats that read back exactly") {
  TestScene scene;
  const float odd = 0.1f + 0.2f;
  scene.add_geometry("odd", GeometryDesc::procedural({{glm::vec3(-odd), glm::vec3(odd)}}));
  const std::string glsl = glsl_aabb_consts(scene);
  CHECK(glsl.find(glsl_const("odd_aabb_max", glm::vec3(odd))) != std::string::npos);
  CHECK(glsl_aabb_consts(TestScene{}).empty());
}

