// How wrong is a picture? Renders a scene on a device with per-pixel outputs (t, normal, steps,
// flags), computes the ground truth for the same camera rays on the CPU in double
// (examples/02_paper_scene/reference.hpp: closed forms, Lipschitz and escape-test searches, never
// the shaders' marching loop), and prints the accuracy table (accuracy/report.hpp) and a CSV.
//
//   proceduray_accuracy --size 320x240 --device cpu --csv paper.csv
//   proceduray_accuracy --device gpu --steps 512 --threshold 0.25 --csv sweep.csv --append
//
// Secondary rays (shadows, reflections) are off, so the steps a pixel reports are its camera
// ray's: evaluations per ray, a cost that does not depend on the machine.
#include "02_paper_scene/paper_scene.hpp"
#include "02_paper_scene/accuracy.hpp"
#include "02_paper_scene/reference.hpp"

#include <proceduray/accuracy/report.hpp>
#include <proceduray/accuracy/samples.hpp>

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

namespace {

struct Knobs {
  std::string size = "160x120";
  std::string device = "auto";
  std::string csv;
  bool append = false;
  bool validation = false;
  float time = 0.0f;
  std::uint32_t steps = 0;   // 0: the scene's default
  float threshold = -1.0f;   // footprints; < 0: the scene's default
  double spacing = 1.0e-3;   // reference spacing, footprints
  std::uint32_t iteration_factor = 1;
};

namespace acc = proceduray::accuracy;

/// One line per object: what a reader compares first.
void print_objects(const paper::ReferenceImage& truth, const std::vector<acc::Sample>& samples,
                   const std::vector<paper::ObjectId>& device_objects, const std::vector<acc::Metrics>& per_object) {
  std::printf("\n%-11s %6s %8s %9s %9s %9s %9s %9s %9s %9s\n", "object", "hits", "sil1 fh%", "sil2 fh%", "miss%",
              "depth med", "depth p99", "depth max", "normal med", "steps");
  for (std::size_t o = 0; o < paper::named_objects.size(); ++o) {
    const auto& [id, label] = paper::named_objects[o];
    const acc::Metrics& m = per_object[o];
    const acc::ClassStats& a = m.all;
    double steps = 0.0;  // mean over the rays that see the object, in the reference or the render
    std::size_t rays = 0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      if (truth.objects[i] != id && device_objects[i] != id) continue;
      steps += samples[i].steps;
      ++rays;
    }
    std::printf("%-11s %6llu %8.2f %9.2f %9.2f %9.3g %9.3g %9.3g %9.3g %9.3g\n", label,
                static_cast<unsigned long long>(a.both_hit), 100.0 * m[acc::PixelClass::silhouette_1px].false_hit_rate(),
                100.0 * m[acc::PixelClass::silhouette_2px].false_hit_rate(), 100.0 * a.false_miss_rate(),
                a.depth.median, a.depth.p99, a.depth.max, a.normal_degrees.median, rays > 0 ? steps / double(rays) : 0.0);
  }
}

proceduray::vk::DevicePreference device_of(const std::string& name) {
  if (name == "cpu") return proceduray::vk::DevicePreference::cpu;
  if (name == "gpu") return proceduray::vk::DevicePreference::gpu;
  return proceduray::vk::DevicePreference::automatic;
}

