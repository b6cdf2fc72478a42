// How wrong is a picture? Renders a scene on a device with per-pixel outputs (t, normal, steps,
// flags), computes the ground truth for the same camera rays on the CPU in double
// (examples/02_paper_scene/reference.hpp, examples/03_d3d12_scene/reference.hpp: closed forms,
// Lipschitz and escape-test searches, never the shaders' marching loop), and prints the accuracy
// table (accuracy/report.hpp), a line per object and a CSV.
//
//   proceduray_accuracy --size 320x240 --device cpu --csv paper.csv
//   proceduray_accuracy --scene d3d12 --size 320x240 --device cpu
//   proceduray_accuracy --device gpu --steps 512 --threshold 0.25 --csv sweep.csv --append
//   proceduray_accuracy --sdf gyroid.glsl --lipschitz 1.75 --size 1920x1080 --knob method=relaxed   (your field)
//
// Secondary rays (shadows, reflections) are off, so the steps a pixel reports are its camera
// ray's: evaluations per ray, a cost that does not depend on the machine.
#include "02_paper_scene/paper_scene.hpp"
#include "02_paper_scene/accuracy.hpp"
#include "02_paper_scene/world_options.hpp"
#include "common/set_constants.hpp"
#include "field/field_tool.hpp"
#include "02_paper_scene/reference.hpp"
#include "03_d3d12_scene/accuracy.hpp"

#include <proceduray/accuracy/report.hpp>
#include <proceduray/accuracy/samples.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace {

struct Knobs {
  std::string scene = "paper";
  std::string size = "160x120";
  std::string device = "auto";
  std::string csv;
  std::string steps_csv;
  std::string classes_csv;
  std::string classes_object;  // --classes-csv by this object's truth; empty: the frame's
  std::string split_csv;
  bool append = false;
  bool validation = false;
  float time = 0.0f;
  std::uint32_t steps = 0;   // 0: the scene's default
  float threshold = -1.0f;   // footprints; < 0: the scene's default
  float epsilon = -1.0f;     // world units; < 0: the scene's default
  float relative = -1.0f;    // threshold as a fraction of t; < 0: use threshold
  double spacing = 1.0e-3;   // reference spacing, footprints (paper scene)
  std::uint32_t iteration_factor = 1;
  std::uint32_t stride = 1;  // paper scene: the truth of one pixel in this many outside the silhouette band
  paper::WorldOptions where;  // paper scene: --origin, --raw-floats (examples/02_paper_scene/world_options.hpp)
};

namespace acc = proceduray::accuracy;

/// One object's line of the table and its rows of the CSV.
struct ObjectRow {
  std::string label;
  acc::Metrics metrics;
  double steps = 0.0;  // mean evaluations per ray that sees the object (reference or render)
  acc::EvaluationSplit split;  // by the object's reference: its hits, its near misses, the rest
  std::vector<acc::RayClass> classes;  // per pixel by the object's reference (--classes-object only)
};

/// What a scene's run gives the report.
struct Measurement {
  std::string settings;         // the scene line of the report
  std::string reference;        // the reference line of the report
  double trace_ms = 0.0;
  acc::Metrics all;
  acc::EvaluationSplit split;  // the whole frame's, by the reference
  std::vector<ObjectRow> objects;
  std::vector<acc::Label> labels;  // the CSV's knob columns
  std::vector<std::uint32_t> steps;  // per pixel: the camera ray's evaluations (heat map)
  std::vector<acc::RayClass> classes;  // per pixel: the frame's truth's class (heat map split)
};

