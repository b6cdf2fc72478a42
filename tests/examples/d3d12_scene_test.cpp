// examples/03_d3d12_scene: the host checks, the hit table, and every primitive rendered alone
// through the Renderer against the same GLSL compiled as C++ (coverage, AABB clip, no NaN).
#include <proceduray/shader/glsl_cpp.hpp>

#include <proceduray/march/knobs.hpp>

namespace d3d12_cpu {
using namespace proceduray::glsl_cpp;
using proceduray::MarchKnobs;
#include "primitives/d3d12_knobs.glsl"
}  // namespace d3d12_cpu

#include "vk/test_context.hpp"

#include <03_d3d12_scene/d3d12_scene.hpp>

#include <set>

using namespace proceduray;

namespace {

constexpr std::uint32_t size = 64;

/// The isolated layout's renderer: one camera per primitive, nothing else in view.
struct Alone {
  d3d12::D3d12Scene scene;
  vk::Renderer renderer;
  explicit Alone(const vk::Context& ctx, OutputSet outputs = {})
      : scene(d3d12::default_primitives(), d3d12::Layout::isolated, outputs),
        renderer(ctx, scene, d3d12::renderer_options()) {}
};

d3d12::SceneConstants debug_constants(const Camera& camera, float time, MarchMethod metaball_method = MarchMethod::fixed) {
  d3d12::SceneConstants c = d3d12::default_constants(camera, time);
  c.flags = d3d12::flag_debug;
  d3d12::knobs(c, d3d12::metaballs).method = metaball_method;
  return c;
}

/// The CPU's answer for pixel (x, y): the ray's AABB clip and the primitive's hit, in local space.
struct CpuPixel {
  bool in_aabb = false, hit = false;
  float steps = 0;  ///< distance or field evaluations, hit or miss
};
CpuPixel cpu_pixel(const d3d12::Primitive& p, d3d12::SceneConstants c, std::uint32_t x, std::uint32_t y,
                   float footprint_scale = -1.0f, float jitter = 0.0f) {
  MarchKnobs k = c.knobs[d3d12::object_id(p.kind)];
  if (footprint_scale >= 0.0f) k.threshold = footprint_scale;
  const float u = (static_cast<float>(x) + 0.5f + jitter) / size * 2.0f - 1.0f;
  const float v = (static_cast<float>(y) + 0.5f + jitter) / size * 2.0f - 1.0f;
  const glm::vec3 dir = glm::normalize(glm::vec3(c.camera.forward) + u * glm::vec3(c.camera.right) - v * glm::vec3(c.camera.up));
  const glm::vec3 o = glm::vec3(c.camera.eye) - d3d12::placement(p.kind, d3d12::Layout::isolated);
  CpuPixel out;
  float t0 = 0.0f, t1 = 1e30f;
  out.in_aabb = d3d12_cpu::ray_clip_aabb(o, dir, glm::vec3(-1.0f), glm::vec3(1.0f), t0, t1);
  float t;
  glm::vec3 n;
  out.hit = d3d12_cpu::d3d12_intersect_knobs(p.kind, p.params, p.spin, c.time, o, dir, 0.0f, 1e30f, 0u, k, 1.0f,
                                             c.camera.pixel_angle, t, n, out.steps);
  return out;
}

}  // namespace

