// shader/lights.hpp: the light block's checks and the GLSL layout the shading library reads.
#include <proceduray/shader/glsl_codegen.hpp>
#include <proceduray/shader/lights.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace proceduray;

TEST_CASE("lights make_lights keeps point lights, normalises directions and counts them") {
  const Lights l = make_lights({point_light({0, 4, 2}, glm::vec3(1.0f)), directional_light({0, 3, 4}, glm::vec3(0.5f))});
  CHECK(l.count == 2u);
  CHECK(l.light[0].kind == light_point);
  CHECK(l.light[0].position == glm::vec3(0, 4, 2));
  CHECK(l.light[1].kind == light_directional);
  CHECK(l.light[1].position.y == doctest::Approx(0.6f));  // (0, 3, 4) / 5
  CHECK(l.light[1].position.z == doctest::Approx(0.8f));
}

TEST_CASE("lights the GLSL struct is the C++ layout: lights.glsl reads kind, position, colour and count") {
  const TypeOps* roots[] = {&type_ops<Lights>};
  const std::string glsl = glsl_declarations(std::span<const TypeOps* const>(roots), false);
  CHECK(glsl.find("struct Light {") != std::string::npos);
  CHECK(glsl.find("Light light[4];") != std::string::npos);
  CHECK(glsl.find("uint count;") != std::string::npos);
  static_assert(sizeof(Light) == 32);  // scalar: vec3 + uint + vec3 + float
  static_assert(sizeof(Lights) == 4 * 32 + 16);
}

TEST_CASE("lights bad input: none, too many, NaN, zero direction, negative colour, unknown kind") {
  CHECK_THROWS_WITH_AS(make_lights(std::vector<Light>{}), doctest::Contains("make_lights: 0 lights; shading needs at least one"),
                       UsageError);
  const std::vector<Light> five(max_lights + 1, point_light(glm::vec3(0), glm::vec3(1)));
  CHECK_THROWS_WITH_AS(make_lights(five), doctest::Contains("5 lights, over the limit of 4"), UsageError);
  CHECK_THROWS_WITH_AS(make_lights({point_light(glm::vec3(NAN), glm::vec3(1))}),
                       doctest::Contains("light 0 has a non-finite"), UsageError);
  CHECK_THROWS_WITH_AS(make_lights({point_light(glm::vec3(0), glm::vec3(1)), directional_light(glm::vec3(0), glm::vec3(1))}),
                       doctest::Contains("light 1 is directional with a zero direction"), UsageError);
  CHECK_THROWS_WITH_AS(make_lights({point_light(glm::vec3(0), glm::vec3(-1, 0, 0))}),
                       doctest::Contains("light 0 has a negative colour"), UsageError);
  Light odd = point_light(glm::vec3(0), glm::vec3(1));
  odd.kind = 7;
  CHECK_THROWS_WITH_AS(make_lights({odd}), doctest::Contains("light 0 has kind 7"), UsageError);
}