int run(const Knobs& k) {
  unsigned width = 0, height = 0;
  char extra = 0;
  if (std::sscanf(k.size.c_str(), "%ux%u%c", &width, &height, &extra) != 2 || width == 0 || height == 0) {
    std::fprintf(stderr, "proceduray_accuracy: --size '%s' is not WxH with positive numbers, e.g. 320x240\n", k.size.c_str());
    return 2;
  }
  proceduray::vk::Context ctx({.device = device_of(k.device), .validation = k.validation});
  const paper::PaperScene scene(paper::accuracy_outputs);
  proceduray::vk::Renderer renderer(ctx, scene, scene.renderer_options());
  paper::SceneConstants constants = paper::default_constants(width, height, k.time);
  constants.flags = 0;  // camera rays only: no shadow or reflection rays
  if (k.steps > 0) constants.max_steps = k.steps;
  if (k.threshold >= 0.0f) constants.footprint_scale = k.threshold;
  renderer.set(paper::constants_slot, constants);
  renderer.warm_up();
  const proceduray::vk::Frame frame = renderer.render(width, height);
  const std::size_t pixels = std::size_t{width} * height;
  const auto samples = proceduray::accuracy::samples_from(pixels, frame.outputs.t, frame.outputs.normal,
                                                          frame.outputs.steps, frame.outputs.flags);
  const auto start = std::chrono::steady_clock::now();
  const paper::ReferenceImage truth =
      paper::reference_image(constants, width, height, {.spacing = k.spacing, .iteration_factor = k.iteration_factor});
  const double reference_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const proceduray::accuracy::Metrics m = proceduray::accuracy::measure(truth.frame(), samples, truth.pixels);
  const std::vector<paper::ObjectId> device_objects = paper::device_objects(renderer.plan(), frame.outputs.ids);

  std::printf("device: %s\nscene: paper, %ux%u, time %.2f s, %u steps, threshold %.3g footprints, step scale %.3g\n",
              ctx.name().c_str(), width, height, static_cast<double>(k.time), constants.max_steps,
              static_cast<double>(constants.footprint_scale), static_cast<double>(constants.step_scale));
  std::printf("trace: %.3f ms; reference: %.2f s, %.3g evaluations (spacing %.3g footprints, iterations x%u)\n\n",
              frame.trace_ms, reference_s, static_cast<double>(truth.evaluations), k.spacing, k.iteration_factor);
  proceduray::accuracy::write_table(std::cout, m);
  std::fflush(stdout);
  std::vector<acc::Metrics> per_object;  // measured once: the table and the CSV both use them
  for (const auto& named : paper::named_objects) {
    per_object.push_back(paper::measure_object(truth, samples, device_objects, named.first));
  }
  print_objects(truth, samples, device_objects, per_object);
  std::printf("(depth in pixel footprints; fh%%: false hits among the silhouette band's rays; steps: mean per ray that sees the object)\n");
  if (!k.csv.empty()) {
    std::ofstream out(k.csv, k.append ? std::ios::app : std::ios::trunc);
    if (!out) {
      std::fprintf(stderr, "proceduray_accuracy: cannot write '%s'; give a writable --csv path\n", k.csv.c_str());
      return 1;
    }
    const std::vector<proceduray::accuracy::Label> labels{
        {"scene", "paper"}, {"device", ctx.name()}, {"width", std::to_string(width)}, {"height", std::to_string(height)},
        {"max_steps", std::to_string(constants.max_steps)}, {"threshold_px", std::to_string(constants.footprint_scale)},
        {"step_scale", std::to_string(constants.step_scale)}, {"trace_ms", std::to_string(frame.trace_ms)}};
    std::vector<acc::Label> with_object = labels;
    with_object.push_back({"object", "all"});
    if (!k.append || out.tellp() == 0) acc::write_csv_header(out, with_object);
    acc::write_csv_rows(out, m, with_object);
    for (std::size_t o = 0; o < paper::named_objects.size(); ++o) {
      with_object.back().value = paper::named_objects[o].second;
      acc::write_csv_rows(out, per_object[o], with_object);
    }
    std::printf("\nwrote %s\n", k.csv.c_str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Knobs k;
  CLI::App app{"Renders a scene with per-pixel outputs and measures it against a double-precision ground truth"};
  app.add_option("--size", k.size, "image size WxH")->capture_default_str();
  app.add_option("--device", k.device, "cpu (lavapipe), gpu or auto")->check(CLI::IsMember({"cpu", "gpu", "auto"}))
      ->capture_default_str();
  app.add_option("--csv", k.csv, "CSV file to write (a header, then a row per pixel class)");
  app.add_flag("--append", k.append, "append rows to --csv (a sweep), writing the header only into an empty file");
  app.add_flag("--validation", k.validation, "enable the Khronos validation layer");
  app.add_option("--time", k.time, "scene time in seconds (the fractals' animation)")->capture_default_str();
  app.add_option("--steps", k.steps, "sphere-tracing steps (0: the scene's default)")->check(CLI::Range(0u, 100000u));
  app.add_option("--threshold", k.threshold, "hit threshold in pixel footprints (default: the scene's)")
      ->check(CLI::Range(0.0f, 100.0f));
  app.add_option("--spacing", k.spacing, "reference sample spacing in footprints")->check(CLI::Range(1e-6, 1.0))
      ->capture_default_str();
  app.add_option("--iterations-factor", k.iteration_factor, "reference fractal iterations x this (2: truncation error)")
      ->check(CLI::Range(1u, 8u))->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    return run(k);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "proceduray_accuracy: %s\n", e.what());
    return 1;
  }
}
