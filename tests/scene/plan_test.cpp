// Tests for proceduray/scene/plan.hpp: what compile(scene) returns is a value (it outlives its scene,
// equals its copies and does not follow later changes to the scene); layout(limits) makes the device
// checks, naming the limit, the value and the device; write() fills handles and root arguments.
#include "proceduray/scene/plan.hpp"
#include "proceduray/scene/uniform_slot.hpp"

#include "proceduray/scene/compile.hpp"
#include "proceduray/scene/default_global_signature.hpp"
#include "proceduray/scene/object.hpp"
#include "scene_fixtures.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <numeric>
#include <type_traits>

using namespace proceduray;

namespace plan_test {

struct Payload { glm::vec4 colour; };
struct Hit { glm::vec3 normal; float t; };
struct Tint { glm::vec3 rgb; float alpha; };
PROCEDURAY_STRUCT(Payload, scalar, colour);
PROCEDURAY_STRUCT(Hit, scalar, normal, t);
PROCEDURAY_STRUCT(Tint, scalar, rgb, alpha);
using TestSceneInterface = proceduray::ShaderInterface<proceduray::Payload<Payload>, proceduray::RootComponent<Tint>, proceduray::RootArguments<Tint>,
                                   proceduray::Attributes<Hit>>;
using TestScene = proceduray::Scene<TestSceneInterface>;

/// A one-ray, one-object scene written as the examples write theirs: two sphere instances, one record.
TestScene spheres() {
  TestScene scene;
  const auto radiance = scene.add_ray<Payload>("radiance", {.miss = "miss.rmiss"});
  const auto tint = scene.add_local_signature<Tint>("tint");
  scene.set_global_signature(default_global_signature());
  scene.add_raygen("raygen.rgen");
  add_object<Hit>(scene, "sphere",
                  {.geometry = GeometryDesc::procedural({Aabb{}}, test::translations(2, 1.0f)),
                   .intersection = "sphere.rint", .closest_hit = {{radiance, "sphere.rchit"}}},
                  tint, {Tint{{1, 0, 0}, 1}});
  return scene;
}

/// The plan of a scene that is gone by the time the caller reads it.
Plan plan_of_spheres() {
  const TestScene scene = spheres();
  return compile(scene);
}

}  // namespace plan_test

using namespace plan_test;

TEST_CASE("plan is a value that outlives its scene and equals a copy") {
  static_assert(std::is_copy_constructible_v<Plan> && std::is_copy_assignable_v<Plan>);
  static_assert(std::is_nothrow_move_constructible_v<Plan>);
  const Plan plan = plan_of_spheres();
  // Everything it answers comes from the plan itself: the scene was destroyed.
  REQUIRE(plan.records(SbtRegionKind::hit).size() == 1);
  const auto data = plan.root_arguments(plan.records(SbtRegionKind::hit)[0]);
  REQUIRE(data.size() == sizeof(Tint));
  Tint back{};
  std::memcpy(&back, data.data(), sizeof back);
  CHECK(back.rgb.x == 1.0f);
  CHECK(back.alpha == 1.0f);
  CHECK(plan.ray_count() == 1);
  CHECK(plan.ray_name(0) == "radiance");
  REQUIRE(plan.geometries().size() == 1);
  CHECK(plan.geometries()[0].name == "sphere");
  CHECK(plan.blases()[0].name == "sphere");
  CHECK(plan.resolve(RayId<>(0), GeometryId(0), 1).record == 0);
  CHECK(plan.resolve(RayId<>(0), GeometryId(0), 1).entry->arguments_size == sizeof(Tint));
  REQUIRE(plan.global_signature() != nullptr);
  CHECK(*plan.global_signature() == default_global_signature());
  CHECK(glsl_for(plan, ShaderStage::closest_hit, "sphere.rchit").find("struct Tint {") != std::string::npos);
  CHECK(plan.pipeline().groups[plan.records(SbtRegionKind::hit)[0].group].name == "sphere");
  // Its instances carry their transforms.
  const auto transforms = test::translations(2, 1.0f);
  REQUIRE(plan.instances().size() == 2);
  CHECK(plan.instances()[0].transform == transforms[0]);
  CHECK(plan.instances()[1].transform == transforms[1]);
  // A copy equals it; so does the plan of an equal scene: compile is a function of the scene.
  const Plan copy = plan;
  CHECK(copy == plan);
  Plan assigned;
  assigned = plan;
  CHECK(assigned == plan);
  CHECK(compile(spheres()) == plan);
  CHECK_FALSE(Plan{} == plan);
  TestScene deeper = spheres();
  deeper.set_max_recursion_depth(2);
  CHECK_FALSE(compile(deeper) == plan);
  // A copy lays out and writes the same table.
  const SbtLayout layout = plan.layout(test::lavapipe_limits);
  const auto handles = test::fake_handles(plan, layout);
  std::vector<std::byte> a(layout.size), b(layout.size);
  plan.write(layout, a, handles);
  copy.write(layout, b, handles);
  CHECK(a == b);
}

