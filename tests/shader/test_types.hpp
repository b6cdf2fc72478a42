// Representative GPU-visible types shared by the shader-layer tests: every member kind under
// every layout rule, nested structs, arrays, matrices, addresses (one of them recursive).
#pragma once

#include <proceduray/shader/categories.hpp>
#include <proceduray/shader/device_address.hpp>
#include <proceduray/shader/field_list.hpp>

#include <glm/glm.hpp>

#include <cstdint>

namespace shader_test {

using proceduray::DeviceAddress;

struct Sphere {
  glm::vec3 center;
  float radius;
};
PROCEDURAY_STRUCT(Sphere, scalar, center, radius);

struct Basis {
  glm::mat4x3 frame;
  glm::mat3 normal;
  float weights[3];
};
PROCEDURAY_STRUCT(Basis, scalar, frame, normal, weights);

struct ScalarMix {
  double d;
  glm::vec3 v;
  float f;
  std::uint64_t u;
  glm::ivec2 iv;
  DeviceAddress<Sphere> spheres;
  Sphere nested[2];
  glm::uvec3 grid[2][2];
};
PROCEDURAY_STRUCT(ScalarMix, scalar, d, v, f, u, iv, spheres, nested, grid);

// Scalar packs the next member into a struct's tail: the explicit pad keeps C++ and GLSL equal.
struct TailPadded {
  double d;
  float f;
  float pad;
};
PROCEDURAY_STRUCT(TailPadded, scalar, d, f, pad);

struct TailHolder {
  TailPadded tails[2];
  float after;
  float pad;
};
PROCEDURAY_STRUCT(TailHolder, scalar, tails, after, pad);

struct Light {
  glm::vec4 position;
  glm::vec3 color;
  float intensity;
  glm::uvec2 ids;
  glm::vec2 uv;
};
PROCEDURAY_STRUCT(Light, std430, position, color, intensity, ids, uv);

struct Material430 {
  glm::mat4 transform;
  glm::mat3x4 basis;
  Light lights[2];
  glm::vec4 tint;
  std::uint32_t flags[4];
  DeviceAddress<Light> more;
  std::uint64_t count;
};
PROCEDURAY_STRUCT(Material430, std430, transform, basis, lights, tint, flags, more, count);

struct ListNode {
  glm::vec4 value;
  DeviceAddress<ListNode> next;
  DeviceAddress<float> weights;
};
PROCEDURAY_STRUCT(ListNode, std430, value, next, weights);

struct Camera140 {
  glm::mat4 view;
  glm::vec4 eye;
  glm::vec3 dir;
  float fov;
  glm::vec4 planes[2];
  std::int32_t mode;
  std::uint32_t pad0;
  std::uint32_t pad1;
  std::uint32_t pad2;
};
PROCEDURAY_STRUCT(Camera140, std140, view, eye, dir, fov, planes, mode, pad0, pad1, pad2);

struct Inner140 {
  glm::vec4 a;
};
PROCEDURAY_STRUCT(Inner140, std140, a);

struct Outer140 {
  glm::vec4 head;
  Inner140 inner;
  float tail;
  float pad0;
  float pad1;
  float pad2;
};
PROCEDURAY_STRUCT(Outer140, std140, head, inner, tail, pad0, pad1, pad2);

// A small ray-tracing interface: two ray types, root arguments with an address, one attribute type.
struct RadiancePayload {
  glm::vec3 color;
  std::uint32_t depth;
};
PROCEDURAY_STRUCT(RadiancePayload, scalar, color, depth);

struct ShadowPayload {
  std::uint32_t occluded;
};
PROCEDURAY_STRUCT(ShadowPayload, scalar, occluded);

struct SphereRecord {
  DeviceAddress<Sphere> spheres;
  glm::vec4 albedo;
  std::uint32_t count;
  std::uint32_t pad;
};
PROCEDURAY_STRUCT(SphereRecord, scalar, spheres, albedo, count, pad);

struct SphereHit {
  glm::vec3 normal;
  float t;
};
PROCEDURAY_STRUCT(SphereHit, scalar, normal, t);

using Interface = proceduray::ShaderInterface<proceduray::Payload<RadiancePayload, ShadowPayload>,
                                              proceduray::RootComponent<Sphere, DeviceAddress<Sphere>>,
                                              proceduray::RootArguments<SphereRecord, Material430>,
                                              proceduray::Attributes<SphereHit>>;

}  // namespace shader_test