TEST_CASE("d3d12 primitive kinds equal the GLSL consts") {
  CHECK(d3d12::box == d3d12_cpu::primitive_box);
  CHECK(d3d12::spheres == d3d12_cpu::primitive_spheres);
  CHECK(d3d12::metaballs == d3d12_cpu::primitive_metaballs);
  CHECK(d3d12::mini_spheres == d3d12_cpu::sdf_mini_spheres);
  CHECK(d3d12::round_cube == d3d12_cpu::sdf_round_cube);
  CHECK(d3d12::square_torus == d3d12_cpu::sdf_square_torus);
  CHECK(d3d12::twisted_torus == d3d12_cpu::sdf_twisted_torus);
  CHECK(d3d12::cog == d3d12_cpu::sdf_cog);
  CHECK(d3d12::cylinder == d3d12_cpu::sdf_cylinder);
  CHECK(d3d12::fractal_pyramid == d3d12_cpu::sdf_fractal_pyramid);
  CHECK(d3d12::primitive_count == d3d12_cpu::primitive_kind_count);
  CHECK(static_cast<std::uint32_t>(MarchMethod::sphere) == d3d12_cpu::march_method_sphere);
  CHECK(static_cast<std::uint32_t>(MarchMethod::relaxed) == d3d12_cpu::march_method_relaxed);
  CHECK(static_cast<std::uint32_t>(MarchMethod::lipschitz) == d3d12_cpu::march_method_lipschitz);
  CHECK(static_cast<std::uint32_t>(MarchMethod::segment) == d3d12_cpu::march_method_segment);
  CHECK(static_cast<std::uint32_t>(MarchMethod::fixed) == d3d12_cpu::march_method_fixed);
  CHECK(static_cast<std::uint32_t>(MarchThreshold::absolute) == d3d12_cpu::march_threshold_absolute);
  CHECK(static_cast<std::uint32_t>(MarchNormal::tetrahedral) == d3d12_cpu::march_normal_tetrahedral);
  CHECK(static_cast<std::uint32_t>(MarchIterations::by_distance) == d3d12_cpu::march_iterations_by_distance);
  // The fields' bounds the host declares are sdf.glsl's, at the default params and at other twists.
  for (d3d12::Primitive p : d3d12::default_primitives()) {
    if (p.kind <= d3d12::metaballs) continue;
    for (float twist : {0.0f, 3.0f, -8.0f}) {
      if (p.kind == d3d12::twisted_torus) p.params.y = twist;
      CAPTURE(d3d12::primitive_names[p.kind]);
      CHECK(d3d12::lipschitz(p) == d3d12_cpu::sdf_lipschitz(p.kind, p.params));
    }
  }
}

TEST_CASE("d3d12 hit table has the sample's 22 records in geometry order") {
  d3d12::D3d12Scene scene;
  const Plan sbt = compile(scene);
  const auto hits = sbt.records(SbtRegionKind::hit);
  REQUIRE(hits.size() == 22);
  CHECK(sbt.records(SbtRegionKind::miss).size() == 2);
  for (std::uint32_t k = 0; k < d3d12::primitive_count; ++k) {
    const auto kind = static_cast<d3d12::PrimitiveKind>(k);
    CAPTURE(d3d12::primitive_names[k]);
    CHECK(sbt.pipeline().groups[hits[2 + 2 * k].group].name == std::string(d3d12::hit_group_of(kind)));
    CHECK(sbt.pipeline().groups[hits[3 + 2 * k].group].name == std::string(d3d12::hit_group_of(kind)) + "_shadow");
  }
  CHECK(format_sbt(sbt, sbt.layout(DeviceLimits{})).find("fractal_pyramid_shadow") != std::string::npos);
  // The seven SDFs are distance fields, each with its generated intersection; the rest keep the sample's.
  CHECK(sbt.fields().size() == d3d12::primitive_count - d3d12::mini_spheres);
}

TEST_CASE("d3d12 host rejects degenerate primitive parameters") {
  using d3d12::Primitive;
  const auto with = [](d3d12::PrimitiveKind k, glm::vec4 params, float spin = 0.0f) {
    Primitive p = d3d12::default_primitive(k);
    p.params = params;
    p.spin = spin;
    return p;
  };
  CHECK_THROWS_WITH_AS(d3d12::validate(with(d3d12::metaballs, {0.0f, 0.25f, 0.0f, 0.0f})),
                       doctest::Contains("'metaballs': influence radius 0.000000 (params.x) must be in (0, 1]"),
                       d3d12::PrimitiveError);
  CHECK_THROWS_WITH_AS(d3d12::validate(with(d3d12::spheres, glm::vec4(0.0f))),
                       doctest::Contains("'spheres': radius scale 0.000000"), d3d12::PrimitiveError);
  CHECK_THROWS_WITH_AS(d3d12::validate(with(d3d12::box, {0.5f, -0.5f, 0.5f, 0.0f})),
                       doctest::Contains("half size -0.500000 (params[1]) must be in (0, 1]"), d3d12::PrimitiveError);
  CHECK_THROWS_WITH_AS(d3d12::validate(with(d3d12::cylinder, {1.0f, 0.0f, 0.0f, 0.0f}, 0.5f)),
                       doctest::Contains("out of its AABB; use spin 0 or a smaller scale"), d3d12::PrimitiveError);
  CHECK_THROWS_WITH_AS(d3d12::validate(with(d3d12::fractal_pyramid, {1.0f, 2.5f, 0.0f, 0.0f})),
                       doctest::Contains("iterations 2.500000"), d3d12::PrimitiveError);
  CHECK_THROWS_AS(d3d12::validate(with(d3d12::cog, {std::nanf(""), 0.0f, 0.0f, 0.0f})), std::logic_error);
  for (const d3d12::Primitive& p : d3d12::default_primitives()) CHECK_NOTHROW(d3d12::validate(p));
  const std::array<Primitive, 1> bad{with(d3d12::metaballs, {0.0f, 0.25f, 0.0f, 0.0f})};
  CHECK_THROWS_AS(d3d12::D3d12Scene(bad, d3d12::Layout::isolated), d3d12::PrimitiveError);
}

