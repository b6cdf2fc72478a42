// Build-time cost of the compile-time checks: 50 (+1) registered structs (every member kind, nested
// structs, addresses, three layout rules) and an interface over all of them. Compile it with and
// without -DPROCEDURAY_BASELINE (same structs, no registration) and compare user CPU time:
//   F="-std=c++20 -Wall -Wextra -Wpedantic -Werror -Iinclude -c tests/shader/build_time/fifty_types.cpp -o /tmp/f.o"
//   /usr/bin/time -f %U g++ $F; /usr/bin/time -f %U g++ $F -DPROCEDURAY_BASELINE
// Measured (g++ 12.2, shared 2-core machine, user CPU, medians of 8 runs): 0.67 s checked vs 0.42 s
// baseline when quiet (wall 0.76 vs 0.47 s), 0.94 vs 0.59 s under load: the checks cost 0.25-0.35 s
// for 51 types. CTest only checks that it compiles.
// expect-success
#include <proceduray/shader/categories.hpp>
#include <proceduray/shader/device_address.hpp>
#include <proceduray/shader/field_list.hpp>

#include <glm/glm.hpp>

#include <cstdint>

#ifdef PROCEDURAY_BASELINE
#define REGISTER(...) static_assert(true)
#else
#define REGISTER(...) PROCEDURAY_STRUCT(__VA_ARGS__)
#endif

