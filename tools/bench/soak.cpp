// Soak benchmark (not a test): many animated frames, then did the host heap grow?
//
//   bench_soak [--frames 10000] [--size 64x64] [--every 1000] [--max-growth 1] [--device cpu|gpu|auto] [--validation]
//   MALLOC_ARENA_MAX=1 bench_soak                         # one malloc arena: RSS without steps (see below)
//   bench_soak --frames 500 --every 100 --validation      # a short run under the Khronos validation layer
//   MALLOC_ARENA_MAX=1 bench_soak --pattern beads --frames 100000 --every 10000 --max-growth 0.1 --max-rss-growth 0.1 --trim
//                                                          # example 05's add-one-remove-one, for ever
//
// One scene, every kind of update the renderer has, in rotation (frame f, 1-based):
//   f % 4 == 0  instances moved: all of them (set_transforms) or one (set_transform), TLAS refit
//   f % 4 == 1  new boxes for a DynamicGeometry procedural geometry: BLAS refit; its count alternates
//               every 20 frames, so every 5th of these frames is a BLAS rebuild (and a TLAS rebuild)
//   f % 4 == 2  new vertex positions for a DynamicGeometry triangle mesh: BLAS refit
//   f % 4 == 3  one instance hidden or shown again (set_mask): TLAS rebuild
// --pattern beads does only what example 05 does to its beads: each frame adds an instance (at one
// of eight places) and removes the oldest past four, a TLAS build per frame.
// Frames trace without readback, except every --every'th, which reads the image back and fails
// (exit 1) if it is all one colour: an animated scene that renders nothing is a broken renderer.
// Shaders: tools/bench/shaders (PROCEDURAY_BENCH_SHADER_DIR overrides the built-in path).
//
// Every --every frames it prints the frame number, the host heap in use, the process RSS, the
// wall time per frame and the structure work (Frame::work) summed over those frames. At the end
// it compares the heap after the first interval (a warm-up: lazy allocations, caches filling)
// with the heap at the last frame and exits 1 if it grew by more than --max-growth percent; a
// run whose work counters stayed zero, or with --validation that got validation messages, also
// exits 1. Bad options exit 2.
//
// Why heap bytes and not RSS: RSS counts pages, not allocations, and lavapipe (llvmpipe) runs
// threads of its own (the queue thread, rasterizer and compile threads: 7 threads in all here).
// glibc gives each allocating thread a malloc arena of its own (up to 8 per core); an arena keeps
// the chunks its thread frees, and gives pages back to the system only from the top of its heap,
// so RSS rises towards each arena's high-water mark and stays there, and steps up whenever a
// thread's allocation pattern leaves a new page touched: growth by design, not a leak. Bytes held
// by live allocations, mallinfo2().uordblks + hblkhd (arena chunks in use, plus the large blocks
// malloc maps by themselves), grow only when something is kept, however the arenas are laid out.
// On glibc 2.36 (Debian 12) mallinfo2() sums every arena, whatever `man mallinfo2` says under
// BUGS (checked: 10 MB malloc'ed in another thread are counted). MALLOC_ARENA_MAX=1 puts every thread
// in the main arena: the heap number is then the main arena's, as the man page describes it, and
// RSS did not step in the runs below. uordblks also counts chunks a thread has freed into its tcache (a few KB),
// hence a limit in percent and a warm-up interval before the baseline.
// Observed on lavapipe (llvmpipe, LLVM 15, 2 cores, shared with builds), 10000 frames at 64x64 in 15-21 s:
//   MALLOC_ARENA_MAX unset  7 arenas; heap 47.7 MB, +1.0 to +1.3 KB (+0.003%) after the warm-up;
//                           RSS 116.4 MB, +1 MiB in one step between frames 8000 and 9000 (+0.9%)
//                           in every run: one lavapipe thread's arena grew from 1.3 to 2.3 MB of
//                           system memory (malloc_stats) while the bytes in use did not
//   MALLOC_ARENA_MAX=1      1 arena; heap 47.7 MB, +1.8 to +4.3 KB (+0.004 to +0.009%); RSS
//                           115.3 MB, flat
//   --validation            heap 55.1 MB, +25 KB over the first 2000 frames (the layer's own
//                           tracking), then flat; no validation messages
#include <proceduray/proceduray.hpp>

#include <CLI/CLI.hpp>

