// Speed against accuracy, measured: renders a scene once per point of a grid of march knobs,
// times it with GPU timestamps, and measures every marched object against the scene's ground
// truth (computed once, in double, independently of the marches). One CSV row group per object
// and point; tools/sweep/chart.py draws the charts from it.
//
//   proceduray_sweep --scene d3d12 --size 256x256 --device gpu --preset methods --csv d3d12.csv
//   proceduray_sweep --scene paper --objects mandelbulb --vary threshold=0.125,0.25,0.5,1
//                    --vary method=sphere,relaxed --set relaxation=1.5 --csv bulb.csv   (one line)
//   proceduray_sweep --scene d3d12 --alone --objects cog,metaballs --preset methods --shard 1/4 --csv part1.csv
//   proceduray_sweep --sdf gyroid.glsl --lipschitz 1.75 --size 1920x1080 --csv gyroid.csv   (your field: a calibration table)
//
// A point sets knobs on every selected object that accepts them (march/knobs.hpp's validate);
// an object that does not (segment tracing on an SDF) keeps its defaults and gets no row for
// that point. Secondary rays are off: a pixel's evaluations are its camera ray's, a cost that
// does not depend on the machine. Time: the median of --frames traces after --warmup, by a
// renderer without per-pixel outputs (the outputs are read from a second one), so it is the
// frame as a user renders it. --alone (d3d12) renders each object by itself with its own
// camera: a time per primitive. --shard i/n keeps the i-th of n contiguous blocks of points
// (1 <= i <= n, as proceduray-field and --sdf), so a batch system can split a sweep over
// machines; the CSVs concatenate in shard order into the unsharded one (one header each).
// The reference uses each object's default iterations: fewer iterations show as error.
#include "02_paper_scene/accuracy.hpp"
#include "common/run.hpp"
#include "field/field_tool.hpp"
#include "02_paper_scene/paper_scene.hpp"
#include "02_paper_scene/reference.hpp"
#include "02_paper_scene/world_options.hpp"
#include "03_d3d12_scene/accuracy.hpp"

#include <proceduray/accuracy/report.hpp>
#include <proceduray/accuracy/samples.hpp>
#include <proceduray/march/calibration.hpp>
#include <proceduray/march/knobs.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace acc = proceduray::accuracy;
namespace pr = proceduray;

struct Options {
  std::string scene = "paper";
  std::string size = "256x256";
  std::string device = "auto";
  std::string csv;
  std::string calibration;
  bool append = false;
  std::vector<std::string> objects;
  std::vector<std::string> vary;
  std::vector<std::string> set;
  std::string preset;
  std::string shard = "1/1";
  bool alone = false;
  bool validation = false;
  float time = 0.0f;
  double spacing = 1.0e-3;
  std::uint32_t stride = 1;  // paper: the truth of one pixel in this many off the silhouette band
  unsigned frames = 9;
  unsigned warmup = 3;
  paper::WorldOptions where;  // paper: --origin, --raw-floats (examples/02_paper_scene/world_options.hpp)
};

/// A usage error of the tool: printed with its name, exit status 2.
struct BadInput : std::runtime_error {
  using std::runtime_error::runtime_error;
};

using Assignment = std::vector<std::pair<std::string, std::string>>;  // knob name, value

/// One point of the sweep: its knob assignments and a short label.
struct Point {
  std::string label;
  Assignment knobs;
  bool sample = false;  ///< the D3D12 sample's settings (a relative threshold of 1e-4 t)
};

std::pair<std::string, std::string> split_assignment(const std::string& text, const char* option) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size()) {
    throw BadInput(std::string(option) + " '" + text + "' is not knob=value[,value...]; e.g. threshold=0.25,0.5");
  }
  return {text.substr(0, eq), text.substr(eq + 1)};
}

std::vector<std::string> split(const std::string& text, char by) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const auto at = text.find(by, start);
    out.push_back(text.substr(start, at - start));
    if (at == std::string::npos) return out;
    start = at + 1;
  }
}

