// scene/layers.hpp: named layers as instance-mask bits, and the scene's masks per instance.
#include <proceduray/scene/compile.hpp>
#include <proceduray/scene/glsl_for.hpp>
#include <proceduray/scene/layers.hpp>
#include <proceduray/shader/field_list.hpp>

#include <doctest/doctest.h>

#include <string>

using namespace proceduray;

namespace layers_test {
struct Light {
  float value;
};
PROCEDURAY_STRUCT(Light, scalar, value);
using TestSceneInterface = proceduray::ShaderInterface<proceduray::Payload<Light>, proceduray::RootComponent<>, proceduray::RootArguments<>,
                                   proceduray::Attributes<>>;
using TestScene = proceduray::Scene<TestSceneInterface>;
}  // namespace layers_test
using layers_test::TestScene;

TEST_CASE("layers give each name its own bit and masks are unions") {
  Layers layers;
  CHECK(layers.add("visible") == 0x01);
  CHECK(layers.add("casts_shadow") == 0x02);
  CHECK(layers.add("reflected") == 0x04);
  CHECK(layers["casts_shadow"] == 0x02);
  CHECK(layers.mask({"visible", "reflected"}) == 0x05);
  CHECK(layers.mask({}) == 0);
  CHECK(layers.size() == 3);
  CHECK(layers.names()[2] == "reflected");
}

TEST_CASE("layers refuse a ninth layer duplicates and unknown names") {
  Layers layers;
  for (int i = 0; i < 8; ++i) {
    std::string name = "l";  // appended, not "l" + ...: g++ 12 -O3 warns falsely (-Wrestrict) on the latter
    name += std::to_string(i);
    CHECK(layers.add(name) == (1 << i));
  }
  CHECK_THROWS_WITH_AS(layers.add("l8"), doctest::Contains("would be the ninth; an instance mask has 8 bits"), SceneError);
  CHECK_THROWS_WITH_AS(layers.add("l0"), doctest::Contains("layer \"l0\" already exists"), DuplicateIdError);
  CHECK_THROWS_WITH_AS(layers.add(""), doctest::Contains("empty layer name"), SceneError);
  CHECK_THROWS_WITH_AS(layers.mask({"l1", "glass"}),
                       doctest::Contains("no layer \"glass\"; the known layers are \"l0\", \"l1\", \"l2\""), UnknownIdError);
}

TEST_CASE("scene layers name the operation and reach the shaders and the instances") {
  TestScene scene;
  CHECK_THROWS_WITH_AS(scene.layer_mask({"visible"}), doctest::Contains("Scene::layer_mask: no layer \"visible\"; the known "
                                                                        "layers are (none)"),
                       UnknownIdError);
  scene.add_layer("visible");
  const std::uint8_t shadow_bit = scene.add_layer("casts shadow");
  CHECK_THROWS_WITH_AS(scene.add_layer("visible"), doctest::Contains("Scene::add_layer: layer \"visible\""), DuplicateIdError);
  auto light = scene.add_ray<layers_test::Light>("light", {.miss = "sky.rmiss"});
  scene.add_ray<layers_test::Light>("shadow", {.miss = "sky.rmiss",
                                               .flags = RayFlags::terminate_on_first_hit | RayFlags::skip_closest_hit,
                                               .cull_mask = shadow_bit});
  auto group = scene.add_hit_group("tri", {.closest_hit = "tri.rchit"});
  const TriangleMesh mesh{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2}};
  GeometryDesc three = GeometryDesc::triangles(mesh, {identity_transform(), identity_transform(), identity_transform()});
  three.instance_masks = {scene.layer_mask({"visible"}), scene.layer_mask({"visible", "casts shadow"}), 0};
  auto g = scene.add_geometry("three", three);
  GeometryDesc one = GeometryDesc::triangles(mesh);
  one.mask = scene.layer_mask({"casts shadow"});
  auto h = scene.add_geometry("one", one);
  auto plain = scene.add_geometry("plain", GeometryDesc::triangles(mesh));
  scene.add_raygen("main.rgen");
  scene.set_default_hit(light, group);
  scene.set_default_hit(scene.ray_id<layers_test::Light>("shadow"), group);
  const Plan sbt = compile(scene);
  const auto instances = sbt.instances();
  CHECK(instances[sbt.tlas_index(g, 0)].mask == 0x01);
  CHECK(instances[sbt.tlas_index(g, 1)].mask == 0x03);
  CHECK(instances[sbt.tlas_index(g, 2)].mask == 0x00);
  CHECK(instances[sbt.tlas_index(h, 0)].mask == 0x02);
  CHECK(instances[sbt.tlas_index(plain, 0)].mask == all_layers);
  const std::string glsl = glsl_for(sbt, ShaderStage::raygen, "main.rgen");
  CHECK(glsl.find("const uint layer_visible = 1u;") != std::string::npos);
  CHECK(glsl.find("const uint layer_casts_shadow = 2u;") != std::string::npos);
  CHECK(glsl.find("const uint light_flags = 0u;") != std::string::npos);
  CHECK(glsl.find("const uint light_mask = 255u;") != std::string::npos);
  CHECK(glsl.find("const uint shadow_flags = 12u;") != std::string::npos);  // terminate on first hit | skip closest hit
  CHECK(glsl.find("const uint shadow_mask = 2u;") != std::string::npos);
}

TEST_CASE("instance masks must match the instances and belong to them") {
  TestScene scene;
  const TriangleMesh mesh{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2}};
  GeometryDesc wrong = GeometryDesc::triangles(mesh, {identity_transform(), identity_transform()});
  wrong.instance_masks = {1};
  CHECK_THROWS_WITH_AS(scene.add_geometry("wrong", wrong),
                       doctest::Contains("geometry \"wrong\" has 1 instance masks for 2 instances"), InvalidGeometryError);
  GeometryDesc first = GeometryDesc::triangles(mesh);
  first.blas = "shared";
  first.mask = 0x04;
  scene.add_geometry("first", first);
  GeometryDesc other_masks = GeometryDesc::triangles(mesh);
  other_masks.blas = "shared";
  other_masks.mask = 0x08;
  CHECK_THROWS_WITH_AS(scene.add_geometry("second", other_masks),
                       doctest::Contains("declares instance masks that differ from those of its BLAS \"shared\""),
                       InvalidGeometryError);
  GeometryDesc no_instances = GeometryDesc::triangles(mesh, {});
  no_instances.blas = "shared";
  no_instances.mask = 0x08;
  CHECK_THROWS_WITH_AS(scene.add_geometry("third", no_instances),
                       doctest::Contains("sets instance masks but declares no instances"), InvalidGeometryError);
  no_instances.mask = all_layers;
  scene.add_geometry("third", no_instances);
  CHECK(scene.blases()[0].masks == std::vector<std::uint8_t>{0x04});
  CHECK(scene.blases()[0].geometries.size() == 2);
}