TEST_CASE("d3d12 each primitive alone matches the CPU coverage with no NaN") {
  TestContext t;
  Alone alone(t.ctx);
  std::array<std::size_t, 5> metaball_coverage{};  // by MarchMethod
  for (const float time : {0.0f, 1.3f}) {
    for (const MarchMethod method : {MarchMethod::fixed, MarchMethod::lipschitz, MarchMethod::segment}) {
      for (const d3d12::Primitive& p : alone.scene.primitives()) {
        if (method != MarchMethod::fixed && p.kind != d3d12::metaballs) continue;
        const d3d12::SceneConstants c = debug_constants(d3d12::isolated_camera(p.kind, size, size), time, method);
        d3d12::set_frame(alone.renderer, c);
        const vk::Frame f = alone.renderer.render(size, size);
        // The CPU's answer at the GPU's hit threshold (0.5 pixel footprints), at 0.25 and 1, and
        // for rays moved by +-0.02 pixel: a pixel is certain where all five agree. Elsewhere
        // rounding (FMA contraction; where the fractal's distance bound jumps at fold seams, the
        // march's sample points) may tip it either way: seen on an H100, 28 such pyramid pixels.
        std::size_t gpu = 0, cpu = 0, tight = 0, loose = 0, disagree = 0, certain_disagree = 0, outside_aabb = 0,
                    nonfinite = 0, unstepped = 0;
        for (std::uint32_t y = 0; y < size; ++y) {
          for (std::uint32_t x = 0; x < size; ++x) {
            const std::size_t i = (std::size_t(y) * size + x) * 4;
            const bool gpu_hit = f.rgba[i] == d3d12::object_id(p.kind);
            const CpuPixel c_px = cpu_pixel(p, c, x, y);
            const bool tight_hit = cpu_pixel(p, c, x, y, 0.25f).hit, loose_hit = cpu_pixel(p, c, x, y, 1.0f).hit;
            const bool stable = cpu_pixel(p, c, x, y, -1.0f, 0.02f).hit == c_px.hit &&
                                cpu_pixel(p, c, x, y, -1.0f, -0.02f).hit == c_px.hit;
            gpu += gpu_hit;
            cpu += c_px.hit;
            tight += tight_hit;
            loose += loose_hit;
            disagree += gpu_hit != c_px.hit;
            certain_disagree += stable && tight_hit == loose_hit && loose_hit == c_px.hit && gpu_hit != c_px.hit;
            outside_aabb += gpu_hit && !c_px.in_aabb;
            nonfinite += f.rgba[i + 3] != 255;
            unstepped += gpu_hit && p.kind > d3d12::spheres && f.rgba[i + 1] == 0 && f.rgba[i + 2] == 0;
          }
        }
        const double n = double(size) * size;
        CAPTURE(d3d12::primitive_names[p.kind]);
        CAPTURE(time);
        CAPTURE(static_cast<std::uint32_t>(method));
        CAPTURE(cpu);
        CAPTURE(tight);
        CAPTURE(loose);
        CHECK(cpu > n * 0.05);                             // the camera sees the primitive
        CHECK(double(gpu) >= double(tight) - n * 0.005);    // coverage between the tight and loose
        CHECK(double(gpu) <= double(loose) + n * 0.005);    // thresholds' coverage
        CHECK(std::abs(double(gpu) - double(cpu)) <= n * 0.02);  // and within 2 % of the image of the CPU's
        CHECK(disagree <= n * 0.03);                       // per pixel, uncertain ones included
        CHECK(certain_disagree <= n * 0.005);              // per pixel, where the answer is certain
        CHECK(outside_aabb == 0);                          // hits only inside the own AABB
        CHECK(nonfinite == 0);                             // no NaN or infinity in any output
        CHECK(unstepped == 0);                             // marched hits report their steps
        if (p.kind == d3d12::metaballs && time == 0.0f) metaball_coverage[static_cast<std::uint32_t>(method)] = gpu;
      }
    }
  }
  // Both metaball marches find the same surface.
  // The three metaball marches see the same blob (segment tracing: Galin et al.'s bound).
  const std::size_t fixed = metaball_coverage[static_cast<std::size_t>(MarchMethod::fixed)];
  CHECK(fixed > 0);
  for (const MarchMethod m : {MarchMethod::lipschitz, MarchMethod::segment}) {
    CHECK(std::abs(double(fixed) - double(metaball_coverage[static_cast<std::uint32_t>(m)])) <= 0.01 * size * size);
  }
}

