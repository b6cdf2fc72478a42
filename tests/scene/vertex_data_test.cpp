// scene/vertex_data.hpp, and what compile() and Plan::write do with it: a triangle geometry's
// vertex structs reach the hit records that hold a MeshRef, at the MeshRef's place in the record,
// on every device profile; a record reading vertices a geometry lacks is refused at compile().
#include "proceduray/scene/vertex_data.hpp"
#include "proceduray/shader/mesh_ref.hpp"

#include "scene_fixtures.hpp"

#include <doctest/doctest.h>

#include <cstring>
#include <string>
#include <vector>

namespace vertex_data_test {
struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
};
PROCEDURAY_STRUCT(Vertex, scalar, position, normal);
struct Other {
  glm::vec4 colour;
};
PROCEDURAY_STRUCT(Other, scalar, colour);
struct MeshArgs {
  glm::vec4 tint;  // the MeshRef after another member: its offset is not 0
  proceduray::MeshRef<Vertex> mesh;
};
PROCEDURAY_STRUCT(MeshArgs, scalar, tint, mesh);
struct OtherArgs {
  proceduray::MeshRef<Other> mesh;
};
PROCEDURAY_STRUCT(OtherArgs, scalar, mesh);
struct Probe {
  float value;
};
PROCEDURAY_STRUCT(Probe, scalar, value);
struct TwoArgs {
  proceduray::MeshRef<Vertex> a;
  proceduray::MeshRef<Vertex> b;
};
PROCEDURAY_STRUCT(TwoArgs, scalar, a, b);
using TestSceneInterface = proceduray::ShaderInterface<proceduray::Payload<Probe>, proceduray::RootComponent<>, proceduray::RootArguments<MeshArgs, OtherArgs, TwoArgs>,
                                   proceduray::Attributes<proceduray::test::FractalAttributes>>;
using TestScene = proceduray::Scene<TestSceneInterface>;
}  // namespace vertex_data_test

using namespace proceduray;
using namespace proceduray::test;
using vertex_data_test::MeshArgs;
using vertex_data_test::Vertex;
using vertex_data_test::TestScene;

namespace {

const TriangleMesh quad{{{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}}, {0, 2, 1, 0, 3, 2}};

std::vector<Vertex> corners() {
  std::vector<Vertex> v;
  for (const glm::vec3& p : quad.vertices) v.push_back({p, glm::normalize(glm::vec3(p.x, 4.0f, p.z))});
  return v;
}

/// A scene with a quad floor (with vertex data) whose record holds a MeshRef, and a procedural ball.
struct MeshScene {
  TestScene s;
  RayId<vertex_data_test::Probe> ray = s.add_ray<vertex_data_test::Probe>("r", {.miss = "m"});
  HitGroupId floor_group = s.add_hit_group("floor", {.closest_hit = "floor.rchit"});
  LocalSignatureId<MeshArgs> sig = s.add_local_signature<MeshArgs>("mesh");
  GeometryId floor;
  explicit MeshScene(bool with_vertices = true) {
    GeometryDesc desc = GeometryDesc::triangles(quad);
    const std::vector<Vertex> v = corners();
    if (with_vertices) desc.vertex_data = VertexData::of(std::span<const Vertex>(v));
    floor = s.add_geometry("floor", desc);
    s.add_raygen("rgen");
  }
};

}  // namespace

TEST_CASE("vertex_data: of() copies the structs and names their type") {
  const std::vector<Vertex> v = corners();
  const VertexData d = VertexData::of(std::span<const Vertex>(v));
  CHECK(static_cast<bool>(d));
  CHECK_FALSE(static_cast<bool>(VertexData{}));
  CHECK(d.type == &type_ops<Vertex>);
  CHECK(d.count == 4);
  REQUIRE(d.bytes.size() == 4 * sizeof(Vertex));
  CHECK(std::memcmp(d.bytes.data(), v.data(), d.bytes.size()) == 0);
}

TEST_CASE("vertex_data: add_geometry refuses it on procedural geometry and with another count") {
  TestScene s;
  const std::vector<Vertex> v = corners();
  GeometryDesc short_by_one = GeometryDesc::triangles(quad);
  short_by_one.vertex_data = VertexData::of(std::span<const Vertex>(v.data(), 3));
  CHECK_THROWS_WITH_AS(s.add_geometry("floor", short_by_one),
                       doctest::Contains("Scene::add_geometry: geometry \"floor\" has vertex data for 3 vertices but 4 "
                                         "positions; give one Vertex per position"),
                       InvalidGeometryError);
  GeometryDesc ball = GeometryDesc::procedural({Aabb{}});
  ball.vertex_data = VertexData::of(std::span<const Vertex>(v));
  CHECK_THROWS_WITH_AS(s.add_geometry("ball", ball), doctest::Contains("is procedural but has a triangle mesh or vertex data"),
                       InvalidGeometryError);
  CHECK(s.geometries().size() == 0);  // nothing registered
}

