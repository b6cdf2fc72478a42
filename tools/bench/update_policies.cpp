// Benchmark (not a test): what each update policy costs per frame, on the renderer.
//
//   bench_update_policies [--device cpu|gpu|auto] [--size N] [--scatter] [instances=10000] [boxes=100000] [frames=21]
//
// Four scenes, each traced at N x N (default 32, so the trace does not hide the structure work)
// without readback for `frames` frames after a warm-up:
//   Static                 `instances` one-box instances and one geometry of `boxes` boxes; nothing changes
//   DynamicTransform       the same, every instance moved every frame (set_transforms: TLAS refit)
//   DynamicGeometry refit  the boxes geometry given new boxes every frame, same count (BLAS refit)
//   DynamicGeometry build  the same with the count alternating (BLAS and TLAS rebuild)
// --scatter gives the boxes new random places every frame instead of a small shift: the refit
// then keeps a tree that no longer fits them, and its trace time shows what that costs.
// Shaders: tools/bench/shaders (PROCEDURAY_BENCH_SHADER_DIR overrides the built-in path).
// Prints the median frame time (the set_* calls and render(), wall clock), the median trace
// time (GPU timestamps), the median of their difference (host work, structure builds and
// refits, submit and wait) and the work the renderer reported for the last frame.
#include <proceduray/proceduray.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <random>
#include <string>
#include <vector>

#ifndef PROCEDURAY_BENCH_SHADER_DIR
#define PROCEDURAY_BENCH_SHADER_DIR "tools/bench/shaders"
#endif

namespace pr = proceduray;

namespace bench {
struct Colour {
  glm::vec3 rgb;
};
PROCEDURAY_STRUCT(Colour, scalar, rgb);
using BenchSceneInterface = proceduray::ShaderInterface<proceduray::Payload<Colour>, proceduray::RootComponent<>, proceduray::RootArguments<>,
                                   proceduray::Attributes<>>;
using BenchScene = proceduray::Scene<BenchSceneInterface>;
}  // namespace bench

namespace {

enum class Case { fixed, moving, refit, rebuild };
const char* names[] = {"Static", "DynamicTransform", "DynamicGeometry refit", "DynamicGeometry build"};

/// `count` small boxes at the same random places every call, moved `shift` along z: small motion,
/// the case a refit is for (random new places would leave a refit tree that traces slowly).
std::vector<pr::Aabb> boxes_at(std::size_t count, float shift, unsigned seed = 7) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> at(-0.95f, 0.95f);
  std::vector<pr::Aabb> out(count);
  for (pr::Aabb& b : out) {
    const glm::vec3 c(at(rng), at(rng), at(rng) + shift);
    b = {c - 0.004f, c + 0.004f};
  }
  return out;
}

glm::mat4 place(std::size_t i, std::size_t n, float t) {
  const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(n))));
  const float x = -0.95f + 1.9f * static_cast<float>(i % side) / static_cast<float>(side);
  const float y = -0.95f + 1.9f * static_cast<float>(i / side) / static_cast<float>(side);
  return glm::scale(glm::translate(glm::mat4(1.0f), {x + 0.01f * std::sin(t + static_cast<float>(i)), y, 0.5f}),
                    glm::vec3(0.004f));
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

