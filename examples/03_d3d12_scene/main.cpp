// The D3D12 procedural-geometry sample's scene through Scene + Renderer: the
// ground and a grid of analytic, volumetric and signed-distance primitives, radiance and shadow
// rays, animated over --frames with no acceleration-structure work. Prints timings and the SBT.
//   --gallery PATH  also render each primitive alone into one tiled PNG (5 x 2 tiles of --size)
//   --bench         per primitive alone at --size: trace ms (median of 5), coverage, evaluations per second, and mean
//                   marching steps (distance or field evaluations, the normal's included) over the rays that hit, over
//                   all rays that entered the primitive's AABB (hits and misses), and per pixel
//   --relax W       sphere tracing's over-relaxation w in [1, 2) (default 1: plain)
#include "../common/run.hpp"
#include "d3d12_scene.hpp"

#include <CLI/CLI.hpp>  // this example adds options of its own

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <exception>
#include <memory>
#include <vector>

namespace {

using examples::median;

/// --relax w: every SDF marched by over-relaxed sphere tracing with w (w = 1: their default method).
void relax_sdfs(d3d12::SceneConstants& c, float w) {
  if (w == 1.0f) return;
  for (std::uint32_t k = d3d12::mini_spheres; k < d3d12::primitive_count; ++k) {
    proceduray::MarchKnobs& knobs = d3d12::knobs(c, static_cast<d3d12::PrimitiveKind>(k));
    knobs.method = proceduray::MarchMethod::relaxed;
    knobs.relaxation = w;
  }
}

/// One benchmark row: median trace ms of 5 frames on `timed` (no outputs: the frame a user
/// renders), then a debug frame on `counted`, whose steps output counts every ray's evaluations
/// (hits and misses, normals included), for coverage and steps. A ray entered the AABB when it
/// hit or evaluated: every marching intersection takes at least one evaluation (analytic ones
/// take none, so their AABB column is empty).
void bench_row(proceduray::vk::Renderer& timed, proceduray::vk::Renderer& counted, const std::string& name,
               d3d12::SceneConstants c, std::uint32_t w, std::uint32_t h, std::uint32_t id) {
  d3d12::set_frame(timed, c);
  std::vector<double> ms;
  for (int f = 0; f < 5; ++f) ms.push_back(timed.render(w, h, false).trace_ms);
  c.flags = d3d12::flag_debug;
  d3d12::set_frame(counted, c);
  const proceduray::vk::Frame debug = counted.render(w, h);
  std::size_t hits = 0, entered = 0;
  double hit_steps = 0, all_steps = 0;
  for (std::size_t i = 0; i < std::size_t(w) * h; ++i) {
    const double steps = debug.outputs.steps[i];
    const bool hit = debug.rgba[i * 4] == id;
    hits += hit;
    entered += hit || steps > 0;
    hit_steps += hit ? steps : 0.0;
    all_steps += steps;
  }
  const double pixels = double(w) * h;
  if (all_steps == 0) {  // analytic: no marching, and no way to tell AABB rays from the rest
    std::printf("%-16s %10.2f %8.1f%% %9s %10.1f %10s %10.2f %11s\n", name.c_str(), median(ms), 100.0 * double(hits) / pixels,
                "-", 0.0, "0", 0.0, "-");
    return;
  }
  // Evaluations per second: the counted frame's evaluations over the timed frame's trace time
  // (times the flops of one evaluation, over bench_peak's FLOP/s: the fraction of the peak).
  std::printf("%-16s %10.2f %8.1f%% %8.1f%% %10.1f %10.1f %10.2f %11.1f\n", name.c_str(), median(ms),
              100.0 * double(hits) / pixels, 100.0 * double(entered) / pixels, hits ? hit_steps / double(hits) : 0.0,
              entered ? all_steps / double(entered) : 0.0, all_steps / pixels, all_steps / (median(ms) * 1.0e3));
}

/// Renders each primitive alone (Layout::isolated): the gallery tiles and the benchmark rows.
void isolated(const proceduray::vk::Context& ctx, const examples::Options& o, const char* gallery, bool bench,
              float relax) {
  d3d12::D3d12Scene scene(d3d12::default_primitives(), d3d12::Layout::isolated);
  proceduray::vk::Renderer renderer(ctx, scene, examples::renderer_options(o, d3d12::renderer_options(o.cache)));
  // The benchmark's evaluation counts come from a second renderer with the steps output.
  const d3d12::D3d12Scene counted_scene(d3d12::default_primitives(), d3d12::Layout::isolated, {proceduray::Output::steps});
  std::unique_ptr<proceduray::vk::Renderer> counted;
  if (bench) counted = std::make_unique<proceduray::vk::Renderer>(ctx, counted_scene, examples::renderer_options(o, d3d12::renderer_options(o.cache)));
  const std::uint32_t w = o.width, h = o.height, columns = 5, rows = 2;
  std::vector<std::uint8_t> tiles(std::size_t(w) * columns * h * rows * 4);
  if (bench) {
    std::printf("over-relaxation w = %.2f\n", double(relax));
    std::printf("%-16s %10s %9s %9s %10s %10s %10s %11s\n", "primitive", "trace ms", "coverage", "in AABB", "steps/hit",
                "steps/ray", "steps/px", "Mevals/s");
  }
  for (std::uint32_t k = 0; k < d3d12::primitive_count; ++k) {
    const auto kind = static_cast<d3d12::PrimitiveKind>(k);
    d3d12::SceneConstants c = d3d12::default_constants(d3d12::isolated_camera(kind, w, h), 0.0f);
    relax_sdfs(c, relax);
    d3d12::set_frame(renderer, c);
    if (k == 0) renderer.warm_up();
    const proceduray::vk::Frame frame = renderer.render(w, h);
    const std::uint32_t tx = k % columns, ty = k / columns;
    for (std::uint32_t y = 0; y < h; ++y) {
      std::memcpy(&tiles[((std::size_t(ty) * h + y) * columns * w + std::size_t(tx) * w) * 4], &frame.rgba[std::size_t(y) * w * 4],
                  std::size_t(w) * 4);
    }
    if (!bench) continue;
    bench_row(renderer, *counted, std::string(d3d12::primitive_names[k]), c, w, h, d3d12::object_id(kind));
    if (kind == d3d12::metaballs) {
      d3d12::knobs(c, d3d12::metaballs).method = proceduray::MarchMethod::lipschitz;
      bench_row(renderer, *counted, "  (Lipschitz)", c, w, h, d3d12::object_id(kind));
      d3d12::knobs(c, d3d12::metaballs).method = proceduray::MarchMethod::segment;
      bench_row(renderer, *counted, "  (segment)", c, w, h, d3d12::object_id(kind));
    }
  }
  if (gallery) {
    proceduray::write_png(gallery, w * columns, h * rows, tiles);
    std::printf("gallery: %s\n", std::filesystem::absolute(gallery).string().c_str());
  }
}

}  // namespace