std::string label_of(const Assignment& a) {
  std::string out;
  for (const auto& [k, v] : a) out += (out.empty() ? "" : " ") + k + "=" + v;
  return out.empty() ? "defaults" : out;
}

/// The grid: the product of every --vary axis (one point of defaults without any).
std::vector<Point> grid(const std::vector<std::string>& vary) {
  std::vector<Assignment> points{{}};
  for (const std::string& axis : vary) {
    const auto [name, values] = split_assignment(axis, "--vary");
    std::vector<Assignment> next;
    for (const Assignment& p : points) {
      for (const std::string& v : split(values, ',')) {
        Assignment q = p;
        q.emplace_back(name, v);
        next.push_back(std::move(q));
      }
    }
    points = std::move(next);
  }
  std::vector<Point> out;
  for (Assignment& a : points) out.push_back({label_of(a), std::move(a)});
  return out;
}

/// The shipped grid "methods": every method at seven thresholds (1/32 to 2 footprints), its main knob at two values,
/// probes of 3 and 4 distances, the unrefined hit rule, tetrahedral normals, iterations by distance, and the D3D12 sample's
/// settings. Objects take the points their kind accepts.
std::vector<Point> methods_preset() {
  std::vector<Assignment> points;
  for (const char* t : {"0.03125", "0.0625", "0.125", "0.25", "0.5", "1", "2"}) {
    points.push_back({{"method", "sphere"}, {"threshold", t}});
    points.push_back({{"method", "lipschitz"}, {"threshold", t}});
    points.push_back({{"method", "relaxed"}, {"relaxation", "1.5"}, {"threshold", t}});
    points.push_back({{"method", "segment"}, {"threshold", t}});
    points.push_back({{"method", "fixed"}, {"fixed_steps", "64"}, {"threshold", t}});
    points.push_back({{"method", "fixed"}, {"fixed_steps", "256"}, {"threshold", t}});
  }
  // Longer probes below the threshold: for estimates that underestimate near their surface.
  for (const char* t : {"0.25", "0.5", "1"}) {
    points.push_back({{"method", "sphere"}, {"probe", "3"}, {"threshold", t}});
    points.push_back({{"method", "sphere"}, {"probe", "4"}, {"threshold", t}});
    points.push_back({{"method", "lipschitz"}, {"probe", "4"}, {"threshold", t}});
    points.push_back({{"method", "relaxed"}, {"relaxation", "1.2"}, {"probe", "4"}, {"threshold", t}});
  }
  points.push_back({{"method", "relaxed"}, {"relaxation", "1.8"}, {"threshold", "0.5"}});
  points.push_back({{"method", "sphere"}, {"threshold", "0.5"}, {"refine", "off"}});
  points.push_back({{"method", "lipschitz"}, {"threshold", "0.5"}, {"refine", "off"}});
  // The classic rule (a hit below the threshold, no crossing): what the sign change buys.
  points.push_back({{"method", "sphere"}, {"threshold", "0.5"}, {"refine", "classic"}});
  points.push_back({{"method", "lipschitz"}, {"threshold", "0.5"}, {"refine", "classic"}});
  points.push_back({{"method", "sphere"}, {"threshold", "0.5"}, {"normal", "tetrahedral"}});
  points.push_back({{"method", "lipschitz"}, {"threshold", "0.5"}, {"normal", "tetrahedral"}});
  points.push_back({{"method", "sphere"}, {"threshold", "0.5"}, {"iterations", "4"}});
  points.push_back({{"method", "sphere"}, {"threshold", "0.5"}, {"iteration_mode", "by_distance"}, {"iteration_detail", "0.01"}});
  points.push_back({{"method", "sphere"}, {"threshold", "0.5"}, {"max_steps", "64"}});
  std::vector<Point> out;
  for (Assignment& a : points) out.push_back({label_of(a), std::move(a)});
  out.push_back({"d3d12 sample", {}, true});
  return out;
}

