// What the measuring tools share for a user's distance field (proceduray-field, and
// proceduray_accuracy / proceduray_sweep given --sdf): the options, the field's C++ truth compiled
// from its GLSL file by the system compiler into a shared library, the meter, and the measure,
// calibrate and merge commands over vk::FieldMeter and vk::calibrate.
//
//   field_tool::FieldOptions o;                    // --sdf, --aabb, --lipschitz, --size, ...
//   field_tool::add_field_options(app, o);         // CLI11
//   o.tool = "proceduray_accuracy";                // names the tool in errors
//   return field_tool::measure(o, {"method=relaxed"}, "out.csv");   // the accuracy table; 1 on a validation message
//   return field_tool::calibrate(o, "1/3", "part1.csv");           // the preset's first third, a calibration table
#pragma once

#include <proceduray/accuracy/report.hpp>
#include <proceduray/proceduray.hpp>

#include <CLI/CLI.hpp>

#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace field_tool {

namespace pr = proceduray;
namespace fs = std::filesystem;

struct BadInput : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Prints `e` as `tool: message` (once: a library error may already start with the tool's name).
inline void report(const std::string& tool, const std::exception& e) {
  const std::string m = e.what();
  std::fprintf(stderr, "%s\n", m.starts_with(tool + ":") ? m.c_str() : (tool + ": " + m).c_str());
}

/// What every subcommand that renders takes.
struct FieldOptions {
  std::string sdf, function, id, aabb = "-1,-1,-1,1,1,1", size = "320x240", eye = "0,0.6,3.2", target = "0,0,0";
  float lipschitz = 0.0f, fov = 45.0f;
  bool exact = false, validation = false;
  std::uint32_t iterations = 0, stride = 1;
  std::string device = "auto", cache;
  std::string tool = "proceduray-field";  ///< the tool's name, in errors
};

inline std::vector<float> numbers(const std::string& text, std::size_t count, const char* option) {
  std::vector<float> out;
  std::stringstream s(text);
  for (std::string part; std::getline(s, part, ',');) {
    char* end = nullptr;
    const float v = std::strtof(part.c_str(), &end);
    if (part.empty() || *end != '\0') break;
    out.push_back(v);
  }
  if (out.size() != count) {
    throw BadInput(std::string(option) + " '" + text + "' is not " + std::to_string(count) + " numbers separated by commas");
  }
  return out;
}

/// A directory holding `probe`: $env, then beside the executable (an installed tool), then the build's.
inline fs::path locate(const char* env, const fs::path& installed, const fs::path& built, const fs::path& probe) {
  if (const char* e = std::getenv(env); e != nullptr && *e != '\0') return e;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec && fs::exists(exe.parent_path() / installed / probe)) return fs::weakly_canonical(exe.parent_path() / installed);
  return built;
}

/// The library's headers the field's C++ truth compiles against.
inline fs::path headers_dir() {
  return locate("PROCEDURAY_INCLUDE_DIR", "../include", PROCEDURAY_TOOL_INCLUDE_DIR, "proceduray/shader/glsl_cpp.hpp");
}
/// The library's shaders (marching/, measure/): installed beside the tool, else the build's.
inline fs::path shaders_dir() {
  return locate("PROCEDURAY_SHADER_DIR", "../share/proceduray/shaders", pr::vk::library_shader_dir(),
                "marching/field.glsl");
}

using Distance = double (*)(double, double, double, std::uint32_t);

