// Your own distance field, from its GLSL file to a calibrated render under an error budget:
// declare it (no marching code), measure its methods against its own ground truth on this
// device at the size you render, let the budget pick the cheapest setting, render.
//
//   06_your_field [--out PATH] [--size WxH] [--device cpu|gpu|auto] [--validation]
//
// Writes the picture (--out) and, beside it, the calibration table (<out>.csv: chart it with
// tools/accuracy/calibration_chart.py). The table is kept in the cache folder: a second run reads it.
#include "../common/cli.hpp"

#include <proceduray/proceduray.hpp>
#include <proceduray/shader/glsl_cpp.hpp>

#include <cstdio>
#include <exception>
#include <fstream>

namespace your_field {
namespace pr = proceduray;
using namespace pr::glsl_cpp;

/// gyroid.glsl as C++, in double: the ground truth runs the very function the GPU marches.
template <class T>
struct gyroid {
  PROCEDURAY_GLSL_CPP_SCALAR(T)
#include "shaders/gyroid.glsl"
};

PROCEDURAY_DEFINE_STRUCT(Radiance, scalar, (glm::vec3, colour));
PROCEDURAY_DEFINE_STRUCT(Frame, scalar, (pr::Camera, camera), (glm::vec3, light));
PROCEDURAY_DEFINE_STRUCT(Material, scalar, (glm::vec3, albedo));
using Interface = pr::ShaderInterface<pr::Payload<Radiance>, pr::RootComponent<Frame>, pr::RootArguments<Material>,
                                      pr::Attributes<pr::FieldHit>>;
constexpr pr::UniformSlot<Frame> frame_slot{.binding = 2, .name = "frame"};

/// The field as the scene and the measuring tools see it.
const pr::DistanceField field{.id = "gyroid", .glsl = "gyroid.glsl", .aabb = {glm::vec3(-1.0f), glm::vec3(1.0f)},
                              .lipschitz = 1.75f};

std::filesystem::path shaders() { return examples::examples_dir() / "06_your_field" / "shaders"; }

pr::Camera camera(std::uint32_t width, std::uint32_t height) {
  return pr::look_at({1.6f, 1.2f, 2.4f}, {0.0f, 0.0f, 0.0f}, 45.0f, width, height);
}

/// Measures the field's preset at the render size (or reads the table from the cache).
pr::Calibration calibrate(const pr::vk::Context& ctx, std::uint32_t width, std::uint32_t height) {
  pr::vk::FieldMeter meter(ctx, field, {.shader_dirs = {shaders()}});
  const auto truth = [](glm::dvec3 p) { return gyroid<double>::gyroid_distance(p); };
  const pr::vk::Calibrated c = pr::vk::calibrate(
      meter, truth, {.view = {camera(width, height), width, height}, .cache_dir = pr::vk::default_cache_dir(),
                     .progress = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); }});
  std::fprintf(stderr, "calibration: %s (%s)\n", c.file.string().c_str(), c.cached ? "cached" : "measured");
  return c.table;
}

/// The scene: a sky, the field, a material; knobs from the budget's pick.
pr::Scene<Interface> scene(const pr::Calibration& table, std::uint32_t width, std::uint32_t height) {
  pr::Scene<Interface> s;
  const auto radiance = s.add_ray<Radiance>("radiance", {.miss = "sky.rmiss"});
  s.set_global_signature(pr::default_global_signature({frame_slot}));
  s.add_raygen("camera.rgen");
  const auto material = s.add_local_signature<Material>("material");
  pr::add_distance_field(s, field.id, {.glsl = field.glsl, .aabb = field.aabb, .lipschitz = field.lipschitz,
                                       .closest_hit = {{radiance, "shade.rchit"}}},
                         material, {{{0.85f, 0.6f, 0.25f}}});
  s.set_error_budget({}, table, width, height);  // the default: a 1080p picture cannot tell
  return s;
}

}  // namespace your_field

int main(int argc, char** argv) {
  namespace pr = proceduray;
  const examples::Options o = examples::parse(argc, argv, "06_your_field", {.width = 320, .height = 240});
  if (o.exit) return *o.exit;
  try {
    pr::check_writable(o.out);
    pr::vk::Context ctx({.device = o.device, .validation = o.validation});
    const pr::Calibration table = your_field::calibrate(ctx, o.width, o.height);
    pr::vk::Renderer renderer(ctx, your_field::scene(table, o.width, o.height),
                              {.shader_dirs = {your_field::shaders()}});
    const pr::CalibrationRow& pick = *renderer.plan().fields()[0].pick;
    std::fprintf(stderr, "pick: %s\n  %.1f evaluations per ray, depth median %.3g p99 %.3g footprints, "
                 "false misses %.3g%%, wrong surface %.3g%%\n", pr::describe(pick.knobs).c_str(), pick.evals,
                 pick.depth_median, pick.depth_p99, 100.0 * pick.false_misses, 100.0 * pick.wrong_surface);
    const pr::Camera cam = your_field::camera(o.width, o.height);
    renderer.set(your_field::frame_slot, {cam, {0.5f, 1.0f, 0.7f}});
    renderer.set_pixel_angle(cam.pixel_angle);
    const pr::vk::Frame frame = renderer.render(o.width, o.height);
    pr::write_png(o.out, o.width, o.height, frame.rgba);
    std::ofstream csv(o.out.string() + ".csv");
    table.write(csv);
    std::printf("%s\n", std::filesystem::absolute(o.out).string().c_str());
    return ctx.validation_messages().empty() ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "06_your_field: %s\n", e.what());
    return 1;
  }
}
