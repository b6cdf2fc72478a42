// OBJ meshes: corners deduplicated, normals read or computed, relative indices, and bad files.
#include <proceduray/mesh/obj.hpp>
#include <proceduray/scene/errors.hpp>

#include "test_paths.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <set>
#include <string>
#include <tuple>

namespace {

// A unit cube's corners.
const std::string cube_positions = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n";

// The cube with one normal per face and the four corners of a square texture.
const std::string cube_with_normals = cube_positions + R"(vn 0 0 -1
vn 0 0 1
vn 0 -1 0
vn 0 1 0
vn -1 0 0
vn 1 0 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
f 1/1/1 4/4/1 3/3/1 2/2/1
f 5/1/2 6/2/2 7/3/2 8/4/2
f 1/1/3 2/2/3 6/3/3 5/4/3
f 4/1/4 8/4/4 7/3/4 3/2/4
f 1/1/5 5/2/5 8/3/5 4/4/5
f 2/1/6 3/2/6 7/3/6 6/4/6
)";

// The same cube with positions only.
const std::string cube_positions_only = cube_positions + R"(f 1 4 3 2
f 5 6 7 8
f 1 2 6 5
f 4 8 7 3
f 1 5 8 4
f 2 3 7 6
)";

glm::vec3 face_normal(const proceduray::ObjMesh& m, std::uint32_t t) {
  const glm::vec3 a = m.positions[m.indices[3 * t]];
  return glm::normalize(glm::cross(m.positions[m.indices[3 * t + 1]] - a, m.positions[m.indices[3 * t + 2]] - a));
}

/// A UV sphere of radius 1 as OBJ text, positions only: its computed normals should approach the
/// closed-form normal, the position itself.
std::string sphere_obj(int rings, int segments) {
  std::string text;
  for (int r = 0; r <= rings; ++r) {
    const double theta = std::numbers::pi * r / rings;
    for (int s = 0; s < segments; ++s) {
      const double phi = 2 * std::numbers::pi * s / segments;
      text += "v " + std::to_string(std::sin(theta) * std::cos(phi)) + " " + std::to_string(std::cos(theta)) + " " +
              std::to_string(std::sin(theta) * std::sin(phi)) + "\n";
    }
  }
  const auto at = [&](int r, int s) { return std::to_string(r * segments + (s % segments) + 1); };
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      text += "f " + at(r, s) + " " + at(r, s + 1) + " " + at(r + 1, s + 1) + " " + at(r + 1, s) + "\n";
    }
  }
  return text;
}

}  // namespace

TEST_CASE("mesh: an OBJ cube with a normal per face has 24 vertices and the file's normals and uvs") {
  const proceduray::ObjMesh m = proceduray::parse_obj(cube_with_normals, "cube");
  CHECK(m.triangle_count() == 12);  // six quads, split
  CHECK(m.positions.size() == 24);
  CHECK(m.normals.size() == 24);
  REQUIRE(m.has_uvs());
  CHECK(m.uvs.size() == 24);
  CHECK_FALSE(m.normals_computed);
  for (std::uint32_t t = 0; t < m.triangle_count(); ++t) {
    for (int k = 0; k < 3; ++k) {
      // Each corner's normal is the face's own, and the file's winding agrees with it.
      CHECK(glm::dot(m.normals[m.indices[3 * t + k]], face_normal(m, t)) == doctest::Approx(1.0).epsilon(1e-6));
    }
  }
  std::set<std::tuple<float, float>> corners;
  for (const glm::vec2& uv : m.uvs) corners.emplace(uv.x, uv.y);
  CHECK(corners == std::set<std::tuple<float, float>>{{0.f, 0.f}, {1.f, 0.f}, {1.f, 1.f}, {0.f, 1.f}});
  const proceduray::TriangleMesh tri = m.triangles();
  CHECK(tri.vertices == m.positions);
  CHECK(tri.indices == m.indices);
}