/// Compiles the field's GLSL as C++ into a shared library (kept in the cache by the file's
/// text) and returns its distance; a file outside the portable subset names its first error line.
inline Distance load_truth(const pr::DistanceField& f, const fs::path& glsl, const fs::path& cache) {
  std::ifstream in(glsl);
  std::stringstream text;
  text << in.rdbuf();
  const fs::path include = headers_dir(), shaders = shaders_dir();
  const char* cxx = std::getenv("CXX") != nullptr ? std::getenv("CXX") : "c++";
  const char* flags = std::getenv("CXXFLAGS") != nullptr ? std::getenv("CXXFLAGS") : "";  // e.g. -I for GLM elsewhere
  const std::string key =
      std::to_string(pr::vk::fnv1a(text.str() + pr::field_function(f) + cxx + flags + glsl.string()));
  const fs::path dir = cache / "field-cpp", so = dir / (f.id + "-" + key + ".so"), cpp = dir / (f.id + "-" + key + ".cpp");
  fs::create_directories(dir);
  if (!fs::exists(so)) {
    std::ofstream src(cpp);
    src << "#include <proceduray/shader/glsl_cpp.hpp>\n#include <cstdint>\nnamespace user {\n"
        << "using namespace proceduray::glsl_cpp;\ntemplate <class T> struct field {\n  PROCEDURAY_GLSL_CPP_SCALAR(T)\n"
        << "#include \"" << fs::absolute(glsl).string() << "\"\n};\n}  // namespace user\n"
        << "extern \"C\" double proceduray_field_distance(double x, double y, double z, std::uint32_t iterations) {\n"
        << "  (void)iterations;\n  return user::field<double>::" << pr::field_function(f) << "(glm::dvec3(x, y, z)"
        << (f.iterations > 0 ? ", iterations" : "") << ");\n}\n";
    src.close();
    const fs::path log = dir / (f.id + "-" + key + ".log");
    const std::string command = std::string(cxx) + " -std=c++20 -O2 -shared -fPIC " + flags + " -I'" +
                                include.string() + "' -I'" +
                                shaders.string() + "' '" + cpp.string() + "' -o '" + so.string() + "' 2> '" +
                                log.string() + "'";
    if (std::system(command.c_str()) != 0) {
      std::ifstream errors(log);
      std::string line, first;
      while (std::getline(errors, line)) {
        if (line.find("error") != std::string::npos) {
          first = line;
          break;
        }
      }
      // Not the field's fault: the shim's own dependency is missing (seen on a GPU machine without it).
      if (first.find("glm/") != std::string::npos) {
        throw BadInput("the C++ compiler '" + std::string(cxx) + "' cannot find GLM's headers, which " +
                       "shader/glsl_cpp.hpp needs to compile " + glsl.string() + " as C++: install them (Debian: " +
                       "apt-get install libglm-dev) or give their folder in CXXFLAGS (-I/path/holding/glm); the log: " +
                       log.string());
      }
      throw BadInput(glsl.string() + " does not compile as C++ (the portable subset of shader/glsl_cpp.hpp: pr_real, "
                     "PR(...), no swizzles): " + first + "; the whole log: " + log.string());
    }
  }
  void* lib = dlopen(so.c_str(), RTLD_NOW | RTLD_LOCAL);
  void* fn = lib != nullptr ? dlsym(lib, "proceduray_field_distance") : nullptr;
  if (fn == nullptr) throw BadInput("cannot load " + so.string() + ": " + dlerror() + "; delete it and run again");
  return reinterpret_cast<Distance>(fn);
}

/// The field, the meter and the view the options describe.
struct Setup {
  pr::DistanceField field;
  std::unique_ptr<pr::vk::Context> ctx;
  std::unique_ptr<pr::vk::FieldMeter> meter;
  pr::vk::MeasureView view;
  Distance distance = nullptr;
  fs::path cache;
  auto truth() const {
    return [d = distance, n = field.iterations](glm::dvec3 p) { return d(p.x, p.y, p.z, n); };
  }
};

inline Setup setup(const FieldOptions& o) {
  Setup s;
  const fs::path glsl = o.sdf;
  if (!fs::is_regular_file(glsl)) throw BadInput("--sdf '" + o.sdf + "' is not a file; give the field's GLSL file");
  const std::vector<float> box = numbers(o.aabb, 6, "--aabb");
  s.field = {.id = o.id.empty() ? glsl.stem().string() : o.id, .glsl = glsl.filename().string(),
             .function = o.function, .aabb = {{box[0], box[1], box[2]}, {box[3], box[4], box[5]}},
             .lipschitz = o.lipschitz, .exact = o.exact, .iterations = o.iterations};
  try {
    pr::validate(s.field, o.tool);  // before any device or compiler work
  } catch (const pr::UsageError& e) {
    throw BadInput(std::string(e.what()) + " (the options: .aabb is --aabb, .lipschitz --lipschitz, .exact --exact, "
                   ".iterations --iterations, .function --function)");
  }
  std::uint32_t w = 0, h = 0;
  if (std::sscanf(o.size.c_str(), "%ux%u", &w, &h) != 2) throw BadInput("--size '" + o.size + "' is not WxH");
  const std::vector<float> eye = numbers(o.eye, 3, "--eye"), target = numbers(o.target, 3, "--target");
  s.view = {pr::look_at({eye[0], eye[1], eye[2]}, {target[0], target[1], target[2]}, o.fov, w, h), w, h};
  s.cache = o.cache.empty() ? pr::vk::default_cache_dir() : fs::path(o.cache);
  s.distance = load_truth(s.field, glsl, s.cache);
  const auto device = o.device == "cpu" ? pr::vk::DevicePreference::cpu
                      : o.device == "gpu" ? pr::vk::DevicePreference::gpu : pr::vk::DevicePreference::automatic;
  s.ctx = std::make_unique<pr::vk::Context>(pr::vk::ContextOptions{.device = device, .validation = o.validation});
  s.meter = std::make_unique<pr::vk::FieldMeter>(*s.ctx, s.field,
      pr::vk::MeasureOptions{.shader_dirs = {fs::absolute(glsl).parent_path(), shaders_dir()}, .cache_dir = s.cache,
                             .interior_stride = o.stride});
  return s;
}

