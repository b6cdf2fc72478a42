#version 460
// bench_paper_peer: the paper scene (examples/02_paper_scene) without a ray-tracing pipeline.
// Every ray tests every object in turn (the plane, two Pac-men, the Julia set and the
// Mandelbulb), with the library's primitives, marchers, knobs and march setup; the pixel is
// shaded as the example's iterative raygen loop does (surface.glsl with PAPER_ITERATIVE):
// Phong with a shadow ray, then the Schlick-weighted reflection, level by level. The preamble
// declares SceneConstants, MaterialRecord, MarchKnobs, Push (as `push`) and the flag_* consts.
#extension GL_EXT_scalar_block_layout : require
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, scalar) writeonly buffer Pixels { uint rgba[]; } pixels;
layout(set = 0, binding = 1, scalar) readonly buffer Scene { SceneConstants constants; } scene;
// Per procedural object (Pac-man 0, Pac-man 1, Julia, Mandelbulb): world to object as three rows.
layout(set = 0, binding = 2, scalar) readonly buffer Objects { vec4 rows[12]; } objects;
// Per object id (plane 1 .. Mandelbulb 5; 0 unused): its material.
layout(set = 0, binding = 3, scalar) readonly buffer Materials { MaterialRecord data[6]; } materials;
// Distance evaluations per pixel, over every ray of the pixel.
layout(set = 0, binding = 4, scalar) writeonly buffer Evaluations { uint count[]; } evaluations;

#include "common/camera.glsl"
#include "common/ray.glsl"
#include "primitives/pacman.glsl"
#include "fractals.glsl"
#include "marching/field_march.glsl"
#include "shading/whitted.glsl"

float peer_julia(vec3 p, uint iterations) {
  return julia_field(p, iterations, scene.constants.time, scene.constants.julia_cuts);
}
float peer_bulb(vec3 p, uint iterations) { return mandelbulb_field(p, iterations, scene.constants.time); }
#define PROCEDURAY_MARCHER peer_julia_march
#define PROCEDURAY_MARCHER_FIELD uint
#define PROCEDURAY_MARCHER_DISTANCE peer_julia
#include "marching/marcher.glsl"
#define PROCEDURAY_MARCHER peer_bulb_march
#define PROCEDURAY_MARCHER_FIELD uint
#define PROCEDURAY_MARCHER_DISTANCE peer_bulb
#include "marching/marcher.glsl"

const float ray_far = 1.0e30;
uint evaluated = 0u;

/// The closest hit so far: t, world normal, object id, how far secondary rays start off it.
struct Hit {
  float t;
  vec3 n;
  uint object;
  float offset;
};

/// Object i's world-to-object transform applied to a point (w = 1) or a direction (w = 0).
vec3 to_object(uint i, vec4 v) {
  return vec3(dot(objects.rows[3u * i], v), dot(objects.rows[3u * i + 1u], v), dot(objects.rows[3u * i + 2u], v));
}
/// An object-space normal of object i in world space (the inverse transpose), unit.
vec3 normal_to_world(uint i, vec3 n, vec3 fallback) {
  mat3 m = mat3(objects.rows[3u * i].xyz, objects.rows[3u * i + 1u].xyz, objects.rows[3u * i + 2u].xyz);
  return safe_normalize(m * n, fallback);  // columns are the rows: transpose(world to object) * n
}

/// Marches field `which` (2 Julia, 3 Mandelbulb) of object slot i for o + t d over [t0, t1]; true
/// with t, the world normal and the offset when it hits. `hit_only`: a shadow ray's (no
/// bisection, no normal), as marching/field.glsl does.
bool march_field(uint i, vec3 o, vec3 d, float t0, float t1, bool hit_only, out float t, out vec3 n, out float offset) {
  vec3 box = i == 2u ? vec3(1.5) : vec3(1.25);
  MarchKnobs k;  // by branch: a ?: between two push-constant structs stores a mismatched type (glslang)
  if (i == 2u) k = push.julia;
  else k = push.bulb;
  FieldMarch fm;
  t = 0.0;
  n = vec3(0.0, 1.0, 0.0);
  offset = 0.0;
  if (!field_march_setup(to_object(i, vec4(o, 1.0)), to_object(i, vec4(d, 0.0)), t0, t1, length(d), -box, box, k,
                         scene.constants.camera.pixel_angle, 1.0, fm)) {
    return false;
  }
  if (hit_only && fm.m.hit_rule == march_hit_refined) fm.m.hit_rule = march_hit_unrefined;
  uint iterations = march_iterations(k, fm.footprint);
  float s;
  uint steps;
  bool found = i == 2u ? peer_julia_march_trace(fm.o, fm.u, fm.range.x, fm.range.y, fm.m, iterations, s, steps)
                       : peer_bulb_march_trace(fm.o, fm.u, fm.range.x, fm.range.y, fm.m, iterations, s, steps);
  evaluated += steps;
  t = s / fm.len;
  if (!found || !t_in_range(t, t0, t1)) return false;
  if (hit_only) return true;
  vec3 p = fm.o + s * fm.u;
  float h = field_normal_offset(k, fm.m, p, s);
  vec3 on = vec3(0.0, 1.0, 0.0);
  if (i == 2u) {
    if (!julia_field_normal(p, iterations, scene.constants.time, scene.constants.julia_cuts, on)) {
      on = peer_julia_march_normal(uint(k.normal), p, h, iterations);
      evaluated += march_normal_evaluations(k);
    }
  } else {
    on = peer_bulb_march_normal(uint(k.normal), p, h, iterations);
    evaluated += march_normal_evaluations(k);
  }
  n = normal_to_world(i, on, -d);
  // FieldHit::threshold in world units, doubled: where shade.rchit starts secondary rays.
  offset = 2.0 * march_epsilon(fm.m, t * fm.len) * length(d) / fm.len;
  return true;
}

