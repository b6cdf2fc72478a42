// Shared by the scene tests: the measured device profiles as constants, synthetic ones,
// layout invariants, and the two hand-made scenes (the report's, the D3D12 sample's).
#pragma once

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "proceduray/scene/compile.hpp"
#include "proceduray/scene/device_limits.hpp"
#include "proceduray/scene/plan.hpp"
#include "proceduray/scene/sbt_layout.hpp"
#include "proceduray/scene/scene.hpp"
#include "proceduray/shader/field_list.hpp"

namespace proceduray::test {

// shared/device-profiles/lavapipe-mesa-25.0.7.json (llvmpipe, Mesa 25.0.7, Vulkan 1.4.305)
inline const DeviceLimits lavapipe_limits{
    .sbt = {.handle_size = 32, .handle_alignment = 16, .base_alignment = 32, .max_stride = 16384},
    .max_ray_recursion_depth = 31, .max_ray_hit_attribute_size = 32,
    .max_geometry_count = 16777215, .max_instance_count = 16777215, .device = "llvmpipe"};

// shared/device-profiles/nvidia-h100-580.json (NVIDIA H100 80GB HBM3, driver 580.159.04)
inline const DeviceLimits h100_limits{
    .sbt = {.handle_size = 32, .handle_alignment = 32, .base_alignment = 64, .max_stride = 4096},
    .max_ray_recursion_depth = 31, .max_ray_hit_attribute_size = 32,
    .max_geometry_count = 16777215, .max_instance_count = 16777215, .device = "NVIDIA H100 80GB HBM3"};

// shared/device-profiles/nvidia-h200-580.json (NVIDIA H200, driver 580.159.04): the H100's numbers,
// kept as its own profile so a driver that changes one of them shows up here.
inline const DeviceLimits h200_limits{
    .sbt = {.handle_size = 32, .handle_alignment = 32, .base_alignment = 64, .max_stride = 4096},
    .max_ray_recursion_depth = 31, .max_ray_hit_attribute_size = 32,
    .max_geometry_count = 16777215, .max_instance_count = 16777215, .device = "NVIDIA H200"};

/// Synthetic profiles the issue names.
inline constexpr SbtProperties synthetic_32_32_64{.handle_size = 32, .handle_alignment = 32, .base_alignment = 64, .max_stride = 4096};
inline constexpr SbtProperties synthetic_64_64_256{.handle_size = 64, .handle_alignment = 64, .base_alignment = 256, .max_stride = 4096};
inline constexpr SbtProperties synthetic_small_stride{.handle_size = 32, .handle_alignment = 16, .base_alignment = 32, .max_stride = 4096};

/// Every profile SBT tests run over.
inline std::vector<SbtProperties> all_sbt_profiles() {
  return {lavapipe_limits.sbt, h100_limits.sbt, h200_limits.sbt, synthetic_32_32_64, synthetic_64_64_256,
          synthetic_small_stride};
}
/// Device limits for every profile (synthetic ones keep lavapipe's non-SBT limits).
inline std::vector<DeviceLimits> all_limits() {
  std::vector<DeviceLimits> out;
  for (const SbtProperties& p : all_sbt_profiles()) {
    DeviceLimits l = lavapipe_limits;
    l.sbt = p;
    out.push_back(l);
  }
  return out;
}

/// Checks what every layout must satisfy: aligned starts, specified strides, raygen size
/// == stride, strides within the maximum, regions in order without overlap.
inline void check_layout_invariants(const SbtLayout& layout, const std::array<SbtRegionRecords, 4>& in) {
  const SbtProperties& p = layout.properties;
  std::uint64_t end = 0;
  for (std::uint32_t k = 0; k < 4; ++k) {
    const SbtRegion& r = layout.regions[k];
    CHECK(r.count == in[k].count);
    if (r.count == 0) {
      CHECK(r.stride == 0);
      CHECK(r.size == 0);
      continue;
    }
    CHECK(r.offset % p.base_alignment == 0);
    CHECK(r.offset >= end);
    CHECK(r.stride % p.handle_alignment == 0);
    CHECK(r.stride >= p.handle_size + in[k].max_arguments_size);
    CHECK(r.stride <= p.max_stride);
    if (k == 0) {
      CHECK(r.stride % p.base_alignment == 0);
      CHECK(r.stride == detail::align_up(p.handle_size + in[k].max_arguments_size, p.base_alignment));
      CHECK(r.size == r.stride);
    } else {
      CHECK(r.stride == detail::align_up(p.handle_size + in[k].max_arguments_size, p.handle_alignment));
      CHECK(r.size == r.stride * r.count);
    }
    for (std::uint32_t i = 0; i < r.count; ++i) {
      const auto kind = static_cast<SbtRegionKind>(k);
      CHECK(layout.record_offset(kind, i) == r.offset + i * r.stride);
      CHECK(layout.arguments_offset(kind, i) + in[k].max_arguments_size <= layout.record_offset(kind, i) + r.stride);
    }
    end = r.offset + r.stride * r.count;
  }
  CHECK(layout.size == end);
}

// ---- The report's scene (Listings 2-4, 9, 10): 2 rays, 8 hit groups, a triangle plane and three fractals.
struct RayPayload { glm::vec4 color; std::uint32_t depth; };
struct ShadowPayload { std::uint32_t hit; };
struct FractalAttributes { glm::vec3 normal; float distance; };
struct MaterialCb { glm::vec4 albedo; float reflectance; float diffuse; float specular; float power; };
struct TriangleRootArguments { MaterialCb material; };
struct ProceduralRootArguments { MaterialCb material; std::uint32_t instance_index; std::uint32_t primitive_type; };
PROCEDURAY_STRUCT(RayPayload, scalar, color, depth);
PROCEDURAY_STRUCT(ShadowPayload, scalar, hit);
PROCEDURAY_STRUCT(FractalAttributes, scalar, normal, distance);
PROCEDURAY_STRUCT(MaterialCb, scalar, albedo, reflectance, diffuse, specular, power);
PROCEDURAY_STRUCT(TriangleRootArguments, scalar, material);
PROCEDURAY_STRUCT(ProceduralRootArguments, scalar, material, instance_index, primitive_type);
using ReportInterface = ShaderInterface<Payload<RayPayload, ShadowPayload>, RootComponent<>,
                                        RootArguments<TriangleRootArguments, ProceduralRootArguments>,
                                        Attributes<FractalAttributes>>;

struct ReportScene {
  Scene<ReportInterface> scene;
  RayId<RayPayload> radiance;
  RayId<ShadowPayload> shadow;
  GeometryId plane, julia, pacman, mandelbulb;
  std::array<std::uint32_t, 3> instances{2, 3, 1};  // Julia, Pacman, Mandelbulb
};

inline std::vector<InstanceTransform> translations(std::uint32_t count, float y) {
  std::vector<InstanceTransform> out;
  for (std::uint32_t i = 0; i < count; ++i) {
    out.push_back(instance_transform(glm::translate(glm::mat4(1.0f), glm::vec3(3.0f * float(i), y, 0.0f))));
  }
  return out;
}

inline void build_report_scene(ReportScene& r) {
  Scene<ReportInterface>& s = r.scene;
  r.radiance = s.add_ray<RayPayload>("Radiance", {.miss = "Miss"});
  r.shadow = s.add_ray<ShadowPayload>("Shadow", {.miss = "Miss_Shadow"});
  s.add_hit_group("Triangle", {.closest_hit = "ClosestHit_Triangle"});
  s.add_hit_group("Triangle_Shadow", {});
  for (const char* name : {"Pacman", "Mandelbulb", "Julia"}) {
    const std::string n = name;
    s.add_hit_group<FractalAttributes>(n, {.kind = HitGroupKind::procedural, .closest_hit = "ClosestHit_" + n,
                                           .intersection = "Intersection_" + n});
    s.add_hit_group<FractalAttributes>(n + "_Shadow", {.kind = HitGroupKind::procedural, .intersection = "Intersection_" + n});
  }
  TriangleMesh quad{{{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}}, {0, 1, 2, 0, 2, 3}};
  r.plane = s.add_geometry("GlobalGeometry", GeometryDesc::triangles(quad, translations(1, 0.0f)));
  r.julia = s.add_geometry("Julia", GeometryDesc::procedural({{glm::vec3(-3.5f), glm::vec3(3.5f)}}, translations(r.instances[0], 4)));
  r.pacman = s.add_geometry("Pacman", GeometryDesc::procedural({{glm::vec3(-0.5f), glm::vec3(0.5f)}}, translations(r.instances[1], 1)));
  r.mandelbulb = s.add_geometry("Mandelbulb", GeometryDesc::procedural({{glm::vec3(-1.5f), glm::vec3(1.5f)}}, translations(r.instances[2], 2)));
  s.add_global_signature("Global", {.bindings = {{.kind = BindingKind::storage_image, .binding = 0},
                                                 {.kind = BindingKind::acceleration_structure, .binding = 1},
                                                 {.kind = BindingKind::uniform_buffer, .binding = 2},
                                                 {.kind = BindingKind::storage_buffer, .binding = 3},
                                                 {.kind = BindingKind::storage_buffer, .binding = 4}}});
  s.add_local_signature<TriangleRootArguments>("Triangle");
  s.add_local_signature<ProceduralRootArguments>("Procedural");
}

/// The report's Listing 10 through the string-id API: common triangle entries, per-instance procedural ones.
inline void add_report_entries(ReportScene& r) {
  Scene<ReportInterface>& s = r.scene;
  s.add_raygen("Raygen");
  const TriangleRootArguments plane_args{{{0.9f, 0.9f, 0.9f, 1.0f}, 0.25f, 1.0f, 0.4f, 50.0f}};
  s.add_hit("Radiance", "Triangle", "Triangle", plane_args, "GlobalGeometry");
  s.add_hit("Shadow", "Triangle_Shadow", "Triangle", plane_args, "GlobalGeometry");
  std::uint32_t primitive = 0;
  std::uint32_t instance_index = 0;
  for (const char* name : {"Julia", "Pacman", "Mandelbulb"}) {
    const std::string n = name;
    for (std::uint32_t i = 0; i < r.instances[primitive]; ++i) {
      ProceduralRootArguments args{{{0.1f * float(primitive), 0.5f, 0.5f, 1.0f}, 0.0f, 0.9f, 0.7f, 50.0f}, instance_index, primitive};
      s.add_hit("Radiance", n, "Procedural", args, n, i);
      s.add_hit("Shadow", n + "_Shadow", "Procedural", args, n, i);
      ++instance_index;
    }
    ++primitive;
  }
  s.set_global_signature(s.global_signature_id("Global"));
  s.set_max_recursion_depth(3);
}

// ---- The D3D12 procedural-geometry sample: a triangle plane BLAS and one BLAS of 10 AABB geometries.
struct PrimitiveConstantBuffer { glm::vec4 albedo; float reflectance; float diffuse; float specular; float power; float step_scale; float pad[3]; };
struct PrimitiveInstanceConstantBuffer { std::uint32_t instance_index; std::uint32_t primitive_type; };
struct D3D12RootArguments { PrimitiveConstantBuffer material; PrimitiveInstanceConstantBuffer aabb; };
struct D3D12Attributes { glm::vec3 normal; };
PROCEDURAY_STRUCT(PrimitiveConstantBuffer, scalar, albedo, reflectance, diffuse, specular, power, step_scale, pad);
PROCEDURAY_STRUCT(PrimitiveInstanceConstantBuffer, scalar, instance_index, primitive_type);
PROCEDURAY_STRUCT(D3D12RootArguments, scalar, material, aabb);
PROCEDURAY_STRUCT(D3D12Attributes, scalar, normal);
using D3D12Interface = ShaderInterface<Payload<RayPayload, ShadowPayload>, RootComponent<>,
                                       RootArguments<D3D12RootArguments>, Attributes<D3D12Attributes>>;

inline const std::array<const char*, 10> d3d12_aabb_geometries{
    "AnalyticAABB", "AnalyticSpheres", "Metaballs", "MiniSpheres", "IntersectedRoundCube",
    "SquareTorus", "TwistedTorus", "Cog", "Cylinder", "FractalPyramid"};
/// Hit group (radiance) of each AABB geometry, in the sample's order.
inline const char* d3d12_group_of(std::uint32_t aabb) {
  return aabb < 2 ? "MyHitGroup_AABB_AnalyticPrimitive"
                  : (aabb == 2 ? "MyHitGroup_AABB_VolumetricPrimitive" : "MyHitGroup_AABB_SignedDistancePrimitive");
}

struct D3D12Scene {
  Scene<D3D12Interface> scene;
  RayId<RayPayload> radiance;
  RayId<ShadowPayload> shadow;
  GeometryId plane;
  std::array<GeometryId, 10> aabbs;
};

inline void build_d3d12_scene(D3D12Scene& d) {
  Scene<D3D12Interface>& s = d.scene;
  d.radiance = s.add_ray<RayPayload>("Radiance", {.miss = "MyMissShader"});
  d.shadow = s.add_ray<ShadowPayload>("Shadow", {.miss = "MyMissShader_ShadowRay"});
  s.add_hit_group("MyHitGroup_Triangle", {.closest_hit = "MyClosestHitShader_Triangle"});
  s.add_hit_group("MyHitGroup_Triangle_ShadowRay", {});
  for (const char* type : {"AnalyticPrimitive", "VolumetricPrimitive", "SignedDistancePrimitive"}) {
    const std::string t = type;
    s.add_hit_group<D3D12Attributes>("MyHitGroup_AABB_" + t, {.kind = HitGroupKind::procedural,
        .closest_hit = "MyClosestHitShader_AABB", .intersection = "MyIntersectionShader_" + t});
    s.add_hit_group<D3D12Attributes>("MyHitGroup_AABB_" + t + "_ShadowRay",
        {.kind = HitGroupKind::procedural, .intersection = "MyIntersectionShader_" + t});
  }
  TriangleMesh quad{{{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}}, {0, 1, 2, 0, 2, 3}};
  d.plane = s.add_geometry("Plane", GeometryDesc::triangles(quad));
  for (std::uint32_t i = 0; i < 10; ++i) {
    GeometryDesc desc = GeometryDesc::procedural({{glm::vec3(float(i) * 3.0f - 1.0f, 0.0f, -1.0f),
                                                   glm::vec3(float(i) * 3.0f + 1.0f, 2.0f, 1.0f)}},
                                                 i == 0 ? std::vector<InstanceTransform>{identity_transform()}
                                                        : std::vector<InstanceTransform>{});
    desc.blas = "AABBs";
    d.aabbs[i] = s.add_geometry(d3d12_aabb_geometries[i], std::move(desc));
  }
  s.add_local_signature<D3D12RootArguments>("Triangle");
  s.add_local_signature<D3D12RootArguments>("AABB");
}

/// Fake group handles: handle g is filled with byte g + 1.
inline std::vector<std::byte> fake_handles(const Plan& plan, const SbtLayout& layout) {
  const std::uint32_t h = layout.properties.handle_size;
  std::vector<std::byte> out(plan.pipeline().groups.size() * h);
  for (std::size_t g = 0; g < plan.pipeline().groups.size(); ++g) {
    std::fill_n(out.begin() + static_cast<std::ptrdiff_t>(g * h), h, std::byte(g + 1));
  }
  return out;
}

/// The sample's entries, added in `order` (a permutation of 0..21 over the 22 (geometry, ray) slots).
inline void add_d3d12_entries(D3D12Scene& d, const std::vector<std::uint32_t>& order) {
  Scene<D3D12Interface>& s = d.scene;
  s.add_raygen("MyRaygenShader");
  const auto tri = s.local_signature_id<D3D12RootArguments>("Triangle");
  const auto aabb = s.local_signature_id<D3D12RootArguments>("AABB");
  for (std::uint32_t slot : order) {
    const std::uint32_t geometry = slot / 2;
    const bool shadow_ray = slot % 2 == 1;
    D3D12RootArguments args{};
    args.aabb = {geometry, slot};
    args.material.albedo = glm::vec4(float(slot));
    if (geometry == 0) {
      const auto group = s.hit_group_id(shadow_ray ? "MyHitGroup_Triangle_ShadowRay" : "MyHitGroup_Triangle");
      if (shadow_ray) s.add_hit(d.shadow, group, tri, args, d.plane);
      else s.add_hit(d.radiance, group, tri, args, d.plane);
    } else {
      const std::string name = std::string(d3d12_group_of(geometry - 1)) + (shadow_ray ? "_ShadowRay" : "");
      if (shadow_ray) s.add_hit(d.shadow, s.hit_group_id(name), aabb, args, d.aabbs[geometry - 1]);
      else s.add_hit(d.radiance, s.hit_group_id(name), aabb, args, d.aabbs[geometry - 1]);
    }
  }
}

/// The sample's scene with its entries in slot order.
inline void build_d3d12_scene_in_order(D3D12Scene& d) {
  build_d3d12_scene(d);
  std::vector<std::uint32_t> order(22);
  for (std::uint32_t k = 0; k < order.size(); ++k) order[k] = k;
  add_d3d12_entries(d, order);
}

}  // namespace proceduray::test