inline void add_field_options(CLI::App& app, FieldOptions& o) {
  app.add_option("--sdf", o.sdf, "the field's GLSL file (pr_real <name>_distance(pr_real3 p))")->required();
  app.add_option("--function", o.function, "its distance function (default: <file stem>_distance)");
  app.add_option("--id", o.id, "the field's name in tables (default: the file's stem)");
  app.add_option("--aabb", o.aabb, "local box: minx,miny,minz,maxx,maxy,maxz")->capture_default_str();
  app.add_option("--lipschitz", o.lipschitz, "the bound L (required unless --exact)");
  app.add_flag("--exact", o.exact, "an exact distance (L = 1)");
  app.add_option("--iterations", o.iterations, "a fractal: f(p, iterations), the default count");
  app.add_option("--size", o.size, "the size you render at, WxH")->capture_default_str();
  app.add_option("--eye", o.eye, "camera position x,y,z")->capture_default_str();
  app.add_option("--target", o.target, "camera target x,y,z")->capture_default_str();
  app.add_option("--fov", o.fov, "vertical field of view, degrees")->capture_default_str();
  app.add_option("--device", o.device, "cpu (lavapipe), gpu or auto")->check(CLI::IsMember({"cpu", "gpu", "auto"}));
  app.add_flag("--validation", o.validation, "the Khronos validation layer; a message fails the run");
  app.add_option("--cache", o.cache, "cache folder (truth, tables, the compiled field; default the library's)");
  app.add_option("--stride", o.stride, "the truth of one pixel in this many outside the silhouettes (1: all; "
                 "vk/measure.hpp's interior_stride)")->capture_default_str();
}

inline int measure(const FieldOptions& o, const std::vector<std::string>& knobs, const std::string& csv) {
  Setup s = setup(o);
  pr::MarchKnobs k = s.meter->capabilities().defaults;
  for (const std::string& kv : knobs) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos) throw BadInput("--knob '" + kv + "' is not name=value");
    pr::set_knob(k, kv.substr(0, eq), kv.substr(eq + 1));
  }
  const pr::vk::Measurement m = s.meter->measure(s.truth(), k, s.view);
  pr::accuracy::write_table(std::cout, m.metrics);
  std::printf("wrong_surface %llu (%.4g%% of the truth's hits)\nevaluations per ray %.3f (%.3f per ray in the box)\n"
              "gpu %.3f ms, truth %.0f ms%s\n", static_cast<unsigned long long>(m.wrong_surface),
              100.0 * m.wrong_surface_rate, m.evaluations_per_ray, m.evaluations_per_box_ray, m.gpu_ms, m.truth_ms,
              m.truth_cached ? " (cached)" : "");
  const pr::accuracy::EvaluationSplit& e = m.evaluation_split;
  std::printf("evaluations per ray by class: hits %.2f (%.0f%% of all), near misses %.2f (%.0f%%), far misses %.2f "
              "(%.0f%%)\n", e.hit.per_ray(), 100.0 * e.share(e.hit), e.near_miss.per_ray(), 100.0 * e.share(e.near_miss),
              e.far_miss.per_ray(), 100.0 * e.share(e.far_miss));
  if (o.stride > 1) {
    std::printf("stratified truth (stride %u): false misses %.4g%% (95%% bound %.4g%%), wrong surface %.4g%% "
                "(95%% bound %.4g%%)\n", o.stride, 100.0 * m.confidence.false_miss_rate,
                100.0 * m.confidence.false_miss_rate_95, 100.0 * m.confidence.wrong_surface_rate,
                100.0 * m.confidence.wrong_surface_rate_95);
  }
  if (!csv.empty()) {
    std::ofstream out(csv);
    std::vector<pr::accuracy::Label> labels{{"field", s.field.id}, {"size", o.size}};
    for (const auto& [name, value] : pr::knob_values(k)) labels.push_back({name, value});
    labels.push_back({"evals_per_box_ray", std::to_string(m.evaluations_per_box_ray)});
    labels.push_back({"evals_per_hit", std::to_string(m.evaluation_split.hit.per_ray())});
    labels.push_back({"evals_per_near_miss", std::to_string(m.evaluation_split.near_miss.per_ray())});
    labels.push_back({"evals_per_far_miss", std::to_string(m.evaluation_split.far_miss.per_ray())});
    labels.push_back({"gpu_ms", std::to_string(m.gpu_ms)});
    pr::accuracy::write_csv(out, m.metrics, labels);
    std::printf("wrote %s\n", csv.c_str());
  }
  return s.ctx->validation_messages().empty() ? 0 : 1;
}