/// The first (any_hit) or closest hit of o + t d over (t0, t1) among every object.
bool trace(vec3 o, vec3 d, float t0, float t1, bool any_hit, out Hit hit) {
  hit.t = t1;
  hit.n = vec3(0.0, 1.0, 0.0);
  hit.object = 0u;
  hit.offset = 0.0;
  // The plane y = 0 within plane_min .. plane_max (x, z): two triangles in the library.
  if (d.y != 0.0) {
    float t = -o.y / d.y;
    vec3 p = o + t * d;
    if (t > t0 && t < hit.t && p.x >= plane_min.x && p.x <= plane_max.x && p.z >= plane_min.y && p.z <= plane_max.y) {
      hit = Hit(t, vec3(0.0, 1.0, 0.0), plane_id, 0.0);
      if (any_hit) return true;
    }
  }
  for (uint i = 0u; i < 2u; ++i) {  // the Pac-men: exact, by interval CSG
    vec3 oo = to_object(i, vec4(o, 1.0)), od = to_object(i, vec4(d, 0.0));
    float a = t0, b = hit.t;
    float t;
    vec3 n;
    if (!ray_clip_aabb(oo, od, vec3(-1.0), vec3(1.0), a, b)) continue;
    if (!pacman_intersect(oo, od, scene.constants.pacman_mouth, a, b, t, n)) continue;
    hit = Hit(t, normal_to_world(i, n, -d), pacman0_id + i, 1.0e-4);
    if (any_hit) return true;
  }
  for (uint i = 2u; i < 4u; ++i) {
    float t, offset;
    vec3 n;
    if (!march_field(i, o, d, t0, hit.t, any_hit, t, n, offset)) continue;
    hit = Hit(t, n, i == 2u ? julia_id : mandelbulb_id, offset);
    if (any_hit) return true;
  }
  return hit.object != 0u;
}

vec3 sky(vec3 d) {
  float up = clamp(d.y / max(length(d), 1.0e-30), 0.0, 1.0);
  vec3 horizon = mix(scene.constants.sky_colour, vec3(1.0), 0.6);
  return mix(horizon, scene.constants.sky_colour, sqrt(up));
}

void main() {
  uvec2 px = gl_GlobalInvocationID.xy;
  uvec2 size = uvec2(push.width, push.height);
  if (px.x >= size.x || px.y >= size.y) return;
  SceneConstants c = scene.constants;
  vec3 origin = c.camera.eye.xyz;
  vec3 dir = camera_ray(c.camera, px, size);
  vec3 pixel = vec3(0.0);
  float weight = 1.0, path = 0.0;
  uint depth_max = min(c.max_depth, max_depth_limit);
  for (uint depth = 0u; depth < depth_max; ++depth) {
    Hit h;
    vec3 o = origin - path * dir;  // t counts the whole path from the eye, as the library's rays do
    if (!trace(o, dir, path, path + ray_far, false, h)) {
      pixel += weight * sky(dir);
      break;
    }
    MaterialRecord mat = materials.data[h.object];
    vec3 p = o + h.t * dir;
    vec3 albedo = mat.albedo;
    if (mat.checker_size > 0.0) {
      ivec2 cell = ivec2(floor(vec2(p.x, p.z) / mat.checker_size));
      if (((cell.x + cell.y) & 1) != 0) albedo = mat.albedo_alt;
    }
    vec3 v = -safe_normalize(dir, h.n);
    vec3 n = whitted_facing(h.n, v);
    vec3 to_light = c.light_position - p;
    float dist = length(to_light);
    vec3 l = safe_normalize(to_light, n);
    vec3 next = offset_ray_origin(p + h.offset * n, n);
    WhittedMaterial m = WhittedMaterial(albedo, mat.diffuse, mat.specular, mat.shininess,
                                        (c.flags & flag_reflections) != 0u ? mat.reflectance : 0.0);
    bool shadows = (c.flags & flag_shadows) != 0u;
    vec3 direct = dot(n, l) > 0.0 || !shadows ? whitted_phong(n, v, l, c.light_colour, m) : vec3(0.0);
    vec3 local = c.ambient * albedo;
    float visible = 1.0;
    if (shadows && dot(n, l) > 0.0) {
      Hit blocker;
      visible = trace(next - h.t * l, l, h.t, h.t + dist, true, blocker) ? 0.0 : 1.0;
    }
    local += visible * direct;
    float f = whitted_fresnel(m, n, v);
    if (depth + 1u >= depth_max || weight * f < c.min_weight) f = 0.0;
    pixel += weight * (1.0 - f) * local;
    if (f == 0.0) break;
    weight *= f;
    origin = next;
    dir = reflect(-v, n);
    path = h.t;
  }
  evaluations.count[px.y * size.x + px.x] = evaluated;
  pixels.rgba[px.y * size.x + px.x] = packUnorm4x8(vec4(pow(clamp(pixel, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0));
}
