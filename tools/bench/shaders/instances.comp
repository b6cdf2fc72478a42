#version 460
// bench_instances' compute peer: the library's scene without a ray-tracing pipeline. Each pixel's
// camera ray tests every instance's box in turn (no acceleration structure) and marches the
// boxes it enters with the same marcher, setup and knobs as the field's generated intersection
// (marching/marcher.glsl, marching/field_march.glsl), keeping the closest hit, as the pipeline
// does. The preamble declares Push (Camera, MarchKnobs, count, size) as `push`.
#extension GL_EXT_scalar_block_layout : require
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, scalar) writeonly buffer Pixels { uint rgba[]; } pixels;
// Each instance as world-to-object: object = w * world + xyz (w = 1 / scale, xyz = -translation / scale),
// the matrix a ray-tracing implementation applies to a ray entering the instance.
layout(set = 0, binding = 1, scalar) readonly buffer Instances { vec4 to_object[]; } instances;
// Distance evaluations per pixel, the normals' included: the library's by construction (same rays, same marcher).
layout(set = 0, binding = 2, scalar) writeonly buffer Evaluations { uint count[]; } evaluations;

#include "instances.glsl"
#include "common/camera.glsl"
#include "marching/field_march.glsl"
#define PROCEDURAY_MARCHER peer
#define PROCEDURAY_MARCHER_FIELD uint
#define PROCEDURAY_MARCHER_DISTANCE bench_bulb
#include "marching/marcher.glsl"

void main() {
  uvec2 px = gl_GlobalInvocationID.xy;
  uvec2 size = uvec2(push.width, push.height);
  if (px.x >= size.x || px.y >= size.y) return;
  vec3 eye = push.camera.eye.xyz;
  vec3 dir = camera_ray(push.camera, px, size);
  MarchKnobs k = push.knobs;
  float closest = 1e30;
  vec3 normal = vec3(0.0);
  bool any = false;
  uint evaluated = 0u;
  for (uint i = 0u; i < push.count; ++i) {
    vec4 m = instances.to_object[i];
    FieldMarch fm;
    if (!field_march_setup(m.w * eye + m.xyz, m.w * dir, 0.0, closest, length(dir),
                           vec3(-push.box), vec3(push.box), k, push.camera.pixel_angle, 1.0, fm)) {
      continue;
    }
    uint iterations = march_iterations(k, fm.footprint);
    float s;
    uint steps;
    bool found = peer_trace(fm.o, fm.u, fm.range.x, fm.range.y, fm.m, iterations, s, steps);
    evaluated += steps;
    float t = s / fm.len;
    if (!found || !t_in_range(t, 0.0, closest)) continue;
    evaluated += march_normal_evaluations(k);
    closest = t;
    vec3 p = fm.o + s * fm.u;
    normal = peer_normal(uint(k.normal), p, field_normal_offset(k, fm.m, p, s), iterations);
    any = true;
  }
  evaluations.count[px.y * size.x + px.x] = evaluated;
  pixels.rgba[px.y * size.x + px.x] = packUnorm4x8(vec4(any ? bench_shade(normal) : vec3(0.0), 1.0));
}