int main(int argc, char** argv) {
  const char* gallery = nullptr;
  std::string gallery_path;
  bool bench = false;
  float relax = 1.0f;
  examples::Options o = examples::parse(argc, argv, "03_d3d12_scene", {.width = 1024, .height = 768, .frames = 1},
                                        [&](CLI::App& app) {
    app.add_option("--gallery", gallery_path, "also render each primitive alone into one tiled PNG (5 x 2 tiles of --size)");
    app.add_flag("--bench", bench, "per primitive alone at --size: trace ms (median of 5), coverage, marching steps, "
                 "evaluations per second");
    app.add_option("--relax", relax, "the SDFs' over-relaxation w in [1, 2) (1: their default method)")
        ->check(CLI::Range(1.0f, 1.9999f));
  });
  if (o.exit) return *o.exit;
  if (!gallery_path.empty()) gallery = gallery_path.c_str();
  try {
    proceduray::check_writable(o.out);
    if (gallery) proceduray::check_writable(gallery);
    proceduray::vk::Context ctx({.device = o.device, .validation = o.validation});
    if (gallery || bench) {
      std::printf("device: %s\n", ctx.name().c_str());
      isolated(ctx, o, gallery, bench, relax);
      return ctx.validation_messages().empty() ? 0 : 1;
    }
    d3d12::D3d12Scene scene;
    proceduray::vk::Renderer renderer(ctx, scene, examples::renderer_options(o, d3d12::renderer_options(o.cache)));
    const proceduray::Camera camera = d3d12::sample_camera(o.width, o.height);
    auto constants = [&](float time) {
      d3d12::SceneConstants c = d3d12::default_constants(camera, time);
      relax_sdfs(c, relax);
      return c;
    };
    d3d12::set_frame(renderer, constants(0.0f));
    examples::print_build(ctx, renderer);
    // Only the uniform time changes: no TLAS refit, no BLAS work (the run reports "TLAS refit: no").
    const examples::Run run = examples::run_frames(renderer, o, [&](std::uint32_t f) {
      d3d12::set_frame(renderer, constants(0.1f * static_cast<float>(f)));
    });
    examples::print_run(run, o);
    std::printf("%s", proceduray::format_sbt(renderer.plan(), renderer.sbt().layout()).c_str());
    examples::write_last(run, o);
    return ctx.validation_messages().empty() ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "03_d3d12_scene: %s\n", e.what());
    return 1;
  }
}