TEST_CASE("mesh: vertex_data gives one ObjVertex per vertex, for a MeshRef to read") {
  const proceduray::ObjMesh m = proceduray::parse_obj(cube_with_normals, "cube");
  const proceduray::VertexData d = m.vertex_data();
  CHECK(d.type == &proceduray::type_ops<proceduray::ObjVertex>);
  REQUIRE(d.count == m.positions.size());
  REQUIRE(d.bytes.size() == d.count * sizeof(proceduray::ObjVertex));
  for (std::size_t i = 0; i < d.count; ++i) {
    proceduray::ObjVertex v;
    std::memcpy(&v, d.bytes.data() + i * sizeof(v), sizeof(v));
    CHECK(v.position == m.positions[i]);
    CHECK(v.normal == m.normals[i]);
    CHECK(v.uv == m.uvs[i]);
  }
  // Without texture coordinates the uv member is zero, not garbage.
  const proceduray::ObjMesh bare = proceduray::parse_obj(cube_positions + "f 1 2 3\n", "triangle");
  const proceduray::VertexData b = bare.vertex_data();
  proceduray::ObjVertex first;
  std::memcpy(&first, b.bytes.data(), sizeof(first));
  CHECK(first.uv == glm::vec2(0.0f));
  proceduray::GeometryDesc desc = proceduray::GeometryDesc::triangles(m.triangles());
  desc.vertex_data = d;
  CHECK_NOTHROW(proceduray::validate(desc, "cube", "test"));  // one per position
}

TEST_CASE("mesh: an OBJ without normals gets smooth angle-weighted ones, shared across its faces") {
  const proceduray::ObjMesh m = proceduray::parse_obj(cube_positions_only, "cube");
  CHECK(m.normals_computed);
  CHECK_FALSE(m.has_uvs());
  CHECK(m.positions.size() == 8);  // nothing splits a position: one vertex each
  const glm::vec3 centre(0.5f);
  for (std::size_t v = 0; v < m.positions.size(); ++v) {
    // Three equal faces meet at each corner: the normal points away from the centre diagonally.
    const glm::vec3 expected = glm::normalize(m.positions[v] - centre);
    CHECK(glm::dot(m.normals[v], expected) == doctest::Approx(1.0).epsilon(1e-6));
    CHECK(glm::length(m.normals[v]) == doctest::Approx(1.0).epsilon(1e-6));
  }
  // Interpolated normals are not face normals: at a corner they differ by acos(1/sqrt(3)).
  CHECK(glm::dot(m.normals[m.indices[0]], face_normal(m, 0)) == doctest::Approx(1.0 / std::sqrt(3.0)).epsilon(1e-5));
}

TEST_CASE("mesh: computed normals of a sphere converge to the closed-form normal at second order") {
  double previous = 1e9;
  for (int n : {8, 16, 32}) {
    const proceduray::ObjMesh m = proceduray::parse_obj(sphere_obj(n, 2 * n), "sphere");
    double worst = 0;  // radians between the computed normal and the position (the exact normal)
    for (std::size_t v = 0; v < m.positions.size(); ++v) {
      const double c = glm::dot(m.normals[v], glm::normalize(m.positions[v]));
      worst = std::max(worst, std::acos(std::min(1.0, c)));
    }
    CAPTURE(n);
    CAPTURE(worst);
    CHECK(worst < 0.03);            // 0.022 rad at 8 rings (measured)
    CHECK(worst < previous / 3.0);  // second order: each halving of the spacing cuts it about 4x
    previous = worst;
  }
}

TEST_CASE("mesh: OBJ relative indices and polygons read like absolute ones") {
  const proceduray::ObjMesh relative = proceduray::parse_obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf -4 -3 -2 -1\n");
  const proceduray::ObjMesh absolute = proceduray::parse_obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  CHECK(relative.triangle_count() == 2);
  CHECK(relative.positions == absolute.positions);
  CHECK(relative.indices == absolute.indices);
  for (const glm::vec3& n : relative.normals) CHECK(n.z == doctest::Approx(1.0));  // counter-clockwise seen from +Z
}

TEST_CASE("mesh: load_obj reads a file and names a missing one") {
  const std::filesystem::path dir = test_output_dir("obj");
  const std::filesystem::path file = dir / "cube.obj";
  std::ofstream(file) << cube_with_normals;
  const proceduray::ObjMesh m = proceduray::load_obj(file);
  CHECK(m.positions == proceduray::parse_obj(cube_with_normals).positions);
  const std::filesystem::path missing = dir / "no-such.obj";
  CHECK_THROWS_WITH_AS(proceduray::load_obj(missing),
                       doctest::Contains(("load_obj: cannot read '" + missing.string() + "'").c_str()), proceduray::EnvironmentError);
}

