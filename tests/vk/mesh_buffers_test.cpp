// vk/mesh_buffers.hpp through the renderer: a hit shader reads its triangle's vertex structs via
// the MeshRef in its record, and interpolates them at the hit's barycentrics. Every pixel of the
// floor is checked against the blend computed here from the pixel's own camera ray.
#include "frame_pixels.hpp"
#include "renderer_scene.hpp"
#include "test_context.hpp"

#include <cmath>
#include <optional>
#include <vector>

namespace mesh_buffers_test {
namespace pr = proceduray;
struct MeshVertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec3 colour;
};
PROCEDURAY_STRUCT(MeshVertex, scalar, position, normal, colour);
struct MeshArgs {
  pr::MeshRef<MeshVertex> mesh;  // the renderer writes the floor's buffers here
  std::uint32_t mode;            // 0: colour, 1: normal
  std::uint32_t pad;             // a MeshRef is 8-aligned: the struct's size is a multiple of 8
};
PROCEDURAY_STRUCT(MeshArgs, scalar, mesh, mode, pad);
using MeshInterface =
    pr::ShaderInterface<pr::Payload<renderer_scene::Colour>, pr::RootComponent<renderer_scene::Constants, renderer_scene::Tint>,
                        pr::RootArguments<MeshArgs>, pr::Attributes<>>;
}  // namespace mesh_buffers_test

using namespace proceduray;
using mesh_buffers_test::MeshArgs;
using mesh_buffers_test::MeshVertex;
namespace rs = renderer_scene;

namespace {

constexpr std::uint32_t width = 96;
constexpr std::uint32_t height = 64;

const TriangleMesh floor_mesh{{{-6, -1, -6}, {6, -1, -6}, {6, -1, 6}, {-6, -1, 6}}, {0, 2, 1, 0, 3, 2}};
const glm::vec3 corner_colours[4] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
/// Normals leaning outward at the corners: smooth shading of a flat quad, unlike its face normal (0, 1, 0).
glm::vec3 corner_normal(std::size_t i) {
  const glm::vec3 p = floor_mesh.vertices[i];
  return glm::normalize(glm::vec3(p.x, 6.0f, p.z));
}

/// The renderer over RendererScene's rays, raygen and miss, with the floor's hit record reading its mesh.
struct MeshRender {
  TestContext t;
  Scene<mesh_buffers_test::MeshInterface> scene;
  std::optional<vk::Renderer> renderer;
  explicit MeshRender(std::uint32_t mode) {
    const auto primary = scene.add_ray<rs::Colour>("primary", {.miss = "sky.rmiss"});
    const auto group = scene.add_hit_group("mesh", {.kind = HitGroupKind::triangles, .closest_hit = "mesh.rchit"});
    std::vector<MeshVertex> vertices;
    for (std::size_t i = 0; i < 4; ++i) vertices.push_back({floor_mesh.vertices[i], corner_normal(i), corner_colours[i]});
    GeometryDesc floor = GeometryDesc::triangles(floor_mesh);
    floor.vertex_data = VertexData::of(std::span<const MeshVertex>(vertices));
    const GeometryId geometry = scene.add_geometry("floor", floor);
    scene.set_global_signature(scene.add_global_signature(
        "global", {.bindings = {{BindingKind::acceleration_structure, 0, 0, 1, "tlas"},
                                {BindingKind::storage_image, 1, 0, 1, "image"}, rs::constants_slot, rs::tints_slot}}));
    scene.add_raygen("scene.rgen");
    scene.add_hit(primary, group, scene.add_local_signature<MeshArgs>("mesh"), MeshArgs{.mode = mode}, geometry);
    renderer.emplace(t.ctx, scene, rs::RendererScene::options());
    rs::prepare(*renderer, width, height);
  }
};

/// Where the camera ray of pixel (x, y) meets the floor plane y = -1, and the blend of the corner
/// values `at` there: barycentrics in the triangle holding the point, as Vulkan weighs them.
template <class At>
std::optional<glm::vec3> blend_at_pixel(int x, int y, At at) {
  const Camera c = rs::constants(width, height).camera;
  const glm::vec2 uv = (glm::vec2(x, y) + 0.5f) / glm::vec2(width, height) * 2.0f - 1.0f;
  const glm::vec3 d = glm::vec3(c.forward) + uv.x * glm::vec3(c.right) - uv.y * glm::vec3(c.up);
  if (d.y >= 0.0f) return std::nullopt;
  const glm::vec3 p = glm::vec3(c.eye) + d * ((-1.0f - c.eye.y) / d.y);
  for (std::size_t t = 0; t < 2; ++t) {
    const std::uint32_t* tri = &floor_mesh.indices[3 * t];
    const glm::vec2 a(floor_mesh.vertices[tri[0]].x, floor_mesh.vertices[tri[0]].z);
    const glm::vec2 b(floor_mesh.vertices[tri[1]].x, floor_mesh.vertices[tri[1]].z);
    const glm::vec2 e(floor_mesh.vertices[tri[2]].x, floor_mesh.vertices[tri[2]].z);
    const glm::vec2 q(p.x, p.z);
    const float area = (b.x - a.x) * (e.y - a.y) - (e.x - a.x) * (b.y - a.y);
    const float wb = ((q.x - a.x) * (e.y - a.y) - (e.x - a.x) * (q.y - a.y)) / area;
    const float we = ((b.x - a.x) * (q.y - a.y) - (q.x - a.x) * (b.y - a.y)) / area;
    const float wa = 1.0f - wb - we;
    const float margin = 0.02f;  // off the edges, where either triangle may take the ray
    if (wa < margin || wb < margin || we < margin) continue;
    return wa * at(tri[0]) + wb * at(tri[1]) + we * at(tri[2]);
  }
  return std::nullopt;
}

}  // namespace