/// The D3D12 sample's settings on knobs `k`: a threshold of 1e-4 t (that many pixel angles), 512
/// steps, its marches (Lipschitz-scaled sphere tracing, fixed 128 steps for the metaballs).
void sample_settings(pr::MarchKnobs& k, std::string_view kind, float pixel_angle) {
  k.threshold_mode = pr::MarchThreshold::footprint;
  k.threshold = 1.0e-4f / pixel_angle;
  k.max_steps = 512;
  if (kind == "metaballs") {
    k.method = pr::MarchMethod::fixed;
    k.fixed_steps = 128;
  } else if (kind == "sdf") {
    k.method = pr::MarchMethod::lipschitz;
  }
}

/// A marched object of a scene: its name, id and what it accepts.
struct Object {
  std::string name;
  std::uint32_t id;
  const pr::MarchCapabilities* caps;
};

std::vector<Object> scene_objects(const std::string& scene) {
  std::vector<Object> out;
  if (scene == "paper") {
    for (const auto& [id, name] : paper::marched_objects) out.push_back({name, id, &paper::capabilities(id)});
  } else {
    for (std::uint32_t k = d3d12::metaballs; k < d3d12::primitive_count; ++k) {
      const auto kind = static_cast<d3d12::PrimitiveKind>(k);
      out.push_back({std::string(d3d12::primitive_names[k]), d3d12::object_id(kind), &d3d12::capabilities(kind)});
    }
  }
  return out;
}

std::vector<Object> selected(const std::vector<Object>& all, const std::vector<std::string>& names) {
  if (names.empty()) return all;
  std::vector<Object> out;
  for (const std::string& n : names) {
    const auto it = std::find_if(all.begin(), all.end(), [&](const Object& o) { return o.name == n; });
    if (it == all.end()) {
      std::string valid;
      for (const Object& o : all) valid += (valid.empty() ? "" : ", ") + o.name;
      throw BadInput("--objects: unknown object '" + n + "'; marched objects of this scene: " + valid);
    }
    out.push_back(*it);
  }
  return out;
}

/// The knobs of `object` at `point` over `base`, or an error message when it does not accept them.
std::pair<pr::MarchKnobs, std::string> knobs_at(const Object& object, const Point& point, pr::MarchKnobs base,
                                                float pixel_angle) {
  try {
    for (const auto& [name, value] : point.knobs) pr::set_knob(base, name, value);
    if (point.sample) sample_settings(base, object.caps->kind, pixel_angle);
    pr::validate(base, *object.caps, object.name);
    return {base, {}};
  } catch (const pr::UsageError& e) {
    return {base, e.what()};
  }
}

std::pair<unsigned, unsigned> parse_pair(const std::string& text, char by, const char* option, const char* example) {
  unsigned a = 0, b = 0;
  char sep = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%u%c%u%c", &a, &sep, &b, &extra) != 3 || sep != by) {
    throw BadInput(std::string(option) + " '" + text + "' is not " + example);
  }
  return {a, b};
}

proceduray::vk::DevicePreference device_of(const std::string& name) {
  if (name == "cpu") return proceduray::vk::DevicePreference::cpu;
  if (name == "gpu") return proceduray::vk::DevicePreference::gpu;
  return proceduray::vk::DevicePreference::automatic;
}

/// What one render of a view gives: the per-object metrics and evaluations, and the time.
struct ObjectResult {
  acc::Metrics metrics;
  double evals = 0.0;
};

/// The measuring renderer reads each point's knobs per ray (the general variant: no pipeline per
/// point); the timing one compiles them in (specialized, as a user's frame runs), one pipeline per
/// point, built before the point's warm-up frames.
pr::vk::RendererOptions general(pr::vk::RendererOptions o) {
  o.specialize_fields = false;
  return o;
}

/// One scene view: a measuring renderer (outputs), a timing renderer (none), its truth.
template <class Scene, class Constants, class Truth>
struct View {
  Scene measured_scene, timed_scene;
  pr::vk::Renderer measured, timed;
  Constants base;
  Truth truth;
  unsigned width, height;
};

