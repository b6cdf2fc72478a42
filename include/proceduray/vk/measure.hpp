// Measuring one distance field on the user's device: render it with given knobs from given
// views, compute the ground truth of every pixel from the same GLSL compiled as C++ in double
// (accuracy/field_truth.hpp), and return the errors and the cost. What a sweep, a calibration
// and an error budget are made of.
//
//   namespace acc = proceduray::accuracy;
//   const proceduray::DistanceField gyroid{.id = "gyroid", .glsl = "gyroid.glsl", .lipschitz = 1.75f};
//   auto cpu = [](glm::dvec3 p) { return mine::gyroid<double>::gyroid_distance(p); };  // the same file in C++
//   proceduray::vk::FieldMeter meter(ctx, gyroid, {.shader_dirs = {"shaders"}, .cache_dir = ".cache"});
//   const proceduray::vk::MeasureView view{proceduray::look_at({0.0f, 0.5f, 3.0f}, {}, 50.0f, 320, 240), 320, 240};
//   proceduray::vk::Measurement m = meter.measure(cpu, proceduray::march_base_knobs, view);
//   m.metrics.all.depth.median;     // footprints; m.metrics[acc::PixelClass::silhouette_1px].false_hits ...
//   m.wrong_surface_rate;           // hits more than 2 footprints behind the truth, per truth hit
//   m.evaluations_per_ray;          // the field's evaluations per camera ray (normals included)
//   m.gpu_ms;                       // median trace time of `repeats` frames
//
// The measuring scene is the library's (shaders/measure/): one camera ray per pixel, the field
// alone at the identity, the outputs t, normal, steps and flags. So the numbers are the
// field's, not a scene's: shading, reflections and other objects add nothing to them.
//
// A field that reads members of a scene uniform (field_parameter(slot, &T::member): a time, a
// size) is measured at the values set(slot, value) gives, before the first measure; `distance`
// must read the same values. The truth is kept per value, so each frame of an animation is
// measured against its own. A field with record parameters is refused (wrap it with fixed values).
//
//   meter.set(constants_slot, constants);                  // the uniform the field reads, as a frame sets it
//   auto cpu = [&](glm::dvec3 p) { return mine::wave<double>::wave_distance(p, constants.time); };
//
// The truth: the camera ray of each pixel in double (common/camera.glsl's formula), the field's
// box and bound checked first (scan_field: a bound the field exceeds is refused, naming the
// point and the slope), then field_hit per pixel on every core; normals are central
// differences of the double function at 1e-6 of the box diagonal. With interior_stride k > 1
// it is computed on a stratified sample (every pixel near a silhouette, one in k elsewhere:
// accuracy/stratified.hpp) and the rates come with their 95% bounds. It does not depend on the
// knobs, so it is computed once per view and kept: in memory, and with a cache folder on disk,
// keyed by the GLSL file's text, the declaration, the view, the sample and the library version
// (a changed file or view computes it again).
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/accuracy/evaluation_split.hpp>
#include <proceduray/accuracy/field_truth.hpp>
#include <proceduray/accuracy/metrics.hpp>
#include <proceduray/accuracy/parallel.hpp>
#include <proceduray/accuracy/samples.hpp>
#include <proceduray/accuracy/stratified.hpp>
#include <proceduray/scene/field.hpp>
#include <proceduray/scene/ids.hpp>
#include <proceduray/scene/uniform_slot.hpp>
#include <proceduray/shader/camera.hpp>
#include <proceduray/shader/categories.hpp>
#include <proceduray/shader/define_struct.hpp>
#include <proceduray/vk/context.hpp>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace proceduray::vk {

class Renderer;

/// A camera and the image size it is rendered at.
struct MeasureView {
  Camera camera;            ///< look_at(...) for this size
  std::uint32_t width = 0;
  std::uint32_t height = 0;
};

/// Where the field's GLSL is, and where the truth may be kept.
struct MeasureOptions {
  std::vector<std::filesystem::path> shader_dirs;  ///< folders holding the field's GLSL file
  std::filesystem::path cache_dir;                 ///< empty: the truth is kept in memory only
  std::uint32_t repeats = 3;                       ///< frames traced per measurement; gpu_ms is their median
  /// 1: the truth of every pixel. k > 1: of every pixel near a silhouette or a depth jump and of
  /// one in k of the others, each standing for k (accuracy/stratified.hpp); the rates are then
  /// estimates, with their 95% bounds in Measurement::confidence.
  std::uint32_t interior_stride = 1;
  std::uint64_t seed = 1;                          ///< which pixels a stride > 1 samples
};

