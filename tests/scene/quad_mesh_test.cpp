// Tests for proceduray/scene/quad_mesh.hpp: a rectangle of two triangles facing +y.
#include "proceduray/scene/quad_mesh.hpp"

#include <doctest/doctest.h>

using namespace proceduray;

TEST_CASE("quad xz spans its corners at its height with normals up") {
  const TriangleMesh m = quad_xz({-12.0f, -10.0f}, {12.0f, 10.0f}, 0.5f);
  REQUIRE(m.vertices.size() == 4);
  REQUIRE(m.indices.size() == 6);
  for (const glm::vec3& v : m.vertices) {
    CHECK(v.y == 0.5f);
    CHECK(std::abs(v.x) == 12.0f);
    CHECK(std::abs(v.z) == 10.0f);
  }
  for (std::size_t t = 0; t < 6; t += 3) {
    const glm::vec3 a = m.vertices[m.indices[t]], b = m.vertices[m.indices[t + 1]], c = m.vertices[m.indices[t + 2]];
    const glm::vec3 n = glm::cross(b - a, c - a);
    CHECK(n.y > 0.0f);  // right-hand rule: up
    CHECK(std::abs(n.y) == doctest::Approx(24.0 * 20.0));  // each triangle is half the rectangle (|n| = 2 * area)
  }
  CHECK_NOTHROW(validate(GeometryDesc::triangles(m), "ground", "test"));
}

TEST_CASE("quad xz rejects swapped or flat corners") {
  CHECK_THROWS_WITH_AS(quad_xz({1.0f, 0.0f}, {-1.0f, 1.0f}), doctest::Contains("swap the corners"), InvalidGeometryError);
  CHECK_THROWS_AS(quad_xz({0.0f, 0.0f}, {1.0f, 0.0f}), InvalidGeometryError);
}