template <class Slot, class Constants>
double time_frames(pr::vk::Renderer& r, pr::UniformSlot<Slot> slot, const Constants& c, const Options& o,
                   unsigned w, unsigned h) {
  examples::set_constants(r, slot, c);
  for (unsigned i = 0; i < o.warmup; ++i) r.render(w, h, false);
  std::vector<double> ms;
  for (unsigned i = 0; i < o.frames; ++i) ms.push_back(r.render(w, h, false).trace_ms);
  return examples::median(ms);
}

/// Renders `c` with outputs and measures `ids` against the truth.
template <class Slot, class Constants, class Truth, class Seen, class Measure>
std::map<std::uint32_t, ObjectResult> measure(pr::vk::Renderer& r, pr::UniformSlot<Slot> slot, const Constants& c,
                                              const Truth& truth, unsigned w, unsigned h,
                                              const std::vector<std::uint32_t>& ids, Seen seen_of, Measure measure_of) {
  examples::set_constants(r, slot, c);
  const pr::vk::Frame f = r.render(w, h);
  const std::vector<acc::Sample> samples =
      acc::samples_from(std::size_t{w} * h, f.outputs.t, f.outputs.normal, f.outputs.steps, f.outputs.flags);
  const auto seen = seen_of(r.plan(), f.outputs.ids);
  std::map<std::uint32_t, ObjectResult> out;
  for (std::uint32_t id : ids) {
    ObjectResult& o = out[id];
    o.metrics = measure_of(truth, samples, seen, id);
    std::span<const std::uint32_t> weights;  // a stratified reference's (paper --stride); none: every pixel
    if constexpr (requires { truth.weights; }) weights = truth.weights;
    o.evals = examples::mean_steps(std::span(truth.objects), std::span<const acc::Sample>(samples), std::span(seen),
                                   static_cast<std::remove_cvref_t<decltype(seen[0])>>(id), weights);
  }
  return out;
}

struct Progress {
  std::size_t done = 0, total = 0;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  void tick(const std::string& what) {
    ++done;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double left = done ? s / double(done) * double(total - done) : 0.0;
    std::fprintf(stderr, "\rsweep: %zu/%zu  %.0f s, ~%.0f s left  %-60.60s", done, total, s, left, what.c_str());
    if (done == total) std::fputc('\n', stderr);
    std::fflush(stderr);
  }
};

/// Writes the rows of one object at one point.
struct CsvOut {
  std::ofstream file;
  bool header = false;
  void rows(const std::vector<acc::Label>& labels, const acc::Metrics& m) {
    if (!header) acc::write_csv_header(file, labels);
    header = true;
    acc::write_csv_rows(file, m, labels);
  }
};

std::vector<acc::Label> labels(const Options& o, const std::string& device, unsigned w, unsigned h, std::size_t index,
                               const Point& p, const Object& object, const pr::MarchKnobs& k, double ms, double evals) {
  std::vector<acc::Label> out{{"scene", o.scene + (o.alone ? " alone" : "")},
                              {"device", device},
                              {"width", std::to_string(w)},
                              {"height", std::to_string(h)},
                              {"point", std::to_string(index)},
                              {"label", p.label},
                              {"object", object.name},
                              {"kind", std::string(object.caps->kind)}};
  for (auto& [name, value] : pr::knob_values(k)) out.push_back({name, value});
  out.push_back({"trace_ms", std::to_string(ms)});
  out.push_back({"object_evals", std::to_string(evals)});
  return out;
}