inline int calibrate(const FieldOptions& o, const std::string& shard, const std::string& out) {
  Setup s = setup(o);
  std::uint32_t i = 1, n = 1;
  if (!shard.empty() && (std::sscanf(shard.c_str(), "%u/%u", &i, &n) != 2 || n == 0 || i == 0 || i > n)) {
    throw BadInput("--shard '" + shard + "' is not i/n with 1 <= i <= n");
  }
  const std::vector<pr::MarchKnobs> all = pr::vk::field_preset(s.meter->capabilities());
  const std::size_t begin = all.size() * (i - 1) / n, end = all.size() * i / n;  // contiguous blocks
  const std::vector<pr::MarchKnobs> part(all.begin() + static_cast<std::ptrdiff_t>(begin),
                                         all.begin() + static_cast<std::ptrdiff_t>(end));
  std::fprintf(stderr, "shard %u/%u: settings %zu..%zu of %zu\n", i, n, begin + 1, end, all.size());
  const pr::vk::Calibrated c = pr::vk::calibrate(*s.meter, s.truth(),
      {.view = s.view, .settings = part, .cache_dir = s.cache,
       .progress = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); }});
  std::ofstream file(out);
  c.table.write(file);
  if (!file) throw BadInput("cannot write '" + out + "'; give a writable --out path");
  std::printf("wrote %s (%zu rows%s)\n", out.c_str(), c.table.rows().size(), c.cached ? ", cached" : "");
  return s.ctx->validation_messages().empty() ? 0 : 1;
}

inline int merge(const std::vector<std::string>& parts, const std::string& out) {
  std::vector<pr::CalibrationRow> rows;
  std::string device, size, source;
  for (const std::string& p : parts) {
    const pr::Calibration t = pr::Calibration::load(p);
    if (!device.empty() && (t.device() != device || t.size() != size || t.source() != source)) {
      throw BadInput(p + " was measured on " + t.device() + " at " + t.size() + " for '" + t.source() +
                     "', the first part on " + device + " at " + size + " for '" + source +
                     "'; merge the parts of one calibration");
    }
    device = t.device();
    size = t.size();
    source = t.source();
    rows.insert(rows.end(), t.rows().begin(), t.rows().end());
  }
  std::ofstream file(out);
  pr::Calibration(device, size, std::move(rows), source).write(file);
  if (!file) throw BadInput("cannot write '" + out + "'; give a writable --out path");
  std::printf("wrote %s\n", out.c_str());
  return 0;
}

/// What `command` returns, or 2 after report() when it throws.
template <class Command>
int guarded(const std::string& tool, Command command) {
  try {
    return command();
  } catch (const std::exception& e) {
    report(tool, e);
    return 2;
  }
}

/// True when the command line names a user's field (--sdf): proceduray_accuracy and
/// proceduray_sweep then measure it through measure_main / calibrate_main.
inline bool wants_field(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--sdf" || a.starts_with("--sdf=")) return true;
  }
  return false;
}

/// `tool --sdf ... [--knob k=v ...] [--csv F]`: one setting measured, as proceduray-field measure.
inline int measure_main(int argc, char** argv, const char* tool) {
  FieldOptions o;
  o.tool = tool;
  std::vector<std::string> knobs;
  std::string csv;
  CLI::App app{std::string(tool) + " --sdf: a distance field's errors against its ground truth at one setting"};
  add_field_options(app, o);
  app.add_option("--knob", knobs, "name=value of march/knobs.hpp (repeat it)");
  app.add_option("--csv", csv, "also write the metrics as CSV (accuracy/report.hpp's columns)");
  CLI11_PARSE(app, argc, argv);
  return guarded(tool, [&] { return measure(o, knobs, csv); });
}

/// `tool --sdf ... --csv F [--shard i/n]`: the methods preset as a calibration table, as
/// proceduray-field calibrate (shards merge with proceduray-field merge).
inline int calibrate_main(int argc, char** argv, const char* tool) {
  FieldOptions o;
  o.tool = tool;
  std::string shard, out;
  CLI::App app{std::string(tool) + " --sdf: a distance field's methods and knobs swept into a calibration table"};
  add_field_options(app, o);
  app.add_option("--shard", shard, "i/n: the i-th of n contiguous blocks of settings");
  app.add_option("--csv", out, "the calibration table to write")->required();
  CLI11_PARSE(app, argc, argv);
  return guarded(tool, [&] { return calibrate(o, shard, out); });
}

}  // namespace field_tool