TEST_CASE("plan does not change when the scene changes after compile") {
  TestScene scene = spheres();
  const Plan plan = compile(scene);
  const Plan before = plan;
  const auto radiance = scene.ray_id<plan_test::Payload>("radiance");
  const auto tint = scene.local_signature_id<Tint>("tint");
  scene.set_max_recursion_depth(5);
  scene.add_raygen("second.rgen");
  scene.add_miss(radiance, tint, Tint{{0, 0, 1}, 1});
  add_object<Hit>(scene, "box", {.geometry = GeometryDesc::procedural({Aabb{}}), .intersection = "box.rint"}, tint,
                  {Tint{{0, 1, 0}, 1}});
  scene.set_global_signature(default_global_signature(), "other");
  CHECK(plan == before);
  CHECK(plan.records(SbtRegionKind::raygen).size() == 1);
  CHECK(plan.records(SbtRegionKind::hit).size() == 1);
  CHECK(plan.instances().size() == 2);
  CHECK(plan.pipeline().max_recursion_depth == 1);
  CHECK(plan.pipeline().global_signature == scene.global_signature_id("global"));
  CHECK(plan.root_arguments(plan.records(SbtRegionKind::miss)[0]).empty());
  // Compiling again sees the changes.
  const Plan after = compile(scene);
  CHECK_FALSE(after == plan);
  CHECK(after.records(SbtRegionKind::raygen).size() == 2);
  CHECK(after.records(SbtRegionKind::hit).size() == 2);
  CHECK(after.instances().size() == 3);
  CHECK(after.pipeline().max_recursion_depth == 5);
  CHECK(after.pipeline().global_signature == scene.global_signature_id("other"));
  CHECK(after.root_arguments(after.records(SbtRegionKind::miss)[0]).size() == sizeof(Tint));
}

TEST_CASE("plan records the global signature and the root arguments sizes") {
  const TestScene scene = spheres();
  const Plan plan = compile(scene);
  CHECK(plan.records(SbtRegionKind::hit).size() == 1);
  CHECK(plan.pipeline().global_signature == scene.global_signature_id("global"));
  CHECK(plan.pipeline().max_root_arguments_size[2] == sizeof(Tint));
  const SbtLayout layout = plan.layout(test::lavapipe_limits);
  CHECK(layout.region(SbtRegionKind::hit).count == 1);
  CHECK(layout.region(SbtRegionKind::hit).stride == detail::align_up(32 + sizeof(Tint), 16));
}

TEST_CASE("plan that does not fit a device throws from layout and stays as it was") {
  TestScene scene = spheres();
  const Plan first = compile(scene);
  scene.set_max_recursion_depth(5);
  const Plan deep = compile(scene);
  const Plan deep_before = deep;
  DeviceLimits shallow = test::lavapipe_limits;
  shallow.max_ray_recursion_depth = 2;
  CHECK_THROWS_AS(deep.layout(shallow), DeviceLimitError);
  CHECK(deep == deep_before);
  // The plan compiled before the change still fits.
  CHECK(first.pipeline().max_recursion_depth == 1);
  CHECK(first.layout(shallow).region(SbtRegionKind::hit).count == first.records(SbtRegionKind::hit).size());
}