#include <malloc.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#ifndef PROCEDURAY_BENCH_SHADER_DIR
#define PROCEDURAY_BENCH_SHADER_DIR "tools/bench/shaders"
#endif

namespace pr = proceduray;

namespace soak {
struct Colour {
  glm::vec3 rgb;
};
PROCEDURAY_STRUCT(Colour, scalar, rgb);
using BenchSceneInterface = proceduray::ShaderInterface<proceduray::Payload<Colour>, proceduray::RootComponent<>, proceduray::RootArguments<>,
                                   proceduray::Attributes<>>;
using BenchScene = proceduray::Scene<BenchSceneInterface>;
}  // namespace soak

namespace {

constexpr std::uint32_t instances = 16;  // one-box instances, left half of the view
constexpr std::size_t boxes = 256;       // the DynamicGeometry boxes, top right
constexpr std::uint32_t grid = 8;        // the mesh: grid x grid quads, bottom right
constexpr int recount_every = 20;        // frames between changes of the box count (BLAS rebuilds)

/// Bytes held by live allocations: the arenas' in-use chunks and malloc's own mmaps.
std::size_t heap_bytes() {
  const struct mallinfo2 m = mallinfo2();
  return m.uordblks + m.hblkhd;
}

/// Resident set size: the second number of /proc/self/statm, in pages.
std::size_t rss_bytes() {
  std::ifstream statm("/proc/self/statm");
  std::size_t size = 0, resident = 0;
  statm >> size >> resident;
  return resident * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
}

glm::mat4 place(std::uint32_t i, float t) {
  const float x = -0.85f + 0.25f * static_cast<float>(i % 4) + 0.05f * std::sin(t + static_cast<float>(i));
  const float y = -0.85f + 0.45f * static_cast<float>(i / 4);
  return glm::scale(glm::translate(glm::mat4(1.0f), {x, y, 0.5f}), glm::vec3(0.08f));
}

/// `count` small boxes at the same random places every call, moved along x by `shift`: the
/// motion a refit is for.
void boxes_at(std::vector<pr::Aabb>& out, std::size_t count, float shift) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> at(0.05f, 0.9f);
  out.resize(count);
  for (pr::Aabb& b : out) {
    const glm::vec3 c(at(rng) + shift, at(rng), 0.5f);
    b = {c - 0.02f, c + 0.02f};
  }
}

/// The mesh's vertices, a wave in z (the rays run along z, so it changes the hit distances).
void wave(std::vector<glm::vec3>& out, float t) {
  out.resize((grid + 1) * (grid + 1));
  for (std::uint32_t j = 0; j <= grid; ++j) {
    for (std::uint32_t i = 0; i <= grid; ++i) {
      const float x = 0.05f + 0.85f * static_cast<float>(i) / grid, y = -0.9f + 0.85f * static_cast<float>(j) / grid;
      out[j * (grid + 1) + i] = {x, y, 0.5f + 0.1f * std::sin(t + 4.0f * x + 3.0f * y)};
    }
  }
}

pr::TriangleMesh mesh() {
  pr::TriangleMesh m;
  wave(m.vertices, 0.0f);
  for (std::uint32_t j = 0; j < grid; ++j) {
    for (std::uint32_t i = 0; i < grid; ++i) {
      const std::uint32_t a = j * (grid + 1) + i, b = a + 1, c = a + grid + 1, d = c + 1;
      m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
    }
  }
  return m;
}

/// An image that is all one colour shows no geometry, or only geometry: either way nothing drew.
bool one_colour(const std::vector<std::uint8_t>& rgba) {
  for (std::size_t i = 4; i + 3 < rgba.size(); i += 4) {
    if (rgba[i] != rgba[0] || rgba[i + 1] != rgba[1] || rgba[i + 2] != rgba[2] || rgba[i + 3] != rgba[3]) return false;
  }
  return true;
}

void add(pr::vk::FrameWork& to, const pr::vk::FrameWork& work) {
  to.blas_builds += work.blas_builds;
  to.blas_refits += work.blas_refits;
  to.tlas_builds += work.tlas_builds;
  to.tlas_updates += work.tlas_updates;
}

struct Options {
  std::uint32_t frames = 10000;
  std::string size = "64x64";
  std::uint32_t every = 1000;
  double max_growth = 1.0;
  double max_rss_growth = -1;  // < 0: not checked
  bool trim = false;
  std::string pattern = "all";
  std::string device = "auto";
  bool validation = false;
};