/// The points of this shard, each checked: names before any rendering (an unknown knob or value is
/// refused with the valid ones), and a point of the user's grid that no selected object accepts
/// is a mistake (0 steps, a negative threshold), not a skip; a preset's points are for kinds the
/// selection may not hold.
std::vector<std::pair<std::size_t, Point>> shard_points(const Options& o, const std::vector<Point>& all,
                                                        const std::vector<Object>& objects, const Assignment& fixed,
                                                        unsigned shard, unsigned shards) {
  for (const Point& p : all) {
    pr::MarchKnobs scratch = pr::march_base_knobs;
    for (const auto& [name, value] : p.knobs) pr::set_knob(scratch, name, value);
  }
  for (const auto& [name, value] : fixed) {
    pr::MarchKnobs scratch = pr::march_base_knobs;
    pr::set_knob(scratch, name, value);
  }
  std::vector<std::pair<std::size_t, Point>> kept;
  const std::size_t begin = all.size() * (shard - 1) / shards, end = all.size() * shard / shards;  // contiguous blocks
  for (std::size_t index = begin; index < end; ++index) {
    const Point& p = all[index];
    std::string first_error;
    bool any = false;
    for (const Object& obj : objects) {
      pr::MarchKnobs base = obj.caps->defaults;
      for (const auto& [name, value] : fixed) pr::set_knob(base, name, value);
      const auto [k, error] = knobs_at(obj, p, base, 1e-3f);
      any = any || error.empty();
      if (first_error.empty()) first_error = error;
    }
    if (!any && o.preset.empty()) {
      throw BadInput("point " + std::to_string(index) + " (" + p.label + ") fits no selected object: " + first_error);
    }
    if (any) kept.push_back({index, p});
  }
  return kept;
}

/// What every view of a sweep shares: the options, the device, the points and how a result is reported.
struct Sweep {
  const Options& o;
  pr::vk::Context& ctx;
  std::uint32_t width, height;
  const Assignment& fixed;
  const std::vector<std::pair<std::size_t, Point>>& points;
  std::function<void(std::size_t, const Point&, const Object&, const pr::MarchKnobs&, double, const ObjectResult&)> report;
  Progress progress;

  /// Constants `base` with point p's knobs for each of `objects` that takes them: the ids and knobs taken.
  template <class Constants>
  std::vector<std::pair<const Object*, pr::MarchKnobs>> apply(Constants& c, const std::vector<Object>& objects,
                                                              const Point& p, std::vector<std::uint32_t>& ids) const {
    std::vector<std::pair<const Object*, pr::MarchKnobs>> taken;
    for (const Object& obj : objects) {
      // A preset varies from a fixed base (march/primitives.hpp), so the table it writes does not
      // depend on the defaults that are picked from it; --vary varies the scene's own knobs.
      pr::MarchKnobs k = o.preset.empty() ? c.knobs[obj.id] : pr::preset_base(*obj.caps);
      for (const auto& [name, value] : fixed) pr::set_knob(k, name, value);
      const auto [knobs, error] = knobs_at(obj, p, k, c.camera.pixel_angle);
      if (!error.empty()) continue;
      c.knobs[obj.id] = knobs;
      ids.push_back(obj.id);
      taken.emplace_back(&obj, knobs);
    }
    return taken;
  }
};