TEST_CASE("vertex_data: compile places the MeshRef and Plan::write fills it on every device profile") {
  MeshScene m;
  m.s.add_hit(m.ray, m.floor_group, m.sig, MeshArgs{.tint = glm::vec4(0.5f)}, m.floor);
  const Plan plan = compile(m.s);
  const auto hit = plan.records(SbtRegionKind::hit);
  REQUIRE(hit.size() == 1);
  CHECK(hit[0].mesh_offset == offsetof(MeshArgs, mesh));
  CHECK(hit[0].mesh_offset == 16);
  CHECK(plan.reads_meshes());
  CHECK(plan.geometries()[0].vertex_type == &type_ops<Vertex>);
  CHECK(plan.geometries()[0].vertex_count == 4);
  const std::string decl = plan.pipeline().stages.front().declarations;
  CHECK(decl.find("Vertex interpolate(VertexMesh m, uint primitive, vec2 barycentrics)") != std::string::npos);

  const MeshAddresses addresses[] = {{0x1000'0000'0040ull, 0x2000'0000'0080ull}};
  for (const DeviceLimits& limits : all_limits()) {
    CAPTURE(limits.device);
    const SbtLayout layout = plan.layout(limits);
    std::vector<std::byte> table(layout.size);
    const std::vector<std::byte> handles(std::size_t{layout.properties.handle_size} * plan.pipeline().groups.size(),
                                         std::byte{0xAB});
    plan.write(layout, table, handles, addresses);
    const std::uint64_t data = layout.record_offset(SbtRegionKind::hit, 0) + layout.properties.handle_size;
    MeshArgs written;
    std::memcpy(&written, table.data() + data, sizeof(MeshArgs));
    CHECK(written.tint == glm::vec4(0.5f));                          // the user's member as given
    CHECK(written.mesh.vertices.value == addresses[0].vertices);     // the addresses where the MeshRef is
    CHECK(written.mesh.triangles.value == addresses[0].triangles);
    CHECK_THROWS_WITH_AS(plan.write(layout, table, handles),  // no addresses: refused, naming the geometry
                         doctest::Contains("Plan::write: hit record 0 reads geometry \"floor\"'s mesh"), UsageError);
  }
}

TEST_CASE("vertex_data: compile refuses a MeshRef the geometry cannot fill") {
  SUBCASE("no vertex data") {
    MeshScene m(false);
    m.s.add_hit(m.ray, m.floor_group, m.sig, MeshArgs{}, m.floor);
    CHECK_THROWS_WITH_AS(compile(m.s),
                         doctest::Contains("compile: ray \"r\" on geometry \"floor\" has root arguments MeshArgs whose "
                                           "member mesh reads Vertex vertices, but the geometry has no vertex data"),
                         SceneError);
  }
  SUBCASE("another vertex type") {
    MeshScene m;
    const auto other = m.s.add_local_signature<vertex_data_test::OtherArgs>("other");
    m.s.add_hit(m.ray, m.floor_group, other, vertex_data_test::OtherArgs{}, m.floor);
    CHECK_THROWS_WITH_AS(compile(m.s), doctest::Contains("reads Other vertices, but the geometry's vertex data is Vertex"),
                         SceneError);
  }
  SUBCASE("procedural geometry") {
    MeshScene m;
    const auto ball_group = m.s.add_hit_group<FractalAttributes>(
        "ball", {.kind = HitGroupKind::procedural, .closest_hit = "b.rchit", .intersection = "b.rint"});
    const GeometryId ball = m.s.add_geometry("ball", GeometryDesc::procedural({Aabb{}}));
    m.s.add_hit(m.ray, m.floor_group, m.sig, MeshArgs{}, m.floor);
    m.s.add_hit(m.ray, ball_group, m.sig, MeshArgs{}, ball);
    CHECK_THROWS_WITH_AS(compile(m.s), doctest::Contains("but the geometry is procedural"), SceneError);
  }
  SUBCASE("two MeshRefs") {
    MeshScene m;
    const auto two = m.s.add_local_signature<vertex_data_test::TwoArgs>("two");
    m.s.add_hit(m.ray, m.floor_group, two, vertex_data_test::TwoArgs{}, m.floor);
    CHECK_THROWS_WITH_AS(compile(m.s), doctest::Contains("root arguments TwoArgs hold two MeshRefs (a, b)"), SceneError);
  }
}