TEST_CASE("mesh: bad OBJ content is refused with the face and the fix") {
  // A face past the last position (tinyobjloader only warns).
  CHECK_THROWS_WITH_AS(proceduray::parse_obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 9\n", "bad.obj"),
                       "load_obj: 'bad.obj' shape \"\" face 1 uses position 9 but the file has 3 (`v` lines); fix the "
                       "face's index or add the position",
                       proceduray::InvalidGeometryError);
  // A normal index past the last normal.
  CHECK_THROWS_WITH_AS(proceduray::parse_obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nvn 0 0 1\nf 1//1 2//1 3//2\n", "n.obj"),
                       doctest::Contains("face 1 uses normal 2 but the file has 1 (`vn` lines)"),
                       proceduray::InvalidGeometryError);
  // Relative indices reaching before the first position: named as written (-3), not as resolved.
  CHECK_THROWS_WITH_AS(proceduray::parse_obj("v 0 0 0\nv 1 0 0\nf -1 -2 -3\n", "rel.obj"),
                       "load_obj: 'rel.obj' line 3: face corner '-3' uses position (`v`) index -3, reaching back past "
                       "the 2 defined before it; fix the face's index",
                       proceduray::InvalidGeometryError);
  CHECK_THROWS_WITH_AS(proceduray::parse_obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 0 1 2\n", "zero.obj"),
                       doctest::Contains("uses position (`v`) index 0, but OBJ indices start at 1"),
                       proceduray::InvalidGeometryError);
  CHECK_THROWS_WITH_AS(proceduray::parse_obj("v 0 0 0\n# no faces\n", "empty.obj"),
                       "load_obj: 'empty.obj' has no faces (`f` lines); a mesh needs at least one triangle",
                       proceduray::InvalidGeometryError);
  CHECK_THROWS_WITH_AS(proceduray::parse_obj("v 1e39 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n", "big.obj"),
                       doctest::Contains("line 1: position coordinate '1e39' is not a finite float"),
                       proceduray::InvalidGeometryError);
  // Every error is a proceduray::Error, so one catch reaches them.
  CHECK_THROWS_AS(proceduray::parse_obj("f 1 2 3\n"), proceduray::Error);
}

TEST_CASE("bad input: an OBJ position of nan or inf (tinyobjloader reads it as 0)") {
  CHECK_THROWS_WITH_AS(proceduray::parse_obj("v nan 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n", "nan.obj"),
                       "load_obj: 'nan.obj' line 1: position coordinate 'nan' is not a finite float; fix its `v` line",
                       proceduray::InvalidGeometryError);
  CHECK_THROWS_WITH_AS(proceduray::parse_obj("v 0 0 0\nv 1 -inf 0\nv 1 1 0\nf 1 2 3\n", "inf.obj"),
                       doctest::Contains("line 2: position coordinate '-inf'"), proceduray::InvalidGeometryError);
  CHECK_THROWS_WITH_AS(proceduray::parse_obj("v 0 0 0\nv 1 0x 0\nv 1 1 0\nf 1 2 3\n", "word.obj"),
                       doctest::Contains("line 2: position coordinate '0x'"), proceduray::InvalidGeometryError);
  // A weight after the three coordinates and a comment line are not positions.
  CHECK_NOTHROW(proceduray::parse_obj("# nan\nv 0 0 0 1\nv 1 0 0\nv 1 1 0\nf 1 2 3\n", "ok.obj"));
}

TEST_CASE("bad input: an OBJ relative index reaching before the file, named as written") {
  CHECK_THROWS_WITH_AS(proceduray::parse_obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nvn 0 0 1\nf -3//-1 -2//-1 -1//-2\n", "n.obj"),
                       doctest::Contains("face corner '-1//-2' uses normal (`vn`) index -2, reaching back past the 1"),
                       proceduray::InvalidGeometryError);
}