void sweep_paper(Sweep& sw, const std::vector<Object>& objects) {
  // The scene may stand far from (0, 0, 0); its truth is the scene at 0: a translation moves no t.
  const paper::World world = sw.o.where.world();
  const paper::PaperScene measured_scene(paper::accuracy_outputs, paper::Tracing::recursive, paper::max_depth_limit, world);
  const paper::PaperScene timed_scene({}, paper::Tracing::recursive, paper::max_depth_limit, world);
  pr::vk::Renderer measured(sw.ctx, measured_scene, general(measured_scene.renderer_options()));
  pr::vk::Renderer timed(sw.ctx, timed_scene, timed_scene.renderer_options());
  paper::Frame base = paper::default_frame(sw.width, sw.height, sw.o.time);
  base.flags = 0;
  std::fprintf(stderr, "sweep: reference of the paper scene (spacing %g footprints) ...\n", sw.o.spacing);
  const paper::ReferenceImage truth =
      sw.o.stride > 1 ? paper::stratified_reference_image(base, sw.width, sw.height, sw.o.stride, {.spacing = sw.o.spacing})
                      : paper::reference_image(base, sw.width, sw.height, {.spacing = sw.o.spacing});
  sw.progress.total = sw.points.size();
  for (const auto& [index, p] : sw.points) {
    paper::Frame c = base;
    std::vector<std::uint32_t> ids;
    const auto taken = sw.apply(c, objects, p, ids);
    world.place(c);
    const double ms = time_frames(timed, paper::constants_slot, c, sw.o, sw.width, sw.height);
    const auto results = measure(
        measured, paper::constants_slot, c, truth, sw.width, sw.height, ids,
        [](const pr::Plan& plan, std::span<const std::uint32_t> raw) { return paper::device_objects(plan, raw); },
        [](const paper::ReferenceImage& t, std::span<const acc::Sample> s, const std::vector<paper::ObjectId>& seen,
           std::uint32_t id) { return paper::measure_object(t, s, seen, static_cast<paper::ObjectId>(id)); });
    for (const auto& [obj, k] : taken) sw.report(index, p, *obj, k, ms, results.at(obj->id));
    sw.progress.tick(p.label);
  }
}

void sweep_d3d12(Sweep& sw, const std::vector<Object>& objects) {
  // One view per selected object (--alone) or one of the whole sample scene.
  struct D3d12View {
    std::vector<Object> objects;
    d3d12::SceneConstants base;
    d3d12::Layout layout;
  };
  std::vector<D3d12View> views;
  if (sw.o.alone) {
    for (const Object& obj : objects) {
      const auto kind = static_cast<d3d12::PrimitiveKind>(obj.id - 2u);
      views.push_back({{obj}, d3d12::default_constants(d3d12::isolated_camera(kind, sw.width, sw.height), sw.o.time),
                       d3d12::Layout::isolated});
    }
  } else {
    views.push_back({objects, d3d12::default_constants(d3d12::sample_camera(sw.width, sw.height), sw.o.time),
                     d3d12::Layout::sample});
  }
  sw.progress.total = sw.points.size() * views.size();
  for (const D3d12View& view : views) {
    const d3d12::D3d12Scene measured_scene(d3d12::default_primitives(), view.layout, d3d12::accuracy_outputs);
    const d3d12::D3d12Scene timed_scene(d3d12::default_primitives(), view.layout);
    pr::vk::Renderer measured(sw.ctx, measured_scene, general(d3d12::renderer_options()));
    pr::vk::Renderer timed(sw.ctx, timed_scene, d3d12::renderer_options());
    d3d12::SceneConstants base = view.base;
    base.flags = 0;
    const std::array<d3d12::Primitive, d3d12::primitive_count> prims = d3d12::default_primitives();
    const d3d12::ReferenceImage truth = d3d12::reference_image(base, prims, view.layout, sw.width, sw.height);
    for (const auto& [index, p] : sw.points) {
      d3d12::SceneConstants c = base;
      std::vector<std::uint32_t> ids;
      const auto taken = sw.apply(c, view.objects, p, ids);
      if (!ids.empty()) {
        const double ms = time_frames(timed, d3d12::constants_slot, c, sw.o, sw.width, sw.height);
        const auto results = measure(
            measured, d3d12::constants_slot, c, truth, sw.width, sw.height, ids,
            [](const pr::Plan& plan, std::span<const std::uint32_t> raw) { return d3d12::device_objects(plan, raw); },
            [](const d3d12::ReferenceImage& t, std::span<const acc::Sample> s, const std::vector<std::uint32_t>& seen,
               std::uint32_t id) { return d3d12::measure_object(t, s, seen, id); });
        for (const auto& [obj, k] : taken) sw.report(index, p, *obj, k, ms, results.at(obj->id));
      }
      sw.progress.tick(view.objects.size() == 1 ? view.objects[0].name + ": " + p.label : p.label);
    }
  }
}

