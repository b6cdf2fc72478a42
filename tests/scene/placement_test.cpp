// Tests for proceduray/scene/placement.hpp: translate * rotate * scale, as glm spells it.
#include "proceduray/scene/placement.hpp"

#include "proceduray/scene/scene.hpp"

#include <doctest/doctest.h>

#include <array>

using namespace proceduray;
using TestSceneInterface = proceduray::ShaderInterface<proceduray::Payload<>, proceduray::RootComponent<>, proceduray::RootArguments<>,
                                   proceduray::Attributes<>>;
using TestScene = proceduray::Scene<TestSceneInterface>;

namespace {
/// Where an instance transform takes a local point.
glm::vec3 apply(const InstanceTransform& t, glm::vec3 p) {
  const glm::vec4 h(p, 1.0f);
  return {glm::dot(t[0], h), glm::dot(t[1], h), glm::dot(t[2], h)};
}
bool near(glm::vec3 a, glm::vec3 b) { return glm::all(glm::lessThan(glm::abs(a - b), glm::vec3(1e-5f))); }
}  // namespace

TEST_CASE("placement scales then moves a point") {
  constexpr Placement p{.translation = {1.0f, 2.0f, 3.0f}, .scale = 0.5f};
  CHECK(near(apply(p.transform(), {0, 0, 0}), {1, 2, 3}));
  CHECK(near(apply(p.transform(), {2, 0, 0}), {2, 2, 3}));
  CHECK(p.transform() == instance_transform(glm::scale(glm::translate(glm::mat4(1.0f), {1, 2, 3}), glm::vec3(0.5f))));
  CHECK(Placement{}.transform() == identity_transform());
}

TEST_CASE("placement rotates about its axis before it moves") {
  const Placement p{.translation = {0.0f, 0.0f, 5.0f}, .scale = 2.0f, .axis = {0, 1, 0}, .degrees = 90.0f};
  // +x scaled to 2, turned 90 degrees about +y to -z, then moved by +5 z.
  CHECK(near(apply(p.transform(), {1, 0, 0}), {0, 0, 3}));
  CHECK(near(apply(p.transform(), {0, 1, 0}), {0, 2, 5}));
}

TEST_CASE("transforms keeps the placements order") {
  const std::array<Placement, 2> ps{Placement{.translation = {-1, 0, 0}}, Placement{.translation = {4, 0, 0}}};
  const std::vector<InstanceTransform> ts = transforms(ps);
  REQUIRE(ts.size() == 2);
  CHECK(near(apply(ts[0], {}), {-1, 0, 0}));
  CHECK(near(apply(ts[1], {}), {4, 0, 0}));
}

TEST_CASE("a zero scale placement is rejected by the geometry naming the instance") {
  TestScene scene;
  const Placement flat{.scale = 0.0f};
  const GeometryDesc desc = GeometryDesc::procedural({Aabb{}}, transforms(std::array{Placement{}, flat}));
  CHECK_THROWS_WITH_AS(scene.add_geometry("flat", desc),
                       doctest::Contains("geometry \"flat\" instance 1 transform is singular"), InvalidGeometryError);
}