/// One line per object: what a reader compares first.
void print_objects(const std::vector<ObjectRow>& rows) {
  std::printf("\n%-15s %6s %8s %9s %9s %9s %9s %9s %9s %9s %9s %9s\n", "object", "hits", "sil1 fh%", "sil2 fh%", "miss%",
              "depth med", "depth p99", "depth max", "normal med", "steps", "ev/hit", "ev/near");
  for (const ObjectRow& row : rows) {
    const acc::Metrics& m = row.metrics;
    const acc::ClassStats& a = m.all;
    std::printf("%-15s %6llu %8.2f %9.2f %9.2f %9.3g %9.3g %9.3g %9.3g %9.3g %9.3g %9.3g\n", row.label.c_str(),
                static_cast<unsigned long long>(a.both_hit), 100.0 * m[acc::PixelClass::silhouette_1px].false_hit_rate(),
                100.0 * m[acc::PixelClass::silhouette_2px].false_hit_rate(), 100.0 * a.false_miss_rate(),
                a.depth.median, a.depth.p99, a.depth.max, a.normal_degrees.median, row.steps, row.split.hit.per_ray(),
                row.split.near_miss.per_ray());
  }
}

proceduray::vk::DevicePreference device_of(const std::string& name) {
  if (name == "cpu") return proceduray::vk::DevicePreference::cpu;
  if (name == "gpu") return proceduray::vk::DevicePreference::gpu;
  return proceduray::vk::DevicePreference::automatic;
}