void run(const pr::vk::Context& ctx, Case which, std::uint32_t size, std::size_t instances, std::size_t boxes,
         int frames, bool scatter) {
  bench::BenchScene scene;
  const auto primary = scene.add_ray<bench::Colour>("primary", {.miss = "bench.rmiss"});
  const auto group = scene.add_hit_group("box", {.kind = pr::HitGroupKind::procedural, .closest_hit = "bench.rchit",
                                                  .intersection = "bench.rint"});
  std::vector<pr::InstanceTransform> placed;
  for (std::size_t i = 0; i < instances; ++i) placed.push_back(pr::instance_transform(place(i, instances, 0.0f)));
  pr::GeometryDesc small = pr::GeometryDesc::procedural({pr::Aabb{}}, placed);
  if (which == Case::moving) small.update = pr::UpdatePolicy::DynamicTransform;
  const pr::GeometryId many = scene.add_geometry("instances", small);
  pr::GeometryDesc cloud = pr::GeometryDesc::procedural(boxes_at(boxes, 0.0f));
  if (which == Case::refit || which == Case::rebuild) cloud.update = pr::UpdatePolicy::DynamicGeometry;
  const pr::GeometryId big = scene.add_geometry("boxes", cloud);
  scene.set_global_signature({.bindings = {{pr::BindingKind::acceleration_structure, 0, 0, 1, "tlas"},
                                            {pr::BindingKind::storage_image, 1, 0, 1, "image"}}});
  scene.add_raygen("bench.rgen");
  scene.set_default_hit(primary, group);
  const char* dir = std::getenv("PROCEDURAY_BENCH_SHADER_DIR");  // for binaries carried to another machine
  pr::vk::Renderer renderer(ctx, scene, {.shader_dirs = {dir != nullptr ? dir : PROCEDURAY_BENCH_SHADER_DIR}});
  renderer.warm_up();
  renderer.render(size, size, false);

  std::vector<double> frame_ms, trace_ms, other_ms;
  pr::vk::FrameWork work;
  for (int f = 1; f <= frames; ++f) {
    // The new data is made before the clock starts: only the renderer's work is timed.
    std::vector<glm::mat4> moved;
    std::vector<pr::Aabb> next;
    if (which == Case::moving) {
      for (std::size_t i = 0; i < instances; ++i) moved.push_back(place(i, instances, 0.3f * static_cast<float>(f)));
    } else if (which == Case::refit || which == Case::rebuild) {
      next = boxes_at(which == Case::rebuild && f % 2 == 1 ? boxes - 1 : boxes, 0.001f * static_cast<float>(f),
                      scatter ? 7u + static_cast<unsigned>(f) : 7u);
    }
    const auto start = std::chrono::steady_clock::now();
    if (!moved.empty()) renderer.set_transforms(many, moved);  // every instance in one call
    if (!next.empty()) renderer.set_aabbs(big, next);
    const pr::vk::Frame frame = renderer.render(size, size, false);
    frame_ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    trace_ms.push_back(frame.trace_ms);
    other_ms.push_back(frame_ms.back() - frame.trace_ms);
    work = frame.work;
  }
  std::printf("%-22s %10.2f %10.3f %10.3f   %u BLAS builds, %u BLAS refits, %u TLAS builds, %u TLAS updates\n",
              names[static_cast<int>(which)], median(frame_ms), median(trace_ms), median(other_ms), work.blas_builds,
              work.blas_refits, work.tlas_builds, work.tlas_updates);
}

}  // namespace

int main(int argc, char** argv) {
  pr::vk::DevicePreference device = pr::vk::DevicePreference::automatic;
  std::vector<std::size_t> numbers;
  std::uint32_t size = 32;
  bool scatter = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--device" && i + 1 < argc) {
      const std::string v = argv[++i];
      device = v == "gpu" ? pr::vk::DevicePreference::gpu : v == "cpu" ? pr::vk::DevicePreference::cpu
                                                                        : pr::vk::DevicePreference::automatic;
    } else if (arg == "--scatter") {
      scatter = true;
    } else if (arg == "--size" && i + 1 < argc) {
      size = static_cast<std::uint32_t>(std::strtoul(argv[++i], nullptr, 10));
    } else {
      numbers.push_back(std::strtoull(arg.c_str(), nullptr, 10));
    }
  }
  const std::size_t instances = numbers.size() > 0 ? numbers[0] : 10000;
  const std::size_t boxes = numbers.size() > 1 ? numbers[1] : 100000;
  const int frames = numbers.size() > 2 ? static_cast<int>(numbers[2]) : 21;
  if (instances == 0 || boxes < 2 || frames < 1) {
    std::fprintf(stderr, "bench_update_policies: need instances >= 1, boxes >= 2, frames >= 1\n");
    return 2;
  }
  try {
    pr::vk::Context ctx({.device = device});
    std::printf("device: %s; %zu instances, a geometry of %zu boxes%s, median of %d frames at %ux%u\n",
                ctx.name().c_str(), instances, boxes, scatter ? " scattered anew each frame" : "", frames, size, size);
    std::printf("%-22s %10s %10s %10s   %s\n", "policy", "frame ms", "trace ms", "other ms", "work in the last frame");
    for (Case c : {Case::fixed, Case::moving, Case::refit, Case::rebuild}) run(ctx, c, size, instances, boxes, frames, scatter);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_update_policies: %s\n", e.what());
    return 1;
  }
  return 0;
}