namespace bench {

struct T00 {
  glm::vec3 position;
  float radius;
  glm::vec4 color;
  std::uint32_t flags;
  std::uint32_t pad;
};
REGISTER(T00, scalar, position, radius, color, flags, pad);

struct T01 {
  glm::mat4 transform;
  glm::vec4 corners[2];
  std::uint64_t id;
  std::uint64_t pad;
};
REGISTER(T01, std430, transform, corners, id, pad);

struct T02 {
  glm::vec2 uv;
  glm::ivec2 pixel;
  proceduray::DeviceAddress<T01> previous;
  float weights[4];
};
REGISTER(T02, scalar, uv, pixel, previous, weights);

struct T03 {
  T00 nested;
  glm::vec3 normal;
  float t;
};
REGISTER(T03, scalar, nested, normal, t);

struct T04 {
  glm::mat3x4 basis;
  glm::uvec4 ids;
  double scale;
  float near;
  float far;
};
REGISTER(T04, std430, basis, ids, scale, near, far);

struct T05 {
  glm::vec3 position;
  float radius;
  glm::vec4 color;
  std::uint32_t flags;
  std::uint32_t pad;
};
REGISTER(T05, scalar, position, radius, color, flags, pad);

struct T06 {
  glm::mat4 transform;
  glm::vec4 corners[2];
  std::uint64_t id;
  std::uint64_t pad;
};
REGISTER(T06, std430, transform, corners, id, pad);

struct T07 {
  glm::vec2 uv;
  glm::ivec2 pixel;
  proceduray::DeviceAddress<T06> previous;
  float weights[4];
};
REGISTER(T07, scalar, uv, pixel, previous, weights);

struct T08 {
  T05 nested;
  glm::vec3 normal;
  float t;
};
REGISTER(T08, scalar, nested, normal, t);

struct T09 {
  glm::mat3x4 basis;
  glm::uvec4 ids;
  double scale;
  float near;
  float far;
};
REGISTER(T09, std430, basis, ids, scale, near, far);

struct T10 {
  glm::vec3 position;
  float radius;
  glm::vec4 color;
  std::uint32_t flags;
  std::uint32_t pad;
};
REGISTER(T10, scalar, position, radius, color, flags, pad);

struct T11 {
  glm::mat4 transform;
  glm::vec4 corners[2];
  std::uint64_t id;
  std::uint64_t pad;
};
REGISTER(T11, std430, transform, corners, id, pad);

struct T12 {
  glm::vec2 uv;
  glm::ivec2 pixel;
  proceduray::DeviceAddress<T11> previous;
  float weights[4];
};
REGISTER(T12, scalar, uv, pixel, previous, weights);

struct T13 {
  T10 nested;
  glm::vec3 normal;
  float t;
};
REGISTER(T13, scalar, nested, normal, t);

struct T14 {
  glm::mat3x4 basis;
  glm::uvec4 ids;
  double scale;
  float near;
  float far;
};
REGISTER(T14, std430, basis, ids, scale, near, far);

struct T15 {
  glm::vec3 position;
  float radius;
  glm::vec4 color;
  std::uint32_t flags;
  std::uint32_t pad;
};
REGISTER(T15, scalar, position, radius, color, flags, pad);

struct T16 {
  glm::mat4 transform;
  glm::vec4 corners[2];
  std::uint64_t id;
  std::uint64_t pad;
};
REGISTER(T16, std430, transform, corners, id, pad);

struct T17 {
  glm::vec2 uv;
  glm::ivec2 pixel;
  proceduray::DeviceAddress<T16> previous;
  float weights[4];
};
REGISTER(T17, scalar, uv, pixel, previous, weights);

struct T18 {
  T15 nested;
  glm::vec3 normal;
  float t;
};
REGISTER(T18, scalar, nested, normal, t);

struct T19 {
  glm::mat3x4 basis;
  glm::uvec4 ids;
  double scale;
  float near;
  float far;
};
REGISTER(T19, std430, basis, ids, scale, near, far);

struct T20 {
  glm::vec3 position;
  float radius;
  glm::vec4 color;
  std::uint32_t flags;
  std::uint32_t pad;
};
REGISTER(T20, scalar, position, radius, color, flags, pad);

struct T21 {
  glm::mat4 transform;
  glm::vec4 corners[2];
  std::uint64_t id;
  std::uint64_t pad;
};
REGISTER(T21, std430, transform, corners, id, pad);

struct T22 {
  glm::vec2 uv;
  glm::ivec2 pixel;
  proceduray::DeviceAddress<T21> previous;
  float weights[4];
};
REGISTER(T22, scalar, uv, pixel, previous, weights);

struct T23 {
  T20 nested;
  glm::vec3 normal;
  float t;
};
REGISTER(T23, scalar, nested, normal, t);

struct T24 {
  glm::mat3x4 basis;
  glm::uvec4 ids;
  double scale;
  float near;
  float far;
};
REGISTER(T24, std430, basis, ids, scale, near, far);

struct T25 {
  glm::vec3 position;
  float radius;
  glm::vec4 color;
  std::uint32_t flags;
  std::uint32_t pad;
};
REGISTER(T25, scalar, position, radius, color, flags, pad);

struct T26 {
  glm::mat4 transform;
  glm::vec4 corners[2];
  std::uint64_t id;
  std::uint64_t pad;
};
REGISTER(T26, std430, transform, corners, id, pad);

struct T27 {
  glm::vec2 uv;
  glm::ivec2 pixel;
  proceduray::DeviceAddress<T26> previous;
  float weights[4];
};
REGISTER(T27, scalar, uv, pixel, previous, weights);

struct T28 {
  T25 nested;
  glm::vec3 normal;
  float t;
};
REGISTER(T28, scalar, nested, normal, t);

struct T29 {
  glm::mat3x4 basis;
  glm::uvec4 ids;
  double scale;
  float near;
  float far;
};
REGISTER(T29, std430, basis, ids, scale, near, far);

struct T30 {
  glm::vec3 position;
  float radius;
  glm::vec4 color;
  std::uint32_t flags;
  std::uint32_t pad;
};
REGISTER(T30, scalar, position, radius, color, flags, pad);

struct T31 {
  glm::mat4 transform;
  glm::vec4 corners[2];
  std::uint64_t id;
  std::uint64_t pad;
};
REGISTER(T31, std430, transform, corners, id, pad);

struct T32 {
  glm::vec2 uv;
  glm::ivec2 pixel;
  proceduray::DeviceAddress<T31> previous;
  float weights[4];
};
REGISTER(T32, scalar, uv, pixel, previous, weights);

struct T33 {
  T30 nested;
  glm::vec3 normal;
  float t;
};
REGISTER(T33, scalar, nested, normal, t);

struct T34 {
  glm::mat3x4 basis;
  glm::uvec4 ids;
  double scale;
  float near;
  float far;
};
REGISTER(T34, std430, basis, ids, scale, near, far);

struct T35 {
  glm::vec3 position;
  float radius;
  glm::vec4 color;
  std::uint32_t flags;
  std::uint32_t pad;
};
REGISTER(T35, scalar, position, radius, color, flags, pad);

struct T36 {
  glm::mat4 transform;
  glm::vec4 corners[2];
  std::uint64_t id;
  std::uint64_t pad;
};
REGISTER(T36, std430, transform, corners, id, pad);

struct T37 {
  glm::vec2 uv;
  glm::ivec2 pixel;
  proceduray::DeviceAddress<T36> previous;
  float weights[4];
};
REGISTER(T37, scalar, uv, pixel, previous, weights);

struct T38 {
  T35 nested;
  glm::vec3 normal;
  float t;
};
REGISTER(T38, scalar, nested, normal, t);

struct T39 {
  glm::mat3x4 basis;
  glm::uvec4 ids;
  double scale;
  float near;
  float far;
};
REGISTER(T39, std430, basis, ids, scale, near, far);

struct T40 {
  glm::vec3 position;
  float radius;
  glm::vec4 color;
  std::uint32_t flags;
  std::uint32_t pad;
};
REGISTER(T40, scalar, position, radius, color, flags, pad);

struct T41 {
  glm::mat4 transform;
  glm::vec4 corners[2];
  std::uint64_t id;
  std::uint64_t pad;
};
REGISTER(T41, std430, transform, corners, id, pad);

struct T42 {
  glm::vec2 uv;
  glm::ivec2 pixel;
  proceduray::DeviceAddress<T41> previous;
  float weights[4];
};
REGISTER(T42, scalar, uv, pixel, previous, weights);

struct T43 {
  T40 nested;
  glm::vec3 normal;
  float t;
};
REGISTER(T43, scalar, nested, normal, t);

struct T44 {
  glm::mat3x4 basis;
  glm::uvec4 ids;
  double scale;
  float near;
  float far;
};
REGISTER(T44, std430, basis, ids, scale, near, far);

struct T45 {
  glm::vec3 position;
  float radius;
  glm::vec4 color;
  std::uint32_t flags;
  std::uint32_t pad;
};
REGISTER(T45, scalar, position, radius, color, flags, pad);

struct T46 {
  glm::mat4 transform;
  glm::vec4 corners[2];
  std::uint64_t id;
  std::uint64_t pad;
};
REGISTER(T46, std430, transform, corners, id, pad);

struct T47 {
  glm::vec2 uv;
  glm::ivec2 pixel;
  proceduray::DeviceAddress<T46> previous;
  float weights[4];
};
REGISTER(T47, scalar, uv, pixel, previous, weights);

struct T48 {
  T45 nested;
  glm::vec3 normal;
  float t;
};
REGISTER(T48, scalar, nested, normal, t);

struct T49 {
  glm::mat3x4 basis;
  glm::uvec4 ids;
  double scale;
  float near;
  float far;
};
REGISTER(T49, std430, basis, ids, scale, near, far);

struct Hit {
  glm::vec3 normal;
  float t;
};
REGISTER(Hit, scalar, normal, t);

#ifndef PROCEDURAY_BASELINE
using Interface = proceduray::ShaderInterface<proceduray::Payload<T00, T03>, proceduray::RootComponent<>,
                                              proceduray::RootArguments<T00, T01, T02, T03, T04, T05, T06, T07, T08, T09, T10, T11, T12, T13, T14, T15, T16, T17, T18, T19, T20, T21, T22, T23, T24, T25, T26, T27, T28, T29, T30, T31, T32, T33, T34, T35, T36, T37, T38, T39, T40, T41, T42, T43, T44, T45, T46, T47, T48, T49>,
                                              proceduray::Attributes<Hit>>;
static_assert(Interface::max_root_arguments_size == sizeof(T01));
#endif

}  // namespace bench