/// Renders one frame of `constants` after a warm-up; the frame and its per-pixel samples.
template <class Slot, class Constants>
std::pair<proceduray::vk::Frame, std::vector<acc::Sample>> render(proceduray::vk::Renderer& renderer,
                                                                  proceduray::UniformSlot<Slot> slot,
                                                                  const Constants& constants, unsigned width,
                                                                  unsigned height) {
  examples::set_constants(renderer, slot, constants);
  renderer.warm_up();
  proceduray::vk::Frame frame = renderer.render(width, height);
  std::vector<acc::Sample> samples = acc::samples_from(std::size_t{width} * height, frame.outputs.t, frame.outputs.normal,
                                                       frame.outputs.steps, frame.outputs.flags);
  return {std::move(frame), std::move(samples)};
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string format(const char* fmt, auto... values) {
  char text[512];
  std::snprintf(text, sizeof text, fmt, values...);
  return text;
}

/// The marched objects of each scene: their knobs are what --steps, --threshold ... change.
std::vector<std::uint32_t> marched_ids(const paper::Frame&) { return {paper::julia_id, paper::mandelbulb_id}; }
std::vector<std::uint32_t> marched_ids(const d3d12::SceneConstants&) {
  std::vector<std::uint32_t> ids;
  for (std::uint32_t k = d3d12::metaballs; k < d3d12::primitive_count; ++k) ids.push_back(d3d12::object_id(static_cast<d3d12::PrimitiveKind>(k)));
  return ids;
}

/// The knobs every scene shares, applied to every marched object's knobs.
template <class Constants>
void apply(const Knobs& k, Constants& constants) {
  constants.flags = 0;  // camera rays only: no shadow or reflection rays
  for (std::uint32_t id : marched_ids(constants)) {
    proceduray::MarchKnobs& m = constants.knobs[id];
    if (k.steps > 0) m.max_steps = k.steps;
    if (k.threshold >= 0.0f) m.threshold = k.threshold;
    // A threshold relative to t (the D3D12 sample's 1e-4 t) is that many pixel angles.
    if (k.relative >= 0.0f) m.threshold = k.relative / constants.camera.pixel_angle;
    if (k.epsilon >= 0.0f) m.epsilon = k.epsilon;
  }
  validate_knobs(constants);
}

template <class Constants>
std::vector<acc::Label> knob_labels(const Constants& c) {
  const proceduray::MarchKnobs& m = c.knobs[marched_ids(c).back()];
  return {{"max_steps", std::to_string(m.max_steps)}, {"threshold_px", std::to_string(m.threshold)},
          {"epsilon", std::to_string(m.epsilon)}, {"step_scale", std::to_string(m.step_scale)}};
}

Measurement measure_paper(proceduray::vk::Context& ctx, const Knobs& k, unsigned width, unsigned height) {
  // The scene may stand far from (0, 0, 0); its truth is the scene at 0: a translation moves no t.
  const paper::World world = k.where.world();
  const paper::PaperScene scene(paper::accuracy_outputs, paper::Tracing::recursive, paper::max_depth_limit, world);
  proceduray::vk::Renderer renderer(ctx, scene, scene.renderer_options());
  paper::Frame constants = paper::default_frame(width, height, k.time);
  apply(k, constants);
  paper::Frame placed = constants;
  world.place(placed);
  const auto [frame, samples] = render(renderer, paper::constants_slot, placed, width, height);
  const auto start = std::chrono::steady_clock::now();
  const paper::ReferenceOptions options{.spacing = k.spacing, .iteration_factor = k.iteration_factor};
  const paper::ReferenceImage truth = k.stride > 1
                                          ? paper::stratified_reference_image(constants, width, height, k.stride, options)
                                          : paper::reference_image(constants, width, height, options);
  Measurement out;
  out.reference = k.stride > 1
      ? format("reference: %.2f s, stratified: %zu of %zu pixels traced, one in %u off the silhouette band "
               "(spacing %.3g footprints, iterations x%u)", seconds_since(start), truth.traced, truth.pixels.size(),
               k.stride, k.spacing, k.iteration_factor)
      : format("reference: %.2f s, %.3g evaluations (spacing %.3g footprints, iterations x%u)", seconds_since(start),
               static_cast<double>(truth.evaluations), k.spacing, k.iteration_factor);
  out.settings = format("scene: paper, %ux%u, time %.2f s; Mandelbulb knobs: %s", width, height,
                        static_cast<double>(k.time), proceduray::describe(constants.knobs[paper::mandelbulb_id]).c_str());
  if (k.where.given()) {
    out.settings += format("; placed at (%g, %g, %g), %s", world.offset.x, world.offset.y, world.offset.z,
                           k.where.raw_floats ? "raw float coordinates" : "WorldOrigin at the camera");
  }
  out.trace_ms = frame.trace_ms;
  out.steps.assign(frame.outputs.steps.begin(), frame.outputs.steps.end());
  out.all = examples::measure_frame(truth.frame(), samples, truth.pixels, truth.weights, truth.stride);
  out.split = acc::split_evaluations(truth.frame(), truth.pixels, samples, truth.weights);
  out.classes = acc::ray_classes(truth.frame(), truth.pixels, truth.weights);
  const std::vector<paper::ObjectId> seen = paper::device_objects(renderer.plan(), frame.outputs.ids);
  for (const auto& [id, label] : paper::named_objects) {
    out.objects.push_back({label, paper::measure_object(truth, samples, seen, id),
                           examples::mean_steps(std::span<const paper::ObjectId>(truth.objects),
                                                std::span<const acc::Sample>(samples),
                                                std::span<const paper::ObjectId>(seen), id,
                                                std::span<const std::uint32_t>(truth.weights)),
                           examples::split_object(truth.frame(), std::span<const acc::Reference>(truth.pixels),
                                                  std::span<const paper::ObjectId>(truth.objects),
                                                  std::span<const acc::Sample>(samples), id,
                                                  std::span<const std::uint32_t>(truth.weights))});
    if (label == k.classes_object) {
      out.objects.back().classes = acc::ray_classes(
          truth.frame(), examples::object_reference(std::span<const acc::Reference>(truth.pixels),
                                                    std::span<const paper::ObjectId>(truth.objects), id),
          truth.weights);
    }
  }
  out.labels = knob_labels(constants);
  return out;
}

Measurement measure_d3d12(proceduray::vk::Context& ctx, const Knobs& k, unsigned width, unsigned height) {
  const d3d12::D3d12Scene scene(d3d12::accuracy_outputs);
  proceduray::vk::Renderer renderer(ctx, scene, d3d12::renderer_options());
  d3d12::SceneConstants constants = d3d12::default_constants(d3d12::sample_camera(width, height), k.time);
  apply(k, constants);
  const auto [frame, samples] = render(renderer, d3d12::constants_slot, constants, width, height);
  const auto start = std::chrono::steady_clock::now();
  const d3d12::ReferenceImage truth = d3d12::reference_image(constants, width, height);
  Measurement out;
  out.reference = format("reference: %.2f s, %.3g evaluations", seconds_since(start),
                         static_cast<double>(truth.evaluations));
  out.settings = format("scene: d3d12, %ux%u, time %.2f s; SDF knobs: %s; metaballs: %s", width, height,
                        static_cast<double>(k.time), proceduray::describe(d3d12::knobs(constants, d3d12::cog)).c_str(),
                        proceduray::describe(d3d12::knobs(constants, d3d12::metaballs)).c_str());
  out.trace_ms = frame.trace_ms;
  out.steps.assign(frame.outputs.steps.begin(), frame.outputs.steps.end());
  out.all = acc::measure(truth.frame(), samples, truth.pixels);
  out.split = acc::split_evaluations(truth.frame(), truth.pixels, samples);
  out.classes = acc::ray_classes(truth.frame(), truth.pixels);
  const std::vector<std::uint32_t> seen = d3d12::device_objects(renderer.plan(), frame.outputs.ids);
  for (std::uint32_t id = d3d12::plane_id; id < d3d12::object_id_count; ++id) {
    out.objects.push_back({d3d12::object_name(id), d3d12::measure_object(truth, samples, seen, id),
                           examples::mean_steps(std::span<const std::uint32_t>(truth.objects),
                                                std::span<const acc::Sample>(samples),
                                                std::span<const std::uint32_t>(seen), id),
                           examples::split_object(truth.frame(), std::span<const acc::Reference>(truth.pixels),
                                                  std::span<const std::uint32_t>(truth.objects),
                                                  std::span<const acc::Sample>(samples), id)});
    if (d3d12::object_name(id) == k.classes_object) {
      out.objects.back().classes = acc::ray_classes(
          truth.frame(), examples::object_reference(std::span<const acc::Reference>(truth.pixels),
                                                    std::span<const std::uint32_t>(truth.objects), id));
    }
  }
  out.labels = knob_labels(constants);
  return out;
}

/// Writes a row per image row, a column per pixel (heatmap.py reads it); false with a message when it cannot.
bool write_grid(const std::string& path, const char* option, unsigned width, const std::vector<std::uint32_t>& values) {
  std::ofstream out(path, std::ios::trunc);
  if (!out || width == 0 || values.size() % width != 0) {
    std::fprintf(stderr, "proceduray_accuracy: cannot write '%s'; give a writable %s path\n", path.c_str(), option);
    return false;
  }
  for (std::size_t i = 0; i < values.size(); ++i) out << values[i] << ((i + 1) % width == 0 ? "\n" : ",");
  std::printf("wrote %s\n", path.c_str());
  return true;
}

/// Writes the evaluations by ray class: the frame's three classes (object "all"), then each
/// object's hits and near misses by its own truth; share: of the frame's evaluations.
bool write_split(const std::string& path, const Measurement& m) {
  std::ofstream out(path, std::ios::trunc);
  if (!out) {
    std::fprintf(stderr, "proceduray_accuracy: cannot write '%s'; give a writable --split-csv path\n", path.c_str());
    return false;
  }
  const double all = m.split.evaluations();
  out << "object,class,rays,evaluations,evals_per_ray,share\n";
  auto row = [&](const std::string& object, const char* cls, const acc::EvaluationClass& c) {
    if (c.rays > 0.0) out << object << ',' << cls << ',' << c.rays << ',' << c.evaluations << ',' << c.per_ray() << ','
                          << (all > 0.0 ? c.evaluations / all : 0.0) << '\n';
  };
  row("all", "hit", m.split.hit);
  row("all", "near_miss", m.split.near_miss);
  row("all", "far_miss", m.split.far_miss);
  for (const ObjectRow& o : m.objects) {
    row(o.label, "hit", o.split.hit);
    row(o.label, "near_miss", o.split.near_miss);
  }
  std::printf("wrote %s\n", path.c_str());
  return true;
}

int run(const Knobs& k) {
  unsigned width = 0, height = 0;
  char extra = 0;
  if (std::sscanf(k.size.c_str(), "%ux%u%c", &width, &height, &extra) != 2 || width == 0 || height == 0) {
    std::fprintf(stderr, "proceduray_accuracy: --size '%s' is not WxH with positive numbers, e.g. 320x240\n", k.size.c_str());
    return 2;
  }
  if (k.where.given() && k.scene != "paper") {
    std::fprintf(stderr, "proceduray_accuracy: --origin places the paper scene only, not '%s'; drop it or pass "
                 "--scene paper\n", k.scene.c_str());
    return 2;
  }
  if (!k.classes_object.empty()) {  // refused before the truth is computed, not after
    std::vector<std::string> names;
    if (k.scene == "d3d12") {
      for (std::uint32_t id = d3d12::plane_id; id < d3d12::object_id_count; ++id) names.push_back(d3d12::object_name(id));
    } else {
      for (const auto& [id, label] : paper::named_objects) names.emplace_back(label);
    }
    if (std::find(names.begin(), names.end(), k.classes_object) == names.end()) {
      std::string list;
      for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
      std::fprintf(stderr, "proceduray_accuracy: --classes-object '%s' is not an object of the %s scene; give one of %s\n",
                   k.classes_object.c_str(), k.scene.c_str(), list.c_str());
      return 2;
    }
  }
  proceduray::vk::Context ctx({.device = device_of(k.device), .validation = k.validation});
  const Measurement m = k.scene == "d3d12" ? measure_d3d12(ctx, k, width, height) : measure_paper(ctx, k, width, height);
  std::printf("device: %s\n%s\ntrace: %.3f ms; %s\n\n", ctx.name().c_str(), m.settings.c_str(), m.trace_ms,
              m.reference.c_str());
  acc::write_table(std::cout, m.all);
  std::fflush(stdout);
  print_objects(m.objects);
  std::printf("(depth in pixel footprints; fh%%: false hits among the silhouette band's rays; steps: mean per ray that sees the object;\n"
              " ev/hit, ev/near: mean evaluations of the rays that hit it, and of those that miss it within 2 pixels of its silhouette)\n");
  const acc::EvaluationSplit& e = m.split;
  std::printf("evaluations per ray, whole frame: hits %.2f (%.0f%%), near misses %.2f (%.0f%%), far misses %.2f (%.0f%%)\n",
              e.hit.per_ray(), 100.0 * e.share(e.hit), e.near_miss.per_ray(), 100.0 * e.share(e.near_miss),
              e.far_miss.per_ray(), 100.0 * e.share(e.far_miss));
  if (!k.steps_csv.empty() && !write_grid(k.steps_csv, "--steps-csv", width, m.steps)) return 1;
  const std::vector<acc::RayClass>* chosen = &m.classes;
  for (const ObjectRow& o : m.objects) {
    if (!k.classes_object.empty() && o.label == k.classes_object) chosen = &o.classes;
  }
  std::vector<std::uint32_t> classes;
  for (acc::RayClass c : *chosen) classes.push_back(static_cast<std::uint32_t>(c));
  if (!k.classes_csv.empty() && !write_grid(k.classes_csv, "--classes-csv", width, classes)) return 1;
  if (!k.split_csv.empty() && !write_split(k.split_csv, m)) return 1;
  if (!k.csv.empty()) {
    std::ofstream out(k.csv, k.append ? std::ios::app : std::ios::trunc);
    if (!out) {
      std::fprintf(stderr, "proceduray_accuracy: cannot write '%s'; give a writable --csv path\n", k.csv.c_str());
      return 1;
    }
    std::vector<acc::Label> labels{{"scene", k.scene}, {"device", ctx.name()}, {"width", std::to_string(width)},
                                   {"height", std::to_string(height)}};
    labels.insert(labels.end(), m.labels.begin(), m.labels.end());
    labels.push_back({"trace_ms", std::to_string(m.trace_ms)});
    labels.push_back({"object", "all"});
    labels.push_back({"object_evals", std::to_string(m.all.all.steps.mean)});  // per ray that sees the object
    // Evaluations per ray that hits, and per near miss (evaluation_split.hpp), by the object's reference.
    labels.push_back({"evals_per_hit", std::to_string(m.split.hit.per_ray())});
    labels.push_back({"evals_per_near_miss", std::to_string(m.split.near_miss.per_ray())});
    if (!k.append || out.tellp() == 0) acc::write_csv_header(out, labels);
    acc::write_csv_rows(out, m.all, labels);
    for (const ObjectRow& row : m.objects) {
      labels[labels.size() - 4].value = row.label;
      labels[labels.size() - 3].value = std::to_string(row.steps);
      labels[labels.size() - 2].value = std::to_string(row.split.hit.per_ray());
      labels.back().value = std::to_string(row.split.near_miss.per_ray());
      acc::write_csv_rows(out, row.metrics, labels);
    }
    std::printf("\nwrote %s\n", k.csv.c_str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // A user's field (--sdf file.glsl --aabb ... --lipschitz ...): vk::FieldMeter against its own truth.
  if (field_tool::wants_field(argc, argv)) return field_tool::measure_main(argc, argv, "proceduray_accuracy");
  Knobs k;
  CLI::App app{"Renders a scene with per-pixel outputs and measures it against a double-precision ground truth"};
  app.add_option("--scene", k.scene, "paper (the report's) or d3d12 (the D3D12 sample's)")
      ->check(CLI::IsMember({"paper", "d3d12"}))->capture_default_str();
  app.add_option("--size", k.size, "image size WxH")->capture_default_str();
  app.add_option("--device", k.device, "cpu (lavapipe), gpu or auto")->check(CLI::IsMember({"cpu", "gpu", "auto"}))
      ->capture_default_str();
  app.add_option("--csv", k.csv, "CSV file to write (a header, then a row per pixel class)");
  app.add_option("--steps-csv", k.steps_csv, "per-pixel evaluations as a W x H CSV (tools/accuracy/heatmap.py draws it)");
  app.add_option("--classes-csv", k.classes_csv, "per-pixel ray class as a W x H CSV: 1 hit, 2 near miss, 3 far miss, "
                 "0 unknown (heatmap.py --classes splits the heat map by it)");
  app.add_option("--classes-object", k.classes_object, "--classes-csv by this object's truth (its hits, its near "
                 "misses; 3: the rest) instead of the whole frame's");
  app.add_option("--split-csv", k.split_csv, "evaluations by ray class, the frame's and each object's "
                 "(tools/accuracy/split_chart.py draws them)");
  app.add_flag("--append", k.append, "append rows to --csv (a sweep), writing the header only into an empty file");
  app.add_flag("--validation", k.validation, "enable the Khronos validation layer");
  app.add_option("--time", k.time, "scene time in seconds (the fractals' animation)")->capture_default_str();
  app.add_option("--steps", k.steps, "sphere-tracing steps (0: the scene's default)")->check(CLI::Range(0u, 100000u));
  app.add_option("--threshold", k.threshold, "hit threshold in pixel footprints (default: the scene's)")
      ->check(CLI::Range(0.0f, 100.0f));
  app.add_option("--relative", k.relative, "hit threshold as a fraction of t, e.g. 1e-4 (the D3D12 sample's); "
                 "overrides --threshold")->check(CLI::Range(0.0f, 1.0f));
  app.add_option("--epsilon", k.epsilon, "absolute hit threshold floor, world units (default: the scene's)")
      ->check(CLI::Range(0.0f, 1.0f));
  app.add_option("--spacing", k.spacing, "reference sample spacing in footprints (paper scene)")->check(CLI::Range(1e-6, 1.0))
      ->capture_default_str();
  app.add_option("--iterations-factor", k.iteration_factor, "reference fractal iterations x this (2: truncation error)")
      ->check(CLI::Range(1u, 8u))->capture_default_str();
  app.add_option("--stride", k.stride, "paper scene: the truth of every pixel near a silhouette and one in this many "
                 "elsewhere, counted that many times (accuracy/stratified.hpp); 1: every pixel")
      ->check(CLI::Range(1u, 1024u))->capture_default_str();
  paper::add_world_options(app, k.where);
  CLI11_PARSE(app, argc, argv);
  try {
    return run(k);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "proceduray_accuracy: %s\n", e.what());
    return 1;
  }
}