int run(const Options& o) {
  // Named, not a structured binding: clang 14 cannot capture one in the lambdas below.
  const auto size = parse_pair(o.size, 'x', "--size", "WxH with positive numbers, e.g. 256x256");
  const auto width = size.first, height = size.second;
  if (width == 0 || height == 0) throw BadInput("--size '" + o.size + "' is not WxH with positive numbers, e.g. 256x256");
  const auto [shard, shards] = parse_pair(o.shard, '/', "--shard", "i/n with 1 <= i <= n, e.g. 1/4");
  if (shards == 0 || shard == 0 || shard > shards) {
    throw BadInput("--shard '" + o.shard + "' is not i/n with 1 <= i <= n, e.g. 1/4");
  }
  if (o.alone && o.scene != "d3d12") throw BadInput("--alone renders the D3D12 primitives one by one; use --scene d3d12");
  if (o.where.given() && o.scene != "paper") {
    throw BadInput("--origin places the paper scene only, not '" + o.scene + "'; drop it or pass --scene paper");
  }
  if (!o.preset.empty() && !o.vary.empty()) throw BadInput("give --preset or --vary, not both");
  const std::vector<Object> objects = selected(scene_objects(o.scene), o.objects);
  const std::vector<Point> all = o.preset == "methods" ? methods_preset() : grid(o.vary);
  Assignment fixed;
  for (const std::string& s : o.set) fixed.push_back(split_assignment(s, "--set"));
  const std::vector<std::pair<std::size_t, Point>> points = shard_points(o, all, objects, fixed, shard, shards);
  // The calibration table: loaded first with --append (a foreign or old one is refused here,
  // before any rendering), written at the end.
  std::vector<pr::CalibrationRow> table;
  if (!o.calibration.empty() && o.append && std::filesystem::exists(o.calibration)) {
    table = pr::Calibration::load(o.calibration).rows();
  }
  CsvOut csv;
  if (!o.csv.empty()) {
    csv.file.open(o.csv, std::ios::trunc);
    if (!csv.file) throw BadInput("cannot write '" + o.csv + "'; give a writable --csv path");
  }
  pr::vk::Context ctx({.device = device_of(o.device), .validation = o.validation});
  std::printf("device: %s; %zu points of %zu (shard %u/%u), %zu objects, %ux%u, median of %u frames after %u\n",
              ctx.name().c_str(), points.size(), all.size(), shard, shards, objects.size(), width, height, o.frames,
              o.warmup);
  std::printf("%-16s %-58s %9s %9s %9s %9s %8s\n", "object", "point", "ms", "evals", "depth med", "depth p99", "sil fh%");
  Sweep sweep{o, ctx, width, height, fixed, points, {}, {}};
  sweep.report = [&](std::size_t index, const Point& p, const Object& obj, const pr::MarchKnobs& k, double ms,
                     const ObjectResult& r) {
    const acc::ClassStats& a = r.metrics.all;
    std::printf("%-16s %-58.58s %9.3f %9.2f %9.3g %9.3g %8.2f\n", obj.name.c_str(), p.label.c_str(), ms, r.evals,
                a.depth.median, a.depth.p99, 100.0 * r.metrics[acc::PixelClass::silhouette_1px].false_hit_rate());
    if (csv.file.is_open()) csv.rows(labels(o, ctx.name(), width, height, index, p, obj, k, ms, r.evals), r.metrics);
    // A calibration row needs hits to have a depth error; a rate of no rays is no error.
    if (!o.calibration.empty() && a.both_hit > 0 && std::isfinite(a.depth.median)) {
      auto rate = [](double v) { return std::isfinite(v) ? v : 0.0; };
      table.push_back({obj.name, std::string(obj.caps->kind), k, r.evals, a.depth.median, a.depth.p99,
                       rate(r.metrics[acc::PixelClass::silhouette_1px].false_hit_rate()), rate(a.missed_hits_rate()),
                       rate(a.normal_degrees.p95), rate(a.wrong_surface_rate())});
    }
  };
  if (o.scene == "paper") sweep_paper(sweep, objects);
  else sweep_d3d12(sweep, objects);
  if (!o.csv.empty()) std::printf("wrote %s\n", o.csv.c_str());
  if (!o.calibration.empty()) {
    std::ofstream out(o.calibration, std::ios::trunc);
    if (!out) throw BadInput("cannot write '" + o.calibration + "'; give a writable --calibration path");
    pr::Calibration(ctx.name(), std::to_string(width) + "x" + std::to_string(height), std::move(table)).write(out);
    std::printf("wrote calibration %s\n", o.calibration.c_str());
  }
  const bool clean = ctx.validation_messages().empty();
  if (!clean) std::fprintf(stderr, "proceduray_sweep: validation messages were reported\n");
  return clean ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  // A user's field (--sdf file.glsl --aabb ... --lipschitz ... --csv table.csv): vk::calibrate.
  if (field_tool::wants_field(argc, argv)) return field_tool::calibrate_main(argc, argv, "proceduray_sweep");
  Options o;
  CLI::App app{"Sweeps march knobs over a scene: GPU time, evaluations per ray and accuracy against a ground truth"};
  app.add_option("--scene", o.scene, "paper (the report's) or d3d12 (the D3D12 sample's)")
      ->check(CLI::IsMember({"paper", "d3d12"}))->capture_default_str();
  app.add_flag("--alone", o.alone, "d3d12: render each selected primitive by itself with its own camera (a time per primitive)");
  app.add_option("--size", o.size, "image size WxH")->capture_default_str();
  app.add_option("--device", o.device, "cpu (lavapipe), gpu or auto")->check(CLI::IsMember({"cpu", "gpu", "auto"}))
      ->capture_default_str();
  app.add_option("--objects", o.objects, "marched objects to sweep (default: all of the scene's)")->delimiter(',');
  app.add_option("--vary", o.vary, "an axis of the grid: knob=value,value,... (repeatable; the grid is their product)");
  app.add_option("--set", o.set, "a knob for every point: knob=value (repeatable)");
  app.add_option("--preset", o.preset, "a shipped grid instead of --vary: methods")->check(CLI::IsMember({"methods"}));
  app.add_option("--shard", o.shard, "i/n: the i-th of n contiguous blocks of points (1 <= i <= n)")->capture_default_str();
  app.add_option("--csv", o.csv, "CSV to write: a header, then per point and object a row per pixel class");
  app.add_option("--calibration", o.calibration, "calibration table to write: per object and point its knobs, "
                 "evaluations and errors (march/calibration.hpp)");
  app.add_flag("--append", o.append, "add to the --calibration table instead of replacing it (same library version)");
  app.add_option("--frames", o.frames, "timed frames per point (median)")->check(CLI::Range(1u, 1000u))->capture_default_str();
  app.add_option("--warmup", o.warmup, "untimed frames before them")->check(CLI::Range(0u, 100u))->capture_default_str();
  app.add_option("--time", o.time, "scene time in seconds")->capture_default_str();
  app.add_option("--stride", o.stride, "paper scene: the truth of every pixel near a silhouette and one in this many "
                 "elsewhere (accuracy/stratified.hpp); 1: every pixel")->check(CLI::Range(1u, 1024u))->capture_default_str();
  app.add_option("--spacing", o.spacing, "paper reference sample spacing in footprints")->check(CLI::Range(1e-6, 1.0))
      ->capture_default_str();
  app.add_flag("--validation", o.validation, "enable the Khronos validation layer");
  paper::add_world_options(app, o.where);
  CLI11_PARSE(app, argc, argv);
  try {
    return run(o);
  } catch (const BadInput& e) {
    std::fprintf(stderr, "proceduray_sweep: %s\n", e.what());
    return 2;
  } catch (const pr::UsageError& e) {
    std::fprintf(stderr, "proceduray_sweep: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "proceduray_sweep: %s\n", e.what());
    return 1;
  }
}