/// The soak scene: instances that move, boxes that change, a sheet that waves.
struct SoakScene {
  soak::BenchScene scene;
  pr::GeometryId movers, cloud, sheet, beads;

  SoakScene() {
    const auto primary = scene.add_ray<soak::Colour>("primary", {.miss = "bench.rmiss"});
    const auto box = scene.add_hit_group("box", {.kind = pr::HitGroupKind::procedural, .closest_hit = "bench.rchit",
                                                  .intersection = "bench.rint"});
    const auto triangle = scene.add_hit_group("triangle", {.closest_hit = "bench.rchit"});
    const auto with = [](pr::GeometryDesc d, pr::UpdatePolicy update) {
      d.update = update;
      return d;
    };
    std::vector<pr::InstanceTransform> placed;
    for (std::uint32_t i = 0; i < instances; ++i) placed.push_back(pr::instance_transform(place(i, 0.0f)));
    movers = scene.add_geometry(
        "instances", with(pr::GeometryDesc::procedural({pr::Aabb{}}, placed), pr::UpdatePolicy::DynamicTransform));
    std::vector<pr::Aabb> first;
    boxes_at(first, boxes, 0.0f);
    cloud = scene.add_geometry("boxes", with(pr::GeometryDesc::procedural(first), pr::UpdatePolicy::DynamicGeometry));
    sheet = scene.add_geometry("sheet", with(pr::GeometryDesc::triangles(mesh()), pr::UpdatePolicy::DynamicGeometry));
    pr::GeometryDesc bead = pr::GeometryDesc::procedural({pr::Aabb{}}, {});
    bead.may_add_instances = true;  // none declared: every bead is added at run time, as example 05's
    beads = scene.add_geometry("beads", bead);
    scene.set_global_signature({.bindings = {{pr::BindingKind::acceleration_structure, 0, 0, 1, "tlas"},
                                              {pr::BindingKind::storage_image, 1, 0, 1, "image"}}});
    scene.add_raygen("bench.rgen");
    scene.set_default_hit(primary, box);
    scene.set_default_hit(primary, triangle);
  }
};

/// Frame f's update, a kind in turn: moves (one instance, or all every 8th frame), new boxes
/// (their count changing every recount_every frames), new vertices, a mask toggled.
struct Animation {
  std::vector<glm::mat4> transforms = std::vector<glm::mat4>(instances);
  std::vector<glm::vec3> vertices;
  std::vector<pr::Aabb> next;
  std::vector<std::uint8_t> masks = std::vector<std::uint8_t>(instances, 0xFF);

  void apply(pr::vk::Renderer& renderer, const SoakScene& s, std::uint32_t f) {
    const float t = 0.01f * static_cast<float>(f);
    switch (f % 4) {
      case 0:
        if (f % 8 == 0) {
          for (std::uint32_t i = 0; i < instances; ++i) transforms[i] = place(i, t);
          renderer.set_transforms(s.movers, transforms);
        } else {
          renderer.set_transform(s.movers, (f / 8) % instances, place((f / 8) % instances, t));
        }
        break;
      case 1:
        boxes_at(next, (f / recount_every) % 2 == 0 ? boxes : boxes - 1, 0.05f * std::sin(t));
        renderer.set_aabbs(s.cloud, next);
        break;
      case 2:
        wave(vertices, t);
        renderer.set_vertices(s.sheet, vertices);
        break;
      default: {
        const std::uint32_t i = (f / 8) % instances;  // hidden at one mask frame, shown at the next
        masks[i] = masks[i] == 0xFF ? 0x00 : 0xFF;
        renderer.set_mask(s.movers, i, masks[i]);
      }
    }
  }
};

/// Example 05's beads: frame f adds one at place f % 8, and past four the oldest goes.
struct Beads {
  std::deque<std::uint32_t> live;

  void apply(pr::vk::Renderer& renderer, const SoakScene& s, std::uint32_t f) {
    const glm::vec3 at(-0.8f + 0.2f * static_cast<float>(f % 8), 0.8f, 0.0f);
    live.push_back(renderer.add_instance(s.beads, glm::scale(glm::translate(glm::mat4(1.0f), at), glm::vec3(0.08f))));
    if (live.size() > 4) {
      renderer.remove_instance(s.beads, live.front());
      live.pop_front();
    }
  }
};

