// Benchmark (not a test): the flops one distance evaluation of each paper-scene fractal costs,
// counted from its code. The float march of every camera ray through the object's box (the C++
// mirror of marching/marcher.glsl, the scene's default knobs) records where it evaluates; each
// point is evaluated again with a counting float (proceduray/shader/counted_float.hpp), so the count follows the
// shader's own control flow (an orbit that escapes early costs less).
//
//   bench_flops [--size 640x360]
//
// With bench_peak's FLOP/s and a device's evaluations per second, it gives the fraction of the
// peak a march reaches: evaluations/s x flops/evaluation / peak.
#include "02_paper_scene/frame.hpp"

#include <proceduray/march/primitives_glsl.hpp>
#include <proceduray/shader/counted_float.hpp>

#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>
#include <vector>

namespace flops_bench {
using namespace proceduray::glsl_cpp;
inline std::vector<glm::vec3>* recorded = nullptr;  // where the current march's evaluations go
inline std::uint32_t bulb_iterations = 8, julia_iterations = 10;
inline glm::vec4 julia_c{}, julia_cut{};
#include "common/ray.glsl"
using MarchKnobs = proceduray::MarchKnobs;
#include "marching/knobs.glsl"
struct Bulb {};
inline float bulb_distance(vec3 p, Bulb) {
  recorded->push_back(p);
  return proceduray::glsl::mandelbulb<float>::mandelbulb_distance(p, bulb_iterations);
}
#define PROCEDURAY_MARCHER bulb
#define PROCEDURAY_MARCHER_FIELD Bulb
#define PROCEDURAY_MARCHER_DISTANCE bulb_distance
#include "marching/marcher.glsl"
struct Julia {};
inline float julia_distance(vec3 p, Julia) {
  recorded->push_back(p);
  return proceduray::glsl::julia<float>::julia_cuts_distance(p, julia_c, julia_iterations, julia_cut, julia_cut, 1u);
}
#define PROCEDURAY_MARCHER julia
#define PROCEDURAY_MARCHER_FIELD Julia
#define PROCEDURAY_MARCHER_DISTANCE julia_distance
#include "marching/marcher.glsl"
}  // namespace flops_bench

namespace {

using proceduray::CountedFloat;
using V3 = glm::vec<3, CountedFloat>;
using V4 = glm::vec<4, CountedFloat>;

V3 counted(glm::vec3 p) { return V3(CountedFloat(p.x), CountedFloat(p.y), CountedFloat(p.z)); }
V4 counted(glm::vec4 p) { return V4(CountedFloat(p.x), CountedFloat(p.y), CountedFloat(p.z), CountedFloat(p.w)); }

struct Object {
  const char* name;
  paper::ObjectId id;
  proceduray::Placement placement;
  proceduray::Aabb box;
};

/// The evaluation points of every camera ray's march through `o`'s box.
std::vector<glm::vec3> march_points(const paper::Frame& f, const Object& o, std::uint32_t w, std::uint32_t h,
                                    std::uint64_t& rays) {
  using namespace flops_bench;
  std::vector<glm::vec3> points;
  recorded = &points;
  const proceduray::Camera& c = f.camera;
  const glm::vec3 eye = (glm::vec3(c.eye) - o.placement.translation) / o.placement.scale;
  for (std::uint32_t y = 0; y < h; ++y) {
    for (std::uint32_t x = 0; x < w; ++x) {
      const glm::vec2 uv = (glm::vec2(float(x), float(y)) + 0.5f) / glm::vec2(float(w), float(h)) * 2.0f - 1.0f;
      const glm::vec3 dir = glm::normalize(glm::vec3(c.forward) + uv.x * glm::vec3(c.right) - uv.y * glm::vec3(c.up));
      const glm::vec3 d = dir / o.placement.scale;
      float t0 = 0.0f, t1 = 1.0e30f;
      if (!ray_clip_aabb(eye, d, o.box.min, o.box.max, t0, t1)) continue;
      ++rays;
      const float len = length(d);
      const MarchSettings m = march_settings(f.knobs[o.id], std::max(length(dir) / len, 1e-20f), c.pixel_angle, 1.0f);
      float s = 0.0f;
      std::uint32_t steps = 0;
      if (o.id == paper::mandelbulb_id) bulb_trace(eye, d / len, t0 * len, t1 * len, m, {}, s, steps);
      else julia_trace(eye, d / len, t0 * len, t1 * len, m, {}, s, steps);
    }
  }
  recorded = nullptr;
  return points;
}

}  // namespace

int main(int argc, char** argv) {
  std::string size = "640x360";
  CLI::App app{"Flops per distance evaluation of the paper scene's fractals, counted from their code"};
  app.add_option("--size", size, "image size WxH of the camera rays")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  unsigned w = 0, h = 0;
  if (std::sscanf(size.c_str(), "%ux%u", &w, &h) != 2 || w == 0 || h == 0 || w > 8192 || h > 8192) {
    std::fprintf(stderr, "bench_flops: --size '%s' is not WxH up to 8192x8192, e.g. 640x360\n", size.c_str());
    return 2;
  }
  const paper::Frame f = paper::default_frame(w, h, 0.0f);
  flops_bench::bulb_iterations = f.knobs[paper::mandelbulb_id].iterations;
  flops_bench::julia_iterations = f.knobs[paper::julia_id].iterations;
  flops_bench::julia_c = proceduray::glsl::julia<float>::julia_animated_c(f.time);
  flops_bench::julia_cut = paper::julia_cut;
  const Object objects[] = {{"mandelbulb", paper::mandelbulb_id, paper::mandelbulb_placement, paper::mandelbulb_aabb},
                            {"julia", paper::julia_id, paper::julia_placement, paper::julia_aabb}};
  std::printf("camera rays at %ux%u, the paper scene's default knobs; flops: + - * / and each sqrt, log, sin, ... count 1\n", w, h);
  for (const Object& o : objects) {
    std::uint64_t rays = 0;
    const std::vector<glm::vec3> points = march_points(f, o, w, h, rays);
    CountedFloat::reset();
    float sink = 0.0f;
    for (const glm::vec3& p : points) {
      if (o.id == paper::mandelbulb_id) {
        sink += proceduray::glsl::mandelbulb<CountedFloat>::mandelbulb_distance(counted(p), flops_bench::bulb_iterations).value();
      } else {
        sink += proceduray::glsl::julia<CountedFloat>::julia_cuts_distance(counted(p), counted(flops_bench::julia_c),
                                                                          flops_bench::julia_iterations,
                                                                          counted(flops_bench::julia_cut),
                                                                          counted(flops_bench::julia_cut), 1u).value();
      }
    }
    const double distance_flops = static_cast<double>(CountedFloat::count()) / static_cast<double>(points.size());
    // The paper's Julia field also forms its constant per evaluation (julia_animated_c(time)).
    CountedFloat::reset();
    if (o.id == paper::julia_id) sink += proceduray::glsl::julia<CountedFloat>::julia_animated_c(CountedFloat(f.time)).x.value();
    const double per_call = static_cast<double>(CountedFloat::count());
    std::printf("%-10s %7.1f flops per evaluation (%.0f distance + %.0f forming c), over %zu evaluations of %llu rays "
                "(%.1f per ray)%s\n",
                o.name, distance_flops + per_call, distance_flops, per_call, points.size(),
                static_cast<unsigned long long>(rays), static_cast<double>(points.size()) / static_cast<double>(rays),
                sink == 12345.0f ? " " : "");
  }
  return 0;
}