TEST_CASE("mesh buffers: a hit shader interpolates its triangle's vertex colours through the record's MeshRef") {
  MeshRender m(0);
  const vk::Frame f = m.renderer->render(width, height);
  std::size_t checked = 0, off = 0;
  for (int y = 0; y < static_cast<int>(height); ++y) {
    for (int x = 0; x < static_cast<int>(width); ++x) {
      const auto want = blend_at_pixel(x, y, [](std::uint32_t i) { return corner_colours[i]; });
      if (!want) continue;
      ++checked;
      if (!frame_pixels::near(frame_pixels::rgb(f, {x, y}), frame_pixels::bytes(*want), 3)) ++off;
    }
  }
  CHECK(checked > width * height / 4);  // most of the image is floor
  CHECK(off == 0);
}

TEST_CASE("mesh buffers: interpolated normals follow the vertices, not the face") {
  MeshRender m(1);
  const vk::Frame f = m.renderer->render(width, height);
  const glm::ivec3 face = frame_pixels::bytes(glm::vec3(0.5f, 1.0f, 0.5f));  // (0, 1, 0) shown as n * 0.5 + 0.5
  std::size_t checked = 0, off = 0, unlike_face = 0;
  for (int y = 0; y < static_cast<int>(height); ++y) {
    for (int x = 0; x < static_cast<int>(width); ++x) {
      const auto n = blend_at_pixel(x, y, [](std::uint32_t i) { return corner_normal(i); });
      if (!n) continue;
      ++checked;
      const glm::ivec3 got = frame_pixels::rgb(f, {x, y});
      if (!frame_pixels::near(got, frame_pixels::bytes(glm::normalize(*n) * 0.5f + 0.5f), 3)) ++off;
      if (!frame_pixels::near(got, face, 8)) ++unlike_face;
    }
  }
  CHECK(checked > width * height / 4);
  CHECK(off == 0);
  CHECK(unlike_face > checked / 2);  // smooth normals: most pixels lean away from the face normal
}

TEST_CASE("mesh buffers: only geometries whose records read a mesh get buffers") {
  MeshRender m(0);
  const Plan plan = compile(m.scene);
  vk::MeshBuffers buffers(m.t.ctx, plan);
  REQUIRE(buffers.addresses().size() == 1);
  CHECK(buffers.addresses()[0].vertices != 0);
  CHECK(buffers.addresses()[0].triangles != 0);
  CHECK(buffers.bytes() >= 4 * sizeof(MeshVertex) + 6 * sizeof(std::uint32_t));
  auto unread = m.scene;  // a geometry with vertex data whose records do not read it
  GeometryDesc plain = GeometryDesc::triangles(floor_mesh);
  std::vector<MeshVertex> v(4);
  plain.vertex_data = VertexData::of(std::span<const MeshVertex>(v));
  unread.add_geometry("plain", plain);
  unread.set_default_hit(unread.ray_id<rs::Colour>("primary"), unread.hit_group_id("mesh"));
  const Plan unread_plan = compile(unread);
  vk::MeshBuffers fewer(m.t.ctx, unread_plan);
  REQUIRE(fewer.addresses().size() == 2);
  CHECK(fewer.addresses()[1].vertices == 0);
  CHECK(fewer.bytes() == buffers.bytes());
}
