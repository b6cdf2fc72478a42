#include "proceduray/scene/geometry.hpp"

#include <doctest/doctest.h>

#include <type_traits>

#include <glm/gtc/matrix_transform.hpp>
#include <limits>

using namespace proceduray;

namespace {
constexpr float k_nan = std::numeric_limits<float>::quiet_NaN();
constexpr float k_inf = std::numeric_limits<float>::infinity();
}  // namespace

// glm converts any matrix into a glm::mat3x4 implicitly, taking a mat4's first three columns: the
// transform type must not accept a mat4 except through instance_transform(), which transposes.
static_assert(!std::is_convertible_v<glm::mat4, InstanceTransform>);
static_assert(!std::is_constructible_v<InstanceTransform, glm::mat4>);

TEST_CASE("geometry instance transforms round-trip through matrix_of") {
  const glm::mat4 m = glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3)), 0.7f, glm::vec3(0, 1, 0)),
                                 glm::vec3(2.0f));
  const InstanceTransform t = instance_transform(m);
  const glm::vec4 p(0.3f, -1.0f, 2.0f, 1.0f);
  // Row r of t dotted with a point is coordinate r of the transformed point.
  for (int r = 0; r < 3; ++r) CHECK(glm::dot(t[r], p) == doctest::Approx((m * p)[r]).epsilon(1e-6));
  CHECK(matrix_of(t) == m);
  CHECK(identity_transform() == instance_transform(glm::mat4(1.0f)));
  CHECK_FALSE(InstanceTransform{} == identity_transform());
}

TEST_CASE("geometry instance transforms match VkTransformMatrixKHR rows") {
  const InstanceTransform t = instance_transform(glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3)));
  static_assert(sizeof(InstanceTransform) == 12 * sizeof(float));
  const float* raw = &t[0][0];
  // Row-major 3x4: translation in the last column of each row.
  CHECK(raw[3] == 1.0f);
  CHECK(raw[7] == 2.0f);
  CHECK(raw[11] == 3.0f);
  CHECK(raw[0] == 1.0f);
  CHECK(raw[5] == 1.0f);
  CHECK(identity_transform()[2][2] == 1.0f);
  CHECK(identity_transform()[2][3] == 0.0f);
}

TEST_CASE("geometry AABBs (proceduray/aabb.hpp): the default is the unit box; equality compares both corners") {
  static_assert(std::is_aggregate_v<Aabb>);
  CHECK(Aabb{} == Aabb{glm::vec3(-1.0f), glm::vec3(1.0f)});
  CHECK(Aabb{} != Aabb{glm::vec3(-1.0f), glm::vec3(1.0f, 1.0f, 2.0f)});
  CHECK(Aabb{} != Aabb{glm::vec3(0.0f), glm::vec3(1.0f)});
}

TEST_CASE("geometry bad AABBs throw with the bounds and the fix") {
  CHECK_NOTHROW(validate(Aabb{glm::vec3(-1), glm::vec3(1)}, "box"));
  CHECK_NOTHROW(validate(Aabb{glm::vec3(2), glm::vec3(2)}, "flat box"));
  CHECK_THROWS_WITH_AS(validate(Aabb{glm::vec3(1, 0, 0), glm::vec3(0, 1, 1)}, "box"),
                       doctest::Contains("box has min (1.000000, 0.000000, 0.000000) > max"), InvalidGeometryError);
  CHECK_THROWS_WITH_AS(validate(Aabb{glm::vec3(1, 0, 0), glm::vec3(0, 1, 1)}, "box"), doctest::Contains("swap the corners"),
                       InvalidGeometryError);
  CHECK_THROWS_WITH_AS(validate(Aabb{glm::vec3(k_nan, 0, 0), glm::vec3(1)}, "box"), doctest::Contains("non-finite bounds"),
                       InvalidGeometryError);
  CHECK_THROWS_AS(validate(Aabb{glm::vec3(0), glm::vec3(k_inf)}, "box"), InvalidGeometryError);
  CHECK_THROWS_AS(validate(Aabb{glm::vec3(-k_inf), glm::vec3(0)}, "box"), InvalidGeometryError);
}