TEST_CASE("d3d12 rays through the AABB beside the primitive report no hit") {
  TestContext t;
  Alone alone(t.ctx);
  for (const d3d12::Primitive& p : alone.scene.primitives()) {
    const d3d12::SceneConstants c = debug_constants(d3d12::isolated_camera(p.kind, size, size), 0.0f);
    d3d12::set_frame(alone.renderer, c);
    const vk::Frame f = alone.renderer.render(size, size);
    std::size_t box_only = 0, reported = 0;
    for (std::uint32_t y = 0; y < size; ++y) {
      for (std::uint32_t x = 0; x < size; ++x) {
        const CpuPixel c_px = cpu_pixel(p, c, x, y);
        // Clearly beside: the neighbours agree too, so silhouette rounding does not count.
        bool all_beside = c_px.in_aabb && !c_px.hit;
        for (int dy = -1; dy <= 1 && all_beside; ++dy)
          for (int dx = -1; dx <= 1 && all_beside; ++dx) {
            const int xx = int(x) + dx, yy = int(y) + dy;
            if (xx >= 0 && yy >= 0 && xx < int(size) && yy < int(size)) all_beside = !cpu_pixel(p, c, xx, yy).hit;
          }
        if (!all_beside) continue;
        ++box_only;
        reported += f.rgba[(std::size_t(y) * size + x) * 4] != d3d12::sky_id;
      }
    }
    CAPTURE(d3d12::primitive_names[p.kind]);
    CHECK(box_only > 50);  // such rays exist for every primitive at this view
    CHECK(reported == 0);
  }
}

TEST_CASE("d3d12 scene shows every primitive and animates without a TLAS refit") {
  TestContext t;
  d3d12::D3d12Scene scene;
  vk::Renderer renderer(t.ctx, scene, d3d12::renderer_options());
  constexpr std::uint32_t w = 160, h = 120;
  const Camera camera = d3d12::sample_camera(w, h);
  auto render = [&](float time) {
    d3d12::SceneConstants c = d3d12::default_constants(camera, time);
    c.flags = d3d12::flag_debug;
    d3d12::set_frame(renderer, c);
    return renderer.render(w, h);
  };
  const vk::Frame first = render(0.0f);
  std::set<int> seen;
  std::size_t nonfinite = 0;
  for (std::size_t i = 0; i < std::size_t(w) * h; ++i) {
    seen.insert(first.rgba[i * 4]);
    nonfinite += first.rgba[i * 4 + 3] != 255;
  }
  for (std::uint32_t k = 0; k < d3d12::primitive_count; ++k) {
    CAPTURE(d3d12::primitive_names[k]);
    CHECK(seen.count(int(d3d12::object_id(static_cast<d3d12::PrimitiveKind>(k)))) == 1);
  }
  CHECK(seen.count(int(d3d12::plane_id)) == 1);
  CHECK(seen.count(int(d3d12::sky_id)) == 1);
  CHECK(nonfinite == 0);
  const vk::Frame later = render(1.5f);
  CHECK_FALSE(later.tlas_refit);
  const std::set<int> animated{int(d3d12::object_id(d3d12::metaballs)), int(d3d12::object_id(d3d12::square_torus)),
                               int(d3d12::object_id(d3d12::twisted_torus)), int(d3d12::object_id(d3d12::cog))};
  std::size_t changed = 0, changed_elsewhere = 0;
  for (std::size_t i = 0; i < std::size_t(w) * h; ++i) {
    const int a = first.rgba[i * 4], b = later.rgba[i * 4];
    if (a == b) continue;
    ++changed;
    changed_elsewhere += !(animated.count(a) || animated.count(b));
  }
  CHECK(changed > 10);
  CHECK(changed_elsewhere == 0);
}