/// Heap and resident bytes at the end of the warm-up and at the last check.
struct Memory {
  std::size_t first_heap = 0, last_heap = 0, first_rss = 0, last_rss = 0;
};

/// The summary lines and the verdict: 0, or 1 when the heap grew past --max-growth, some kind of
/// structure work never happened, or the validation layer spoke.
int verdict(const Options& o, const pr::vk::Context& ctx, const Memory& m, const pr::vk::FrameWork& total, double seconds) {
  const auto change = [](std::size_t a, std::size_t b) { return 100.0 * (static_cast<double>(b) - a) / a; };
  const double growth = change(m.first_heap, m.last_heap);
  const auto delta = [](std::size_t a, std::size_t b) { return static_cast<long long>(b) - static_cast<long long>(a); };
  std::printf("heap after the warm-up (frame %u) %zu bytes, at the end (frame %u) %zu bytes: %+lld bytes, %+.3f%% "
              "(limit %g%%)\n", o.every, m.first_heap, o.frames - o.frames % o.every, m.last_heap,
              delta(m.first_heap, m.last_heap), growth, o.max_growth);
  const double rss = change(m.first_rss, m.last_rss);
  std::printf("rss  after the warm-up %zu bytes, at the end %zu bytes: %+lld bytes, %+.3f%% (%s)\n", m.first_rss,
              m.last_rss, delta(m.first_rss, m.last_rss), rss,
              o.max_rss_growth < 0 ? "not checked" : ("limit " + std::to_string(o.max_rss_growth) + "%").c_str());
  std::printf("wall time %.1f s, %.3f ms/frame\n", seconds, 1000.0 * seconds / o.frames);
  int status = 0;
  if (growth > o.max_growth) {
    std::fprintf(stderr, "bench_soak: the heap grew %+.3f%% after the warm-up, more than --max-growth %g%%: a leak?\n",
                 growth, o.max_growth);
    status = 1;
  }
  if (o.max_rss_growth >= 0 && rss > o.max_rss_growth) {
    std::fprintf(stderr, "bench_soak: RSS grew %+.3f%% after the warm-up, more than --max-rss-growth %g%%\n", rss,
                 o.max_rss_growth);
    status = 1;
  }
  const bool beads = o.pattern == "beads";
  if (beads && total.tlas_builds < o.frames) {
    std::fprintf(stderr, "bench_soak: %u TLAS builds in %u frames: the beads were not added and removed\n",
                 total.tlas_builds, o.frames);
    status = 1;
  }
  if (!beads && (total.blas_builds == 0 || total.blas_refits == 0 || total.tlas_builds == 0 || total.tlas_updates == 0)) {
    std::fprintf(stderr, "bench_soak: some structure work never happened (%u BLAS builds, %u BLAS refits, %u TLAS "
                 "builds, %u TLAS updates): the updates were not applied\n", total.blas_builds, total.blas_refits,
                 total.tlas_builds, total.tlas_updates);
    status = 1;
  }
  if (!ctx.validation_messages().empty()) {
    std::fprintf(stderr, "bench_soak: %zu validation messages were reported\n", ctx.validation_messages().size());
    status = 1;
  }
  return status;
}