/// One field, one setting, one view.
struct Measurement {
  accuracy::Metrics metrics;          ///< per pixel class: agreement, depth and normal errors, steps
  std::uint64_t wrong_surface = 0;    ///< hits more than 2 footprints behind the truth's (metrics.all.wrong_surface)
  double wrong_surface_rate = 0.0;    ///< wrong_surface / the truth's hits (0 when none)
  double evaluations_per_ray = 0.0;   ///< mean evaluations per camera ray, every ray
  double evaluations_per_box_ray = 0.0;  ///< mean over the rays that evaluated the field (entered its box)
  /// The evaluations of the rays that hit, that miss within 2 pixels of a silhouette, and that
  /// miss farther out (by the truth): where a setting's cost goes.
  accuracy::EvaluationSplit evaluation_split;
  double gpu_ms = 0.0;                ///< median trace time of the frames
  double truth_ms = 0.0;              ///< wall time of the truth (0 when it came from a cache)
  bool truth_cached = false;          ///< the truth came from memory or the cache folder
  std::size_t truth_traced = 0;       ///< pixels whose truth was computed (all of them at stride 1)
  /// The false-miss and wrong-surface rates and their upper 95% bounds (equal at stride 1).
  accuracy::SampleConfidence confidence;
};

/// The truth of one view: per pixel (or on a stratified sample), from field_hit and the double normal.
struct ViewTruth {
  accuracy::StratifiedTruth sample;
  double ms = 0.0;
};

namespace detail {

/// The measuring scene's payload and constants (shaders/measure/). The view's uniform has a
/// reserved name, so a field's own uniform (often "constants") can sit beside it.
PROCEDURAY_DEFINE_STRUCT(MeasurePayload, scalar, (std::uint32_t, hit));
PROCEDURAY_DEFINE_STRUCT(MeasureConstants, scalar, (Camera, camera));
using MeasureInterface = ShaderInterface<Payload<MeasurePayload>, RootComponent<MeasureConstants>, RootArguments<>,
                                         Attributes<FieldHit>>;
inline constexpr UniformSlot<MeasureConstants> measure_constants{.binding = 2, .name = "proceduray_view"};
/// The first binding of the uniforms a field's parameters read (one each, in order of first use).
inline constexpr std::uint32_t measure_parameter_binding = 3;

/// A uniform a field's parameters read, in the measuring scene: its binding, and the bytes last set.
struct ParameterBlock {
  std::string name;              ///< the uniform's GLSL name (UniformSlot::name)
  const TypeOps* type = nullptr;
  std::uint32_t binding = 0;     ///< in the measuring scene
  std::string bytes;             ///< the value set; empty until set
};

/// Unit direction of pixel (x, y): camera.glsl's camera_ray in double.
PROCEDURAY_DECL glm::dvec3 measure_direction(const Camera& c, std::uint32_t x, std::uint32_t y, std::uint32_t width,
                                             std::uint32_t height);
/// The cache key of a view's truth: the field's GLSL text, its declaration, the view, the sample
/// (stride and seed), the version.
PROCEDURAY_DECL std::uint64_t truth_key(const DistanceField& field, const std::string& glsl_text, const MeasureView& view,
                                        const MeasureOptions& options, std::string_view parameters = {});
/// Reads a cached truth (false when absent or not this key's); writes one (best effort).
PROCEDURAY_DECL bool read_truth(const std::filesystem::path& file, std::uint64_t key, std::size_t pixels,
                                accuracy::StratifiedTruth& out);
PROCEDURAY_DECL void write_truth(const std::filesystem::path& file, std::uint64_t key,
                                 const accuracy::StratifiedTruth& truth);
PROCEDURAY_DECL void check_view(const MeasureView& view, std::string_view op);

}  // namespace detail

/// A field's measuring scene on a device, built once (the pipeline is the dear part) and
/// measured at any knobs and views.
class FieldMeter {
 public:
  /// Builds the measuring scene of `field` (checked: validate(DistanceField)); throws what the
  /// Renderer throws (a GLSL file that does not compile names its line).
  FieldMeter(const Context& ctx, DistanceField field, MeasureOptions options);
  FieldMeter(const FieldMeter&) = delete;
  FieldMeter& operator=(const FieldMeter&) = delete;
  ~FieldMeter();

  /// The value of a uniform the field's parameters read, for the render and the truth's key:
  /// throws UsageError when the field reads no uniform of that name, TypeMismatchError for another
  /// type than the field's parameters were declared with.
  template <RegisteredStruct T>
  void set(UniformSlot<T> slot, const std::type_identity_t<T>& value) {
    detail::ParameterBlock& b = parameter_block(slot.name, &type_ops<T>);
    std::string bytes(reinterpret_cast<const char*>(&value), sizeof value);
    if (bytes == b.bytes) return;
    upload(UniformSlot<T>{.binding = b.binding, .name = b.name.c_str()}, value);
    b.bytes = std::move(bytes);
    m_scanned = false;  // the bound holds for these values: checked again
  }