namespace {
double steps_at(const vk::Frame& f, std::size_t pixel) { return f.rgba[pixel * 4 + 1] + 256.0 * f.rgba[pixel * 4 + 2]; }
/// A pixel's march: the debug view's steps where it hit `id` (the march's, normals left out),
/// the steps output elsewhere (a miss evaluates no normal).
double march_steps(const vk::Frame& f, std::size_t pixel, std::uint32_t id) {
  return f.rgba[pixel * 4] == id ? steps_at(f, pixel) : f.outputs.steps[pixel];
}
}  // namespace

TEST_CASE("d3d12 the steps output gives marched misses their evaluations, the CPU's count") {
  // The benchmark counts misses with the steps output: rays that enter the AABB and miss carry
  // the CPU's count for the same ray; rays outside the AABB take none. The SDFs are distance
  // fields (the library's intersection), the metaballs the example's shader: both count alike.
  TestContext t;
  Alone alone(t.ctx, {Output::steps});
  for (const d3d12::Primitive& p : alone.scene.primitives()) {
    if (p.kind < d3d12::metaballs) continue;  // analytic: no steps to count
    d3d12::SceneConstants c = debug_constants(d3d12::isolated_camera(p.kind, size, size), 0.0f);
    d3d12::set_frame(alone.renderer, c);
    const vk::Frame f = alone.renderer.render(size, size);
    REQUIRE(f.outputs.steps.size() == std::size_t(size) * size);
    std::size_t misses = 0, uncounted = 0, outside_counted = 0;
    double gpu_miss_steps = 0, cpu_miss_steps = 0;
    for (std::uint32_t y = 0; y < size; ++y) {
      for (std::uint32_t x = 0; x < size; ++x) {
        const std::size_t i = std::size_t(y) * size + x;
        const bool hit = f.rgba[i * 4] == d3d12::object_id(p.kind);
        const CpuPixel cpu = cpu_pixel(p, c, x, y);
        outside_counted += !cpu.in_aabb && f.outputs.steps[i] != 0;
        if (hit || cpu.hit || !cpu.in_aabb) continue;
        ++misses;
        uncounted += f.outputs.steps[i] == 0;
        gpu_miss_steps += f.outputs.steps[i];
        cpu_miss_steps += cpu.steps;
      }
    }
    CAPTURE(d3d12::primitive_names[p.kind]);
    CAPTURE(gpu_miss_steps);
    CAPTURE(cpu_miss_steps);
    CHECK(misses > 100);      // the view has rays through the AABB beside the primitive
    CHECK(uncounted == 0);    // each of them marched at least once and says so
    CHECK(outside_counted == 0);
    // Same GLSL marcher, float on both sides: step totals agree closely (rounding may move a step).
    CHECK(std::abs(gpu_miss_steps - cpu_miss_steps) <= 0.02 * cpu_miss_steps);
  }
}

TEST_CASE("d3d12 over-relaxation is a run-time knob that keeps the image and saves steps") {
  // The twisted torus (steps divided by its Lipschitz bound 5.2): w = 1.6 from the uniform,
  // same hits as w = 1, fewer steps over all rays (the CPU test of the GLSL sees 0.65).
  TestContext t;
  Alone alone(t.ctx, {Output::steps});
  const d3d12::Primitive& p = alone.scene.primitives()[d3d12::twisted_torus];
  REQUIRE(p.kind == d3d12::twisted_torus);
  std::array<double, 2> steps{};
  std::array<vk::Frame, 2> frames;
  for (int k = 0; k < 2; ++k) {
    d3d12::SceneConstants c = debug_constants(d3d12::isolated_camera(p.kind, size, size), 0.0f);
    MarchKnobs& torus = d3d12::knobs(c, d3d12::twisted_torus);
    torus.method = k == 0 ? MarchMethod::lipschitz : MarchMethod::relaxed;
    torus.relaxation = 1.6f;
    d3d12::set_frame(alone.renderer, c);
    frames[k] = alone.renderer.render(size, size);
    for (std::size_t i = 0; i < std::size_t(size) * size; ++i) steps[k] += march_steps(frames[k], i, d3d12::object_id(p.kind));
  }
  std::size_t differ = 0;
  for (std::size_t i = 0; i < std::size_t(size) * size; ++i) differ += frames[0].rgba[i * 4] != frames[1].rgba[i * 4];
  CAPTURE(steps[0]);
  CAPTURE(steps[1]);
  CHECK(differ <= size * size / 200);
  CHECK(steps[1] < 0.8 * steps[0]);
}