int run(const Options& o, std::uint32_t width, std::uint32_t height) {
  pr::vk::Context ctx({.device = o.device == "cpu"   ? pr::vk::DevicePreference::cpu
                                 : o.device == "gpu" ? pr::vk::DevicePreference::gpu
                                                     : pr::vk::DevicePreference::automatic,
                       .validation = o.validation});
  const SoakScene s;
  const char* dir = std::getenv("PROCEDURAY_BENCH_SHADER_DIR");  // for binaries carried to another machine
  pr::vk::Renderer renderer(ctx, s.scene, {.shader_dirs = {dir != nullptr ? dir : PROCEDURAY_BENCH_SHADER_DIR}});
  renderer.warm_up();
  // A first frame with readback, before any count: the readback's lazy allocations are not growth.
  if (one_colour(renderer.render(width, height, true).rgba)) {
    std::fprintf(stderr, "bench_soak: the first frame is all one colour: the scene renders nothing\n");
    return 1;
  }

  std::printf("bench_soak: device %s; %ux%u, %u frames, a line every %u%s\n", ctx.name().c_str(), width, height,
              o.frames, o.every, ctx.validation_enabled() ? ", validation on" : "");
  std::printf("%8s %12s %12s %9s   %s\n", "frame", "heap bytes", "rss bytes", "ms/frame",
              "work in these frames: BLAS builds, BLAS refits, TLAS builds, TLAS updates");
  Animation animation;
  Beads beads;
  pr::vk::FrameWork sum, total;
  Memory memory;
  const auto start = std::chrono::steady_clock::now();
  auto interval = start;
  for (std::uint32_t f = 1; f <= o.frames; ++f) {
    if (o.pattern == "beads") {
      beads.apply(renderer, s, f);
    } else {
      animation.apply(renderer, s, f);
    }
    const bool check = f % o.every == 0;
    bool blank = false;
    {  // the frame and its pixels are freed before the heap is sampled below
      const pr::vk::Frame frame = renderer.render(width, height, check);
      add(sum, frame.work);
      add(total, frame.work);
      blank = check && one_colour(frame.rgba);
    }
    if (!check) continue;
    if (blank) {
      std::fprintf(stderr, "bench_soak: frame %u is all one colour: the animated scene renders nothing\n", f);
      return 1;
    }
    const auto now = std::chrono::steady_clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - interval).count() / o.every;
    interval = now;
    if (o.trim) malloc_trim(0);  // freed pages back to the system: RSS then counts what is in use
    memory.last_heap = heap_bytes();
    memory.last_rss = rss_bytes();
    if (f == o.every) {  // the end of the warm-up: the baseline
      memory.first_heap = memory.last_heap;
      memory.first_rss = memory.last_rss;
    }
    std::printf("%8u %12zu %12zu %9.3f   %u, %u, %u, %u\n", f, memory.last_heap, memory.last_rss, ms, sum.blas_builds,
                sum.blas_refits, sum.tlas_builds, sum.tlas_updates);
    std::fflush(stdout);  // a line as it comes, for runs watched or cut short
    sum = {};
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return verdict(o, ctx, memory, total, seconds);
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"Soak benchmark: animated frames with every kind of structure update; fails if the heap grows",
               "bench_soak"};
  app.add_option("--frames", o.frames, "frames to trace")->check(CLI::Range(1u, 100000000u))->capture_default_str();
  app.add_option("--size", o.size, "image size WxH")->capture_default_str();
  app.add_option("--every", o.every, "frames between lines, readbacks and heap samples; the first are a warm-up")
      ->check(CLI::Range(1u, 100000000u))->capture_default_str();
  app.add_option("--max-growth", o.max_growth, "heap growth after the warm-up, in percent, that fails the run")
      ->check(CLI::Range(0.0, 1e6))->capture_default_str();
  app.add_option("--max-rss-growth", o.max_rss_growth, "RSS growth after the warm-up, in percent, that fails the run "
                 "(default: not checked; see above for why RSS steps without a leak)")->check(CLI::Range(0.0, 1e6));
  app.add_flag("--trim", o.trim, "malloc_trim(0) before each sample, so RSS counts pages in use, not the allocator's "
               "free pages (a heap whose top moved up steps RSS without a leak)");
  app.add_option("--pattern", o.pattern, "all: every kind of update in turn; beads: example 05's add and remove")
      ->check(CLI::IsMember({"all", "beads"}))->capture_default_str();
  app.add_option("--device", o.device, "cpu (lavapipe), gpu or auto")->check(CLI::IsMember({"cpu", "gpu", "auto"}))
      ->capture_default_str();
  app.add_flag("--validation", o.validation, "enable the Khronos validation layer; its messages fail the run");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;  // --help: 0; a bad option: reported, 2 as the others here
  }
  unsigned width = 0, height = 0;
  char extra = 0;
  if (std::sscanf(o.size.c_str(), "%ux%u%c", &width, &height, &extra) != 2 || width == 0 || height == 0) {
    std::fprintf(stderr, "bench_soak: --size '%s' is not WxH with positive numbers, e.g. 64x64\n", o.size.c_str());
    return 2;
  }
  if (o.frames < 2 * o.every) {
    std::fprintf(stderr, "bench_soak: --frames %u needs to be at least twice --every %u: the first interval is a "
                 "warm-up, and the heap is compared after it\n", o.frames, o.every);
    return 2;
  }
  try {
    return run(o, width, height);
  } catch (const pr::UsageError& e) {
    std::fprintf(stderr, "bench_soak: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_soak: %s\n", e.what());
    return 1;
  }
}
