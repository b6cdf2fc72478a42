// Host scaling benchmark (not a test): registry + entries + build (layout, offsets, plan) +
// resolution of every (ray, geometry, instance) for N procedural instances.
//
//   bench_scene_scaling [instances=1000000] [geometries=1000]
//
// Each geometry is its own BLAS with instances/geometries instances; two ray types; the
// radiance ray gets one entry per instance (16 bytes of record data), the shadow ray one
// entry per geometry. Prints wall time per phase and the peak resident memory.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "proceduray/scene/compile.hpp"
#include "proceduray/shader/field_list.hpp"

namespace {
struct Payload { float color[4]; };
struct Attributes { float normal[3]; };
struct InstanceArgs { std::uint32_t instance; std::uint32_t material; float scale; float pad; };
PROCEDURAY_STRUCT(Payload, scalar, color);
PROCEDURAY_STRUCT(Attributes, scalar, normal);
PROCEDURAY_STRUCT(InstanceArgs, scalar, instance, material, scale, pad);
using BenchSceneInterface = proceduray::ShaderInterface<proceduray::Payload<Payload>, proceduray::RootComponent<>, proceduray::RootArguments<InstanceArgs>,
                                   proceduray::Attributes<Attributes>>;
using BenchScene = proceduray::Scene<BenchSceneInterface>;

/// VmHWM (peak resident set) in KiB, from /proc; 0 where unavailable.
long peak_kib() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::strtol(line.c_str() + 6, nullptr, 10);
  }
  return 0;
}
}  // namespace

int main(int argc, char** argv) {
  using clock = std::chrono::steady_clock;
  const std::uint32_t instances = argc > 1 ? static_cast<std::uint32_t>(std::strtoul(argv[1], nullptr, 10)) : 1'000'000u;
  const std::uint32_t geometries = argc > 2 ? static_cast<std::uint32_t>(std::strtoul(argv[2], nullptr, 10)) : 1000u;
  const std::uint32_t per_geometry = instances / geometries;
  const long base_kib = peak_kib();
  auto ms = [](clock::time_point a, clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); };

  const auto t0 = clock::now();
  BenchScene scene;
  const auto radiance = scene.add_ray<Payload>("Radiance", {.miss = "miss"});
  const auto shadow = scene.add_ray<Payload>("Shadow", {.miss = "miss_shadow"});
  const auto group = scene.add_hit_group<Attributes>("Sphere", {.kind = proceduray::HitGroupKind::procedural,
                                                                .closest_hit = "sphere.rchit", .intersection = "sphere.rint"});
  const auto shadow_group = scene.add_hit_group<Attributes>("SphereShadow", {.kind = proceduray::HitGroupKind::procedural,
                                                                             .intersection = "sphere.rint"});
  const auto signature = scene.add_local_signature<InstanceArgs>("Instance");
  scene.reserve_geometries(geometries);
  std::vector<proceduray::GeometryId> ids;
  ids.reserve(geometries);
  for (std::uint32_t g = 0; g < geometries; ++g) {
    std::vector<proceduray::InstanceTransform> transforms(per_geometry, proceduray::identity_transform());
    for (std::uint32_t i = 0; i < per_geometry; ++i) transforms[i][0][3] = static_cast<float>(i);
    ids.push_back(scene.add_geometry("sphere" + std::to_string(g),
                                     proceduray::GeometryDesc::procedural({proceduray::Aabb{}}, std::move(transforms))));
  }
  const auto t1 = clock::now();
  scene.reserve_entries(std::size_t{instances} + geometries + 1, std::size_t{instances} * sizeof(InstanceArgs));
  scene.add_raygen("raygen.rgen");
  for (std::uint32_t g = 0; g < geometries; ++g) {
    scene.add_hit(shadow, shadow_group, ids[g]);
    for (std::uint32_t i = 0; i < per_geometry; ++i) {
      scene.add_hit(radiance, group, signature, InstanceArgs{g * per_geometry + i, g, 1.0f, 0.0f}, ids[g], i);
    }
  }
  const auto t2 = clock::now();
  const proceduray::Plan sbt = proceduray::compile(scene);
  const proceduray::SbtLayout layout =
      sbt.layout({.sbt = {.handle_size = 32, .handle_alignment = 16, .base_alignment = 32, .max_stride = 16384}});
  const auto t3 = clock::now();
  std::uint64_t checksum = 0;
  for (std::uint32_t g = 0; g < geometries; ++g) {
    for (std::uint32_t i = 0; i < per_geometry; ++i) {
      checksum += sbt.resolve(radiance, ids[g], i).record;
      checksum += sbt.resolve(shadow, ids[g], i).record;
    }
  }
  const auto t4 = clock::now();
  std::printf("instances %u (geometries %u x %u), hit records %zu, SBT %llu bytes, TLAS instances %zu\n",
              geometries * per_geometry, geometries, per_geometry, sbt.records(proceduray::SbtRegionKind::hit).size(),
              static_cast<unsigned long long>(layout.size), sbt.instances().size());
  std::printf("registry %.1f ms, entries %.1f ms, compile + layout %.1f ms, resolve x%u %.1f ms, total %.1f ms\n", ms(t0, t1),
              ms(t1, t2), ms(t2, t3), 2 * geometries * per_geometry, ms(t3, t4), ms(t0, t4));
  std::printf("peak memory %.1f MiB (%.1f MiB above start; %.1f bytes per instance); checksum %llu\n",
              static_cast<double>(peak_kib()) / 1024.0, static_cast<double>(peak_kib() - base_kib) / 1024.0,
              static_cast<double>(peak_kib() - base_kib) * 1024.0 / static_cast<double>(geometries * per_geometry),
              static_cast<unsigned long long>(checksum));
  return 0;
}
