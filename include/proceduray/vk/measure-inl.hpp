// The bodies of proceduray/vk/measure.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/measure.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>

#include "proceduray/scene/compile.hpp"
#include "proceduray/scene/default_global_signature.hpp"
#include "proceduray/scene/distance_field.hpp"
#include "proceduray/shader/categories.hpp"
#include "proceduray/version.hpp"
#include "proceduray/vk/renderer.hpp"
#include "proceduray/vk/shader_compiler.hpp"
#include "proceduray/vk/spirv_cache.hpp"

namespace proceduray::vk {

template <class T>
void FieldMeter::upload(UniformSlot<T> slot, const T& value) {
  m_renderer->set(slot, value);
}

}  // namespace proceduray::vk

#if PROCEDURAY_BODIES
namespace proceduray::vk {

namespace detail {

/// The measuring scene, whose vocabulary adds the uniforms a field's parameters read to its own.
class MeasureScene : public Scene<MeasureInterface> {
 public:
  explicit MeasureScene(std::vector<const TypeOps*> types) : m_types(std::move(types)) { set_vocabulary(m_types); }

 private:
  std::vector<const TypeOps*> m_types;
};

PROCEDURAY_DECL glm::dvec3 measure_direction(const Camera& c, std::uint32_t x, std::uint32_t y, std::uint32_t width,
                                             std::uint32_t height) {
  const double u = (x + 0.5) / width * 2.0 - 1.0, v = (y + 0.5) / height * 2.0 - 1.0;
  return glm::normalize(glm::dvec3(c.forward) + u * glm::dvec3(c.right) - v * glm::dvec3(c.up));
}

PROCEDURAY_DECL std::uint64_t truth_key(const DistanceField& field, const std::string& glsl_text, const MeasureView& view,
                                        const MeasureOptions& options, std::string_view parameters) {
  std::uint64_t h = fnv1a(proceduray::version);
  if (!parameters.empty()) h = fnv1a(parameters, h);  // the values the field was measured at
  h = fnv1a(glsl_text, h);
  h = fnv1a(field.id + "\n" + field_function(field) + "\n", h);
  const float numbers[] = {field.aabb.min.x, field.aabb.min.y, field.aabb.min.z, field.aabb.max.x,
                           field.aabb.max.y, field.aabb.max.z, field_lipschitz(field),
                           static_cast<float>(field.iterations)};
  h = fnv1a(std::string_view(reinterpret_cast<const char*>(numbers), sizeof numbers), h);
  h = fnv1a(std::string_view(reinterpret_cast<const char*>(&view.camera), sizeof view.camera), h);
  const std::uint64_t size[] = {view.width, view.height, options.interior_stride, options.seed};
  return fnv1a(std::string_view(reinterpret_cast<const char*>(size), sizeof size), h);
}

inline constexpr char truth_magic[16] = "proceduray-tr2\n";
/// One pixel of a truth file.
struct TruthRecord {
  double t;
  double normal[3];
  std::uint32_t outcome;
  std::uint32_t weight;  ///< StratifiedTruth::weight
};

PROCEDURAY_DECL bool read_truth(const std::filesystem::path& file, std::uint64_t key, std::size_t pixels,
                                accuracy::StratifiedTruth& out) {
  std::ifstream in(file, std::ios::binary);
  char magic[sizeof truth_magic];
  std::uint64_t stored_key = 0, count = 0;
  if (!in.read(magic, sizeof magic) || std::memcmp(magic, truth_magic, sizeof magic) != 0) return false;
  if (!in.read(reinterpret_cast<char*>(&stored_key), sizeof stored_key) || stored_key != key) return false;
  if (!in.read(reinterpret_cast<char*>(&count), sizeof count) || count != pixels) return false;
  std::vector<TruthRecord> records(pixels);
  if (!in.read(reinterpret_cast<char*>(records.data()), static_cast<std::streamsize>(pixels * sizeof(TruthRecord)))) {
    return false;
  }
  accuracy::StratifiedTruth t;
  t.pixels.resize(pixels);
  t.weight.resize(pixels);
  for (std::size_t i = 0; i < pixels; ++i) {
    const TruthRecord& r = records[i];
    if (r.outcome > static_cast<std::uint32_t>(accuracy::Outcome::undetermined)) return false;  // not ours
    t.pixels[i] = {static_cast<accuracy::Outcome>(r.outcome), r.t, glm::dvec3(r.normal[0], r.normal[1], r.normal[2])};
    t.weight[i] = r.weight;
    t.stride = std::max(t.stride, r.weight);
    t.band += r.weight == 1;
    t.sampled += r.weight > 1;
  }
  t.traced = t.band + t.sampled;  // the coarse pass's other pixels are not kept apart
  out = std::move(t);
  return true;
}

PROCEDURAY_DECL void write_truth(const std::filesystem::path& file, std::uint64_t key,
                                 const accuracy::StratifiedTruth& truth) {
  std::error_code ec;
  std::filesystem::create_directories(file.parent_path(), ec);
  std::vector<TruthRecord> records(truth.pixels.size());
  for (std::size_t i = 0; i < truth.pixels.size(); ++i) {
    const accuracy::Reference& r = truth.pixels[i];
    records[i] = {r.t, {r.normal.x, r.normal.y, r.normal.z}, static_cast<std::uint32_t>(r.outcome), truth.weight[i]};
  }
  // Written beside and renamed: a reader never sees half a file (a cache is best effort: no throw).
  const std::filesystem::path part = file.string() + ".part";
  {
    std::ofstream out(part, std::ios::binary | std::ios::trunc);
    const std::uint64_t count = truth.pixels.size();
    out.write(truth_magic, sizeof truth_magic);
    out.write(reinterpret_cast<const char*>(&key), sizeof key);
    out.write(reinterpret_cast<const char*>(&count), sizeof count);
    out.write(reinterpret_cast<const char*>(records.data()), static_cast<std::streamsize>(records.size() * sizeof(TruthRecord)));
    if (!out) return;
  }
  std::filesystem::rename(part, file, ec);
}

PROCEDURAY_DECL void check_view(const MeasureView& view, std::string_view op) {
  if (view.width == 0 || view.height == 0 || view.width > 16384 || view.height > 16384) {
    throw UsageError(std::string(op) + ": view size " + std::to_string(view.width) + "x" + std::to_string(view.height) +
                     " is out of range; give 1 to 16384 pixels each way, the size you render at");
  }
  if (!(view.camera.pixel_angle > 0.0f) || !std::isfinite(view.camera.pixel_angle)) {
    throw UsageError(std::string(op) + ": the view's camera has pixel angle " + std::to_string(view.camera.pixel_angle) +
                     "; make it with look_at(eye, target, fov, width, height) for this view's size");
  }
}

}  // namespace detail

PROCEDURAY_DECL FieldMeter::FieldMeter(const Context& ctx, DistanceField field, MeasureOptions options)
    : m_field(std::move(field)), m_options(std::move(options)) {
  validate(m_field, "FieldMeter");
  std::vector<const TypeOps*> types(detail::MeasureInterface::types.begin(), detail::MeasureInterface::types.end());
  std::vector<proceduray::Binding> bindings{detail::measure_constants};
  for (const FieldParameter& p : m_field.parameters) {
    if (p.record) {
      throw UsageError("FieldMeter: distance field \"" + m_field.id + "\" takes " + p.block + "." + p.member +
                       " from its hit records, which the measuring scene does not have; measure a function with that "
                       "value fixed (a wrapper in the GLSL file), or pass it from a uniform");
    }
    if (p.block == detail::measure_constants.name) {
      throw UsageError("FieldMeter: distance field \"" + m_field.id + "\" reads the uniform \"" + p.block +
                       "\", the measuring scene's own name; rename the uniform");
    }
    const auto same = [&](const detail::ParameterBlock& b) { return b.name == p.block; };
    if (std::find_if(m_blocks.begin(), m_blocks.end(), same) != m_blocks.end()) continue;
    const auto binding = detail::measure_parameter_binding + static_cast<std::uint32_t>(m_blocks.size());
    m_blocks.push_back({p.block, p.block_type, binding, {}});
    bindings.push_back({BindingKind::uniform_buffer, binding, 0, 1, p.block, p.block_type});
    types.push_back(p.block_type);
  }
  m_caps = field_capabilities(m_field);
  if (m_options.repeats == 0) {
    throw UsageError("FieldMeter: MeasureOptions::repeats is 0; trace at least one frame per measurement (default 3)");
  }
  if (m_options.interior_stride == 0 || m_options.interior_stride > 1024) {
    throw UsageError("FieldMeter: MeasureOptions::interior_stride is " + std::to_string(m_options.interior_stride) +
                     "; give 1 (the truth of every pixel) to 1024 (one pixel in that many outside the silhouettes)");
  }
  std::vector<std::filesystem::path> dirs = m_options.shader_dirs;
  m_glsl_text = read_text_file(find_shader(dirs, m_field.glsl));
  detail::MeasureScene scene(std::move(types));
  const auto ray = scene.add_ray<detail::MeasurePayload>("measure", {.miss = "measure/measure.rmiss"});
  scene.set_global_signature(default_global_signature(std::move(bindings)));
  scene.add_raygen("measure/measure.rgen");
  scene.set_outputs({Output::t, Output::normal, Output::steps, Output::flags});
  m_geometry = add_distance_field(scene, m_field.id,
                                  {.glsl = m_field.glsl, .function = m_field.function, .aabb = m_field.aabb,
                                   .lipschitz = m_field.exact ? 0.0f : m_field.lipschitz, .exact = m_field.exact,
                                   .iterations = m_field.iterations, .parameters = m_field.parameters,
                                   .normal = m_field.normal,
                                   .closest_hit = {{ray, "measure/measure.rchit"}}});
  if (const auto lib = library_shader_dir(); !lib.empty()) dirs.push_back(lib);
  // The general variant: a meter renders many settings, each a new pipeline if specialized.
  m_renderer = std::make_unique<Renderer>(ctx, scene, RendererOptions{.shader_dirs = dirs, .specialize_fields = false});
  m_device = ctx.name();
}

PROCEDURAY_DECL FieldMeter::~FieldMeter() = default;

PROCEDURAY_DECL detail::ParameterBlock& FieldMeter::parameter_block(std::string_view name, const TypeOps* type) {
  for (detail::ParameterBlock& b : m_blocks) {
    if (b.name != name) continue;
    if (b.type != type && std::string_view(b.type->glsl_name) != std::string_view(type->glsl_name)) {
      throw UsageError("FieldMeter::set: uniform \"" + b.name + "\" holds " + std::string(b.type->glsl_name) +
                       " in field \"" + m_field.id + "\"'s parameters, not " + std::string(type->glsl_name) +
                       "; pass the slot they were declared with");
    }
    return b;
  }
  std::string read;
  for (const detail::ParameterBlock& b : m_blocks) read += (read.empty() ? "\"" : ", \"") + b.name + "\"";
  throw UsageError("FieldMeter::set: distance field \"" + m_field.id + "\" reads no uniform \"" + std::string(name) +
                   "\"; " + (read.empty() ? std::string("it takes no parameters") : "it reads " + read) +
                   ": set those");
}

PROCEDURAY_DECL std::string FieldMeter::parameter_values() const {
  std::string out;
  for (const detail::ParameterBlock& b : m_blocks) out += b.name + "=" + b.bytes + "\n";
  return out;
}

PROCEDURAY_DECL void FieldMeter::check_parameters_set(std::string_view op) const {
  for (const detail::ParameterBlock& b : m_blocks) {
    if (!b.bytes.empty()) continue;
    throw UsageError(std::string(op) + ": distance field \"" + m_field.id + "\" reads the uniform \"" + b.name +
                     "\" (its parameters), which has no value; call FieldMeter::set(slot, value) with the values to "
                     "measure at first");
  }
}

PROCEDURAY_DECL void FieldMeter::rendered(const MarchKnobs& knobs, const MeasureView& view,
                                          const accuracy::StratifiedTruth& truth, Measurement& m) {
  m_renderer->set(detail::measure_constants, detail::MeasureConstants{view.camera});
  m_renderer->set_pixel_angle(view.camera.pixel_angle);
  m_renderer->set_field_knobs(m_geometry, knobs);
  std::vector<double> times;
  Frame frame;
  for (std::uint32_t r = 0; r < m_options.repeats; ++r) {
    frame = m_renderer->render(view.width, view.height, r + 1 == m_options.repeats);
    times.push_back(frame.trace_ms);
  }
  std::sort(times.begin(), times.end());
  m.gpu_ms = times[times.size() / 2];
  const std::size_t pixels = truth.pixels.size();
  const std::vector<accuracy::Sample> samples = accuracy::samples_from(
      pixels, frame.outputs.t, frame.outputs.normal, frame.outputs.steps, frame.outputs.flags);
  const accuracy::Frame grid{.width = view.width, .height = view.height, .pixel_angle = view.camera.pixel_angle};
  m.metrics = accuracy::measure_stratified(grid, samples, truth);
  m.evaluation_split = accuracy::split_evaluations(grid, truth.pixels, samples, truth.weight);
  m.confidence = accuracy::confidence(grid, samples, truth);
  m.wrong_surface = m.metrics.all.wrong_surface;
  std::uint64_t evaluations = 0, box_rays = 0;
  for (std::uint32_t s : frame.outputs.steps) {
    evaluations += s;
    box_rays += s > 0;
  }
  m.evaluations_per_box_ray = box_rays == 0 ? 0.0 : static_cast<double>(evaluations) / static_cast<double>(box_rays);
  const double rate = m.metrics.all.wrong_surface_rate();  // NaN when the truth hits nothing
  m.wrong_surface_rate = std::isnan(rate) ? 0.0 : rate;
  m.evaluations_per_ray = static_cast<double>(evaluations) / static_cast<double>(pixels);
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
