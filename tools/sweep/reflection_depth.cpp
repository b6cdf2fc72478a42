// Frame time against reflection depth, recursive against iterative tracing (the CIS 565
// analysis): the paper scene at --size, reflections 0 to --max (the plane and every object
// reflect; min_weight 0, so no reflection is cut for adding little), each depth timed by GPU
// timestamps as the median of --frames traces after --warmup, the two modes interleaved frame
// by frame (A B A B ...) so both see the same machine. A table and a CSV; tools/sweep/depth_chart.py
// draws the chart.
//
//   proceduray_reflection_depth --device gpu --size 1920x1080 --csv depth.csv
//   tools/sweep/depth_chart.py depth.csv --out docs/images/reflection_depth.png
#include "02_paper_scene/paper_scene.hpp"
#include "common/run.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  std::string size = "640x360", device = "auto", csv;
  unsigned max_reflections = 8, frames = 15, warmup = 3;
  bool validation = false;
  CLI::App app{"Frame time against reflection depth, recursive and iterative tracing (paper scene)"};
  app.add_option("--size", size, "image size WxH")->capture_default_str();
  app.add_option("--device", device, "cpu (lavapipe), gpu or auto")->check(CLI::IsMember({"cpu", "gpu", "auto"}))
      ->capture_default_str();
  app.add_option("--max", max_reflections, "reflections 0 to this")->check(CLI::Range(0u, paper::max_depth_supported - 1))
      ->capture_default_str();
  app.add_option("--frames", frames, "timed frames per depth and mode (median)")->check(CLI::Range(1u, 1000u))
      ->capture_default_str();
  app.add_option("--warmup", warmup, "untimed frames before them")->check(CLI::Range(0u, 100u))->capture_default_str();
  app.add_option("--csv", csv, "CSV to write: mode, reflections, median, min and max trace ms");
  app.add_flag("--validation", validation, "enable the Khronos validation layer");
  CLI11_PARSE(app, argc, argv);
  unsigned width = 0, height = 0;
  char extra = 0;
  if (std::sscanf(size.c_str(), "%ux%u%c", &width, &height, &extra) != 2 || width == 0 || height == 0) {
    std::fprintf(stderr, "proceduray_reflection_depth: --size '%s' is not WxH with positive numbers, e.g. 640x360\n",
                 size.c_str());
    return 2;
  }
  try {
    namespace pr = proceduray;
    const pr::vk::DevicePreference pref = device == "cpu"   ? pr::vk::DevicePreference::cpu
                                          : device == "gpu" ? pr::vk::DevicePreference::gpu
                                                            : pr::vk::DevicePreference::automatic;
    pr::vk::Context ctx({.device = pref, .validation = validation});
    const std::uint32_t limit = max_reflections + 1;
    const paper::PaperScene recursive({}, paper::Tracing::recursive, limit), iterative({}, paper::Tracing::iterative, limit);
    pr::vk::Renderer a(ctx, recursive, recursive.renderer_options());
    pr::vk::Renderer b(ctx, iterative, iterative.renderer_options());
    std::printf("device: %s, %ux%u, median of %u frames after %u, modes interleaved; pipeline stack: recursive %u, "
                "iterative %u bytes\n%12s %14s %14s %8s\n",
                ctx.name().c_str(), width, height, frames, warmup, a.pipeline().stack_size(), b.pipeline().stack_size(),
                "reflections", "recursive ms", "iterative ms", "ratio");
    std::ofstream out;
    if (!csv.empty()) {
      out.open(csv, std::ios::trunc);
      if (!out) {
        std::fprintf(stderr, "proceduray_reflection_depth: cannot write '%s'; give a writable --csv path\n", csv.c_str());
        return 2;
      }
      out << "mode,reflections,trace_ms_median,trace_ms_min,trace_ms_max,width,height,device\n";
    }
    for (std::uint32_t r = 0; r <= max_reflections; ++r) {
      paper::SceneConstants c = paper::default_constants(width, height, 0.0f);
      c.max_depth = r + 1;
      c.min_weight = 0.0f;
      paper::set_frame(a, c);
      paper::set_frame(b, c);
      for (unsigned i = 0; i < warmup; ++i) {
        a.render(width, height, false);
        b.render(width, height, false);
      }
      std::vector<double> ta, tb;
      for (unsigned i = 0; i < frames; ++i) {
        ta.push_back(a.render(width, height, false).trace_ms);
        tb.push_back(b.render(width, height, false).trace_ms);
      }
      const double ma = examples::median(ta), mb = examples::median(tb);
      std::printf("%12u %14.3f %14.3f %8.3f\n", r, ma, mb, ma > 0 ? mb / ma : 0.0);
      if (out.is_open()) {
        for (const auto& [mode, t] : {std::pair{"recursive", &ta}, std::pair{"iterative", &tb}}) {
          out << mode << "," << r << "," << examples::median(*t) << "," << *std::min_element(t->begin(), t->end()) << ","
              << *std::max_element(t->begin(), t->end()) << "," << width << "," << height << "," << ctx.name() << "\n";
        }
      }
    }
    if (!csv.empty()) std::printf("wrote %s\n", csv.c_str());
    return ctx.validation_messages().empty() ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "proceduray_reflection_depth: %s\n", e.what());
    return 1;
  }
}