TEST_CASE("plan layout checks device limits naming the limit the value and the device") {
  test::ReportScene r;
  test::build_report_scene(r);
  test::add_report_entries(r);
  const Plan t = compile(r.scene);
  CHECK_NOTHROW(t.layout(test::lavapipe_limits));
  DeviceLimits limits = test::lavapipe_limits;
  limits.max_instance_count = 6;
  CHECK_THROWS_WITH_AS(t.layout(limits),
                       doctest::Contains("Plan::layout: the scene's instance count is 7, llvmpipe allows 6 (maxInstanceCount)"),
                       DeviceLimitError);
  limits.device.clear();  // an unnamed device
  CHECK_THROWS_WITH_AS(t.layout(limits), doctest::Contains("the scene's instance count is 7, the device allows 6 (maxInstanceCount)"),
                       DeviceLimitError);
  limits = test::h100_limits;
  limits.max_ray_recursion_depth = 2;
  CHECK_THROWS_WITH_AS(t.layout(limits),
                       doctest::Contains("the scene's max recursion depth is 3, NVIDIA H100 80GB HBM3 allows 2 (maxRayRecursionDepth)"),
                       DeviceLimitError);
  limits = test::lavapipe_limits;
  limits.max_ray_hit_attribute_size = 8;
  CHECK_THROWS_WITH_AS(t.layout(limits),
                       doctest::Contains("the hit attribute size (bytes) of hit group \"Pacman\" is 16, llvmpipe allows 8 "
                                         "(maxRayHitAttributeSize)"),
                       DeviceLimitError);
  limits = test::lavapipe_limits;
  limits.sbt.max_stride = 64;  // 32 + 32 bytes of ProceduralRootArguments... exceeds
  CHECK_THROWS_WITH_AS(t.layout(limits), doctest::Contains("exceeds the device's maxShaderGroupStride 64"), DeviceLimitError);
  limits = test::lavapipe_limits;
  limits.max_geometry_count = 0;
  CHECK_THROWS_WITH_AS(t.layout(limits),
                       doctest::Contains("the geometry count of BLAS \"GlobalGeometry\" is 1, llvmpipe allows 0 (maxGeometryCount)"),
                       DeviceLimitError);
  // A scene that does not fit a device is no bug in the calling code: a runtime error, not a SceneError.
  CHECK_THROWS_AS(t.layout(limits), std::runtime_error);
  CHECK_THROWS_AS(t.layout(limits), Error);
  static_assert(!std::is_base_of_v<SceneError, DeviceLimitError>);
}

TEST_CASE("plan write puts handles and root arguments at their offsets") {
  test::D3D12Scene d;
  test::build_d3d12_scene_in_order(d);
  const Plan sbt = compile(d.scene);
  for (const DeviceLimits& limits : test::all_limits()) {
    const SbtLayout layout = sbt.layout(limits);
    const auto handles = test::fake_handles(sbt, layout);
    std::vector<std::byte> buffer(layout.size, std::byte{0xEE});
    sbt.write(layout, buffer, handles);
    const std::uint32_t h = limits.sbt.handle_size;
    for (std::uint32_t k = 0; k < 3; ++k) {
      const auto kind = static_cast<SbtRegionKind>(k);
      const auto records = sbt.records(kind);
      for (std::uint32_t i = 0; i < records.size(); ++i) {
        const std::uint64_t at = layout.record_offset(kind, i);
        CHECK(buffer[at] == std::byte(records[i].group + 1));
        CHECK(buffer[at + h - 1] == std::byte(records[i].group + 1));
        const auto data = sbt.root_arguments(records[i]);
        CHECK(std::equal(data.begin(), data.end(), buffer.begin() + static_cast<std::ptrdiff_t>(layout.arguments_offset(kind, i))));
      }
    }
    // Padding is zeroed: the byte after the last hit record's data.
    const auto last = static_cast<std::uint32_t>(sbt.records(SbtRegionKind::hit).size() - 1);
    const std::uint64_t after = layout.arguments_offset(SbtRegionKind::hit, last) + sizeof(test::D3D12RootArguments);
    if (after < layout.size) CHECK(buffer[after] == std::byte{0});
    std::vector<std::byte> small(layout.size - 1);
    CHECK_THROWS_WITH_AS(sbt.write(layout, small, handles), doctest::Contains("Plan::write: buffer has"), UsageError);
    CHECK_THROWS_WITH_AS(sbt.write(layout, small, handles), doctest::Contains("allocate layout.size"), std::logic_error);
    CHECK_THROWS_WITH_AS(sbt.write(layout, buffer, std::span(handles).first(h)), doctest::Contains("fetch handles"),
                         UsageError);
  }
}