TEST_CASE("geometry non-finite or singular transforms throw") {
  CHECK_NOTHROW(validate(identity_transform(), "t"));
  CHECK_NOTHROW(validate(instance_transform(glm::scale(glm::mat4(1.0f), glm::vec3(1e-3f))), "tiny but invertible"));
  InstanceTransform t = identity_transform();
  t[1][3] = k_nan;
  CHECK_THROWS_WITH_AS(validate(t, "t"), doctest::Contains("non-finite element at row 1 column 3"), InvalidGeometryError);
  t = identity_transform();
  t[0][0] = k_inf;
  CHECK_THROWS_AS(validate(t, "t"), InvalidGeometryError);
  CHECK_THROWS_WITH_AS(validate(instance_transform(glm::scale(glm::mat4(1.0f), glm::vec3(1, 0, 1))), "t"),
                       doctest::Contains("is singular"), InvalidGeometryError);
  t = identity_transform();
  t[1] = t[0];  // two equal rows
  CHECK_THROWS_AS(validate(t, "t"), InvalidGeometryError);
  CHECK_THROWS_AS(validate(InstanceTransform{}, "t"), InvalidGeometryError);
}

TEST_CASE("geometry one transform rule: relative flatness and an absolute determinant floor") {
  auto uniform = [](float s) { return instance_transform(glm::scale(glm::mat4(1.0f), glm::vec3(s))); };
  // 1e-11: |det| = 1e-33 is not flat relative to its scale, but under the 1e-30 floor.
  CHECK(detail::check_transform(uniform(1e-11f)).singular);
  CHECK_THROWS_WITH_AS(validate(uniform(1e-11f), "t"), doctest::Contains("t is singular (determinant 1e-33"),
                       InvalidGeometryError);
  CHECK_FALSE(detail::check_transform(uniform(1e-9f)).singular);  // |det| = 1e-27: above the floor
  CHECK_FALSE(detail::check_transform(uniform(1e6f)).singular);   // large scales stay valid
  // Relative: a matrix flattened along one axis by 1e-10 of its size, whatever the units.
  CHECK(detail::check_transform(instance_transform(glm::scale(glm::mat4(1.0f), glm::vec3(1e4f, 1e4f, 1e-6f)))).singular);
  // The rule reads elements through an accessor, so the backend applies it to a glm::mat4 in place.
  const glm::mat4 m = glm::scale(glm::mat4(1.0f), glm::vec3(1e-11f));
  CHECK(detail::check_transform_at([&m](int r, int c) { return m[c][r]; }).singular);
  glm::mat4 moved(1.0f);
  moved[3][1] = k_nan;  // column 3 (translation), row 1
  const detail::TransformCheck nan = detail::check_transform_at([&moved](int r, int c) { return moved[c][r]; });
  CHECK(nan.row == 1);
  CHECK(nan.column == 3);
}

TEST_CASE("geometry descriptions are validated as a whole") {
  const TriangleMesh tri{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2}};
  CHECK_NOTHROW(validate(GeometryDesc::triangles(tri), "Plane", "op"));
  CHECK_NOTHROW(validate(GeometryDesc::procedural({Aabb{}, Aabb{}}), "Boxes", "op"));
  CHECK_THROWS_WITH_AS(validate(GeometryDesc::procedural({}), "Empty", "op"),
                       doctest::Contains("op: geometry \"Empty\" is procedural with no AABB"), InvalidGeometryError);
  CHECK_THROWS_WITH_AS(validate(GeometryDesc::procedural({Aabb{}, Aabb{glm::vec3(1), glm::vec3(0)}}), "Bad", "op"),
                       doctest::Contains("geometry \"Bad\" AABB 1 has min"), InvalidGeometryError);
  CHECK_THROWS_WITH_AS(validate(GeometryDesc::triangles({tri.vertices, {0, 1}}), "Mesh", "op"),
                       doctest::Contains("non-zero multiple of 3"), InvalidGeometryError);
  CHECK_THROWS_WITH_AS(validate(GeometryDesc::triangles({tri.vertices, {0, 1, 3}}), "Mesh", "op"),
                       doctest::Contains("index 2 is 3 but there are 3 vertices"), InvalidGeometryError);
  CHECK_THROWS_WITH_AS(validate(GeometryDesc::triangles({{{0, 0, 0}, {k_nan, 0, 0}, {0, 1, 0}}, {0, 1, 2}}), "Mesh", "op"),
                       doctest::Contains("vertex 1"), InvalidGeometryError);
  CHECK_THROWS_WITH_AS(validate(GeometryDesc::procedural({Aabb{}}, {identity_transform(), InstanceTransform{}}), "P", "op"),
                       doctest::Contains("instance 1 transform is singular"), InvalidGeometryError);
}