  /// Renders `view` with `knobs` (checked against the field's capabilities) and measures it
  /// against the truth of `distance` (double(glm::dvec3), the field's GLSL in C++).
  template <class Distance>
  Measurement measure(const Distance& distance, const MarchKnobs& knobs, const MeasureView& view) {
    detail::check_view(view, "FieldMeter::measure");
    check_parameters_set("FieldMeter::measure");
    Measurement m;
    const ViewTruth& truth = truth_of(distance, view, m.truth_cached);
    m.truth_ms = m.truth_cached ? 0.0 : truth.ms;
    m.truth_traced = truth.sample.traced;
    rendered(knobs, view, truth.sample, m);
    return m;
  }

  /// The truth of `view` (cached as measure() does).
  template <class Distance>
  const ViewTruth& truth_of(const Distance& distance, const MeasureView& view, bool& cached) {
    const std::uint64_t key = detail::truth_key(m_field, m_glsl_text, view, m_options, parameter_values());
    cached = true;
    if (auto it = m_truths.find(key); it != m_truths.end()) return it->second;
    ViewTruth t;
    const std::size_t pixels = std::size_t{view.width} * view.height;
    const std::filesystem::path file = m_options.cache_dir.empty()
                                           ? std::filesystem::path()
                                           : m_options.cache_dir / "truth" / (std::to_string(key) + ".truth");
    if (file.empty() || !detail::read_truth(file, key, pixels, t.sample)) {
      cached = false;
      const auto start = std::chrono::steady_clock::now();
      compute_truth(distance, view, t.sample);
      t.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      if (!file.empty()) detail::write_truth(file, key, t.sample);
    }
    return m_truths.emplace(key, std::move(t)).first->second;
  }

  const DistanceField& field() const noexcept { return m_field; }
  /// The options the meter was built with.
  const MeasureOptions& options() const noexcept { return m_options; }
  /// The text of the field's GLSL file as read when the meter was built.
  const std::string& glsl_text() const noexcept { return m_glsl_text; }
  /// The device's name (Context::name), for calibration tables.
  const std::string& device() const noexcept { return m_device; }
  /// What the field accepts (field_capabilities).
  const MarchCapabilities& capabilities() const noexcept { return m_caps; }
  /// The bytes of every uniform the field reads, as set (empty for a field without parameters).
  std::string parameter_values() const;
  /// Throws UsageError naming `op`, the uniform and set() when a uniform the field reads has no value.
  void check_parameters_set(std::string_view op) const;

 private:
  template <class Distance>
  void compute_truth(const Distance& distance, const MeasureView& view, accuracy::StratifiedTruth& out) {
    const accuracy::FieldBounds bounds = accuracy::field_bounds(m_field);
    if (!m_scanned) {
      accuracy::scan_field(distance, bounds, "FieldMeter::measure");  // throws: NaN, a slope past L
      m_scanned = true;
    }
    const double diagonal = glm::length(bounds.max - bounds.min);
    const accuracy::SearchOptions search{.min_step = 1.0e-9 * diagonal};
    const glm::dvec3 eye(view.camera.eye);
    const accuracy::Frame frame{.width = view.width, .height = view.height, .pixel_angle = view.camera.pixel_angle};
    out = accuracy::stratified_truth(frame, m_options.interior_stride, m_options.seed, [&](std::uint32_t x, std::uint32_t y) {
      const glm::dvec3 d = detail::measure_direction(view.camera, x, y, view.width, view.height);
      const accuracy::Result r = accuracy::field_hit(distance, bounds, eye, d, 0.0, 1.0e30, search);
      accuracy::Reference ref{.outcome = r.outcome};
      if (r.outcome != accuracy::Outcome::hit) return ref;
      ref.t = r.t;
      ref.normal = accuracy::gradient_normal(distance, eye + r.t * d, 1.0e-6 * diagonal);
      return ref;
    });
  }
  detail::ParameterBlock& parameter_block(std::string_view name, const TypeOps* type);
  template <class T>
  void upload(UniformSlot<T> slot, const T& value);  // measure-inl.hpp: where Renderer is complete
  /// Renders and fills m from the frames against `truth`.
  void rendered(const MarchKnobs& knobs, const MeasureView& view, const accuracy::StratifiedTruth& truth,
                Measurement& m);

  DistanceField m_field;
  MeasureOptions m_options;
  MarchCapabilities m_caps;
  std::string m_glsl_text;
  std::string m_device;
  std::unique_ptr<Renderer> m_renderer;
  GeometryId m_geometry;
  std::vector<detail::ParameterBlock> m_blocks;  // fixed after construction: slots point at the names
  std::map<std::uint64_t, ViewTruth> m_truths;
  bool m_scanned = false;
};

}  // namespace proceduray::vk

#include "proceduray/vk/measure-inl.hpp"  // the bodies (config.hpp)