TEST_CASE("plan knows its BLASes geometries and instances and names bad ids") {
  test::D3D12Scene d;
  test::build_d3d12_scene_in_order(d);
  const Plan plan = compile(d.scene);
  REQUIRE(plan.blases().size() == 2);
  const PlannedBlas& plane = plan.blases()[0];
  CHECK(plane.name == "Plane");
  CHECK(plane.kind == GeometryKind::triangles);
  CHECK(plane.update == UpdatePolicy::Static);
  CHECK(plane.geometries == std::vector<std::uint32_t>{d.plane.index()});
  CHECK(plane.first_instance == 0);
  CHECK(plane.instance_count == 1);
  const PlannedBlas& aabbs = plan.blases()[1];
  CHECK(aabbs.name == "AABBs");
  CHECK(aabbs.kind == GeometryKind::procedural);
  CHECK(aabbs.geometries.size() == 10);
  CHECK(aabbs.first_instance == 1);
  CHECK(aabbs.instance_count == 1);
  REQUIRE(plan.geometries().size() == 11);
  CHECK(plan.geometry(d.aabbs[3]).name == "MiniSpheres");
  CHECK(plan.geometry(d.aabbs[3]).blas == 1);
  CHECK(plan.geometry_index(d.aabbs[3]) == 3);
  CHECK(plan.tlas_index(d.aabbs[3], 0) == 1);
  CHECK_THROWS_WITH_AS(plan.geometry(GeometryId(11)),
                       doctest::Contains("Plan::geometry: geometry #11 is not in the compiled scene (it has 11 geometries)"),
                       UnknownIdError);
  CHECK_THROWS_WITH_AS(plan.tlas_index(d.plane, 1),
                       doctest::Contains("Plan::tlas_index: geometry \"Plane\" has 1 instances, no instance 1"),
                       InvalidGeometryError);
  CHECK_THROWS_WITH_AS(plan.instance_sbt_offset(d.plane, 3), doctest::Contains("Plan::instance_sbt_offset"),
                       InvalidGeometryError);
  CHECK_THROWS_WITH_AS(plan.resolve(RayId<>(2), d.plane, 0), doctest::Contains("Plan::resolve: ray #2"), UnknownIdError);
}

TEST_CASE("plan layout refuses a push constant block past the device's maxPushConstantsSize") {
  TestScene scene = plan_test::spheres();
  GlobalSignatureDesc pushing = default_global_signature();
  pushing.push_constants = PushConstantSlot<Tint>{.name = "tint_push"};
  scene.set_global_signature(pushing, "pushing");
  const Plan plan = compile(scene);
  DeviceLimits small{.max_push_constants_size = 8, .device = "a small device"};
  CHECK_THROWS_WITH_AS((void)plan.layout(small),
                       doctest::Contains("Plan::layout: the push constant block (bytes) the global signature declares "
                                         "is 16, a small device allows 8 (maxPushConstantsSize; every device allows 128); "
                                         "move the rest to a uniform"),
                       DeviceLimitError);
  small.max_push_constants_size = 16;
  CHECK_NOTHROW((void)plan.layout(small));
}
