// Distance fields on the device: the generated intersection shader against a hand-written march
// of the same file (the same image, byte for byte) and against the closed form (the same
// silhouette within the threshold), knobs checked on change, the pixel angle required, and a
// field with a bound above 1 that plain sphere steps would overshoot.
#include "test_context.hpp"
#include "test_paths.hpp"

#include <proceduray/proceduray.hpp>
#include <proceduray/scene/distance_field.hpp>
#include <proceduray/vk/measure.hpp>

#include <doctest/doctest.h>

#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

namespace pr = proceduray;

struct Constants {
  pr::Camera camera;
  pr::MarchKnobs knobs;  // handwritten.rint's; the generated shader reads the library's buffer
  float radius = 1.0f;   // sized_ball.glsl's parameter
  std::uint32_t ray_flags = 0;  // field.rgen traces with these besides opaque (cull flags)
};
PROCEDURAY_STRUCT(Constants, scalar, camera, knobs, radius, ray_flags);
struct Colour {
  glm::vec3 rgb;
};
PROCEDURAY_STRUCT(Colour, scalar, rgb);
using Interface = pr::ShaderInterface<pr::Payload<Colour>, pr::RootComponent<Constants>, pr::RootArguments<>,
                                      pr::Attributes<pr::FieldHit>>;
using Scene = pr::Scene<Interface>;

constexpr pr::UniformSlot<Constants> constants_slot{.binding = 2, .name = "constants"};
constexpr std::uint32_t width = 96, height = 72;

/// A ray, a camera and the object "ball": a field of `glsl` (or, with `intersection`, a
/// procedural object running that hand-written shader over the unit box).
struct FieldScene {
  Scene scene;
  pr::GeometryId object;

  explicit FieldScene(const std::string& glsl, const std::string& intersection = {}, float lipschitz = 0.0f,
                      std::vector<pr::FieldParameter> parameters = {}, std::string normal = {},
                      pr::OutputSet outputs = {}) {
    const auto primary = scene.add_ray<Colour>("primary", {.miss = "sky.rmiss"});
    scene.set_outputs(outputs);
    scene.set_global_signature(pr::default_global_signature({constants_slot}));
    scene.add_raygen("field.rgen");
    if (!intersection.empty()) {
      object = pr::add_object<pr::FieldHit>(scene, "ball", {.geometry = pr::GeometryDesc::procedural({pr::Aabb{}}),
                                                            .intersection = intersection,
                                                            .closest_hit = {{primary, "shade.rchit"}}});
      return;
    }
    object = pr::add_distance_field(scene, "ball", {.glsl = glsl, .function = glsl.substr(0, glsl.find('.')) + "_distance",
                                                    .aabb = {glm::vec3(-1.0f), glm::vec3(1.0f)},
                                                    .lipschitz = lipschitz, .exact = lipschitz == 0.0f,
                                                    .parameters = std::move(parameters), .normal = std::move(normal),
                                                    .closest_hit = {{primary, "shade.rchit"}}});
  }
};

/// The test's fields, and example 06's gyroid (the field the library does not ship).
pr::vk::RendererOptions options() {
  return {.shader_dirs = {test_source_dir() / "vk" / "shaders" / "fields", test_source_dir() / ".." / "examples" / "06_your_field" / "shaders"}};
}

Constants constants() {
  return {pr::look_at({0.0f, 0.6f, 3.2f}, {0.0f, 0.0f, 0.0f}, 50.0f, width, height), pr::march_base_knobs};
}

std::vector<std::uint8_t> render(pr::vk::Renderer& r, const pr::MarchKnobs& knobs = pr::march_base_knobs,
                                 float radius = 1.0f, std::uint32_t ray_flags = 0) {
  Constants c = constants();
  c.knobs = knobs;
  c.radius = radius;
  c.ray_flags = ray_flags;
  r.set(constants_slot, c);
  if (!r.plan().fields().empty()) {
    r.set_pixel_angle(c.camera.pixel_angle);
    r.set_field_knobs(r.plan().fields()[0].geometry, knobs);
  }
  return r.render(width, height).rgba;
}

std::size_t covered(const std::vector<std::uint8_t>& rgba) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < rgba.size(); i += 4) n += (rgba[i] | rgba[i + 1] | rgba[i + 2]) != 0;
  return n;
}

}  // namespace

TEST_CASE("a distance field renders through the generated shader as through a hand-written march of its file") {
  TestContext t;
  FieldScene generated("ball.glsl"), handwritten("", "handwritten.rint");
  pr::vk::Renderer a(t.ctx, generated.scene, options()), b(t.ctx, handwritten.scene, options());
  const auto ia = render(a), ib = render(b);
  CHECK(covered(ia) > width * height / 8);  // the ball fills a good part of the view
  CHECK(ia == ib);
  // Another setting moves both alike: tetrahedral normals and the relaxed method.
  pr::MarchKnobs k = pr::march_base_knobs;
  k.method = pr::MarchMethod::relaxed;
  k.relaxation = 1.5f;
  k.normal = pr::MarchNormal::tetrahedral;
  CHECK(render(a, k) == render(b, k));
  CHECK(render(a, k) != ia);  // the normal changed, and with it the colours
}

TEST_CASE("a distance field's image matches the closed form within its threshold") {
  TestContext t;
  FieldScene generated("ball.glsl"), analytic("", "analytic.rint");
  pr::vk::Renderer a(t.ctx, generated.scene, options()), b(t.ctx, analytic.scene, options());
  const auto ia = render(a), ib = render(b);
  std::size_t coverage_differs = 0, colour_far = 0;
  for (std::size_t i = 0; i < ia.size(); i += 4) {
    const bool ha = (ia[i] | ia[i + 1] | ia[i + 2]) != 0, hb = (ib[i] | ib[i + 1] | ib[i + 2]) != 0;
    if (ha != hb) ++coverage_differs;
    for (int c = 0; ha && hb && c < 3; ++c) colour_far += std::abs(int(ia[i + c]) - int(ib[i + c])) > 4;
  }
  const std::size_t hits = covered(ib);
  CHECK(hits > width * height / 8);
  CHECK(coverage_differs <= hits / 100);  // silhouette pixels at most: half a footprint threshold
  CHECK(colour_far <= hits / 100);        // normals within ~1 degree (4 of 255 levels)
}

TEST_CASE("distance field knobs: checked on change, the pixel angle required, no sphere steps past L = 1") {
  TestContext t;
  FieldScene gyroid("gyroid.glsl", "", 1.75f);
  pr::vk::Renderer r(t.ctx, gyroid.scene, options());
  r.set(constants_slot, constants());
  // No pixel angle yet: footprint thresholds have nothing to scale with.
  try {
    r.render(width, height);
    FAIL("render without a pixel angle did not throw");
  } catch (const pr::UsageError& e) {
    CHECK(std::string(e.what()).find("set_pixel_angle") != std::string::npos);
    CHECK(std::string(e.what()).find("\"ball\"") != std::string::npos);
  }
  CHECK_THROWS_AS(r.set_pixel_angle(0.0f), pr::UsageError);
  CHECK_THROWS_AS(r.set_pixel_angle(std::nanf("")), pr::UsageError);
  pr::MarchKnobs k = pr::march_base_knobs;
  k.method = pr::MarchMethod::sphere;  // assumes L = 1: would step through the gyroid's sheets
  try {
    r.set_field_knobs(gyroid.object, k);
    FAIL("sphere steps on an L = 1.75 field were accepted");
  } catch (const pr::UsageError& e) {
    const std::string m = e.what();
    CHECK(m.find("Renderer::set_field_knobs") != std::string::npos);
    CHECK(m.find("sphere") != std::string::npos);
    CHECK(m.find("lipschitz") != std::string::npos);  // the valid methods are listed
  }
  CHECK(r.field_knobs(gyroid.object).method == pr::MarchMethod::lipschitz);  // unchanged by the refusal
  k = pr::march_base_knobs;
  k.max_steps = 0;
  CHECK_THROWS_AS(r.set_field_knobs(gyroid.object, k), pr::UsageError);
  CHECK_THROWS_AS(r.set_field_knobs(pr::GeometryId(7), pr::march_base_knobs), pr::UsageError);
  CHECK_THROWS_AS(r.set_field_knobs(pr::GeometryId(), pr::march_base_knobs), pr::UsageError);
  // The gyroid renders: holes through the shell, so it covers less of its disc than the ball.
  const auto image = render(r);
  FieldScene ball("ball.glsl");
  pr::vk::Renderer rb(t.ctx, ball.scene, options());
  const std::size_t g = covered(image), b = covered(render(rb));
  CHECK(g > b / 5);
  CHECK(g < b * 9 / 10);
}

TEST_CASE("a distance field's parameters come from the scene's uniform, frame by frame, without a rebuild") {
  TestContext t;
  FieldScene sized("sized_ball.glsl", "", 0.0f, {pr::field_parameter(constants_slot, &Constants::radius)});
  FieldScene ball("ball.glsl");
  pr::vk::Renderer a(t.ctx, sized.scene, options()), b(t.ctx, ball.scene, options());
  CHECK(render(a, pr::march_base_knobs, 1.0f) == render(b));  // radius 1: the unit ball, byte for byte
  const std::size_t small = covered(render(a, pr::march_base_knobs, 0.5f));
  const std::size_t large = covered(render(a, pr::march_base_knobs, 0.9f));
  CHECK(small > 50);
  // The disc's area grows with the radius squared (3.24x), less the perspective's few percent.
  CHECK(double(large) / double(small) > 2.8);
  CHECK(double(large) / double(small) < 3.8);
  CHECK(a.plan().fields()[0].field.parameters[0].member == "radius");
}

TEST_CASE("a distance field's normal function gives the normal where it says it knows it") {
  TestContext t;
  FieldScene facing("facing_ball.glsl", "", 0.0f, {}, "facing_ball_normal"), ball("ball.glsl");
  pr::vk::Renderer a(t.ctx, facing.scene, options()), b(t.ctx, ball.scene, options());
  const auto ia = render(a), ib = render(b);
  // The camera sees the ball's front (z > 0): every hit takes the function's +z, colour (128, 128, 255).
  std::size_t hits = 0, facing_colour = 0;
  for (std::size_t i = 0; i < ia.size(); i += 4) {
    if ((ia[i] | ia[i + 1] | ia[i + 2]) == 0) continue;
    ++hits;
    facing_colour += std::abs(int(ia[i]) - 128) <= 1 && std::abs(int(ia[i + 1]) - 128) <= 1 && ia[i + 2] >= 254;
  }
  CHECK(hits == covered(ib));                      // the same march, the same silhouette
  CHECK(facing_colour == hits);
  CHECK(ia != ib);                                 // the plain ball's differences vary over the disc
}

namespace {
struct Size {
  float radius;
};
PROCEDURAY_STRUCT(Size, scalar, radius);
using SizedInterface = pr::ShaderInterface<pr::Payload<Colour>, pr::RootComponent<Constants>, pr::RootArguments<Size>,
                                           pr::Attributes<pr::FieldHit>>;
}  // namespace

TEST_CASE("a distance field's record parameters give each instance block its own value") {
  TestContext t;
  pr::Scene<SizedInterface> scene;
  const auto primary = scene.add_ray<Colour>("primary", {.miss = "sky.rmiss"});
  scene.set_global_signature(pr::default_global_signature({constants_slot}));
  scene.add_raygen("field.rgen");
  const auto size = scene.add_local_signature<Size>("size");
  // Two balls of one field, left and right of the view's centre, radius 0.4 and 0.8 from their records.
  const auto at = [](float x) { return pr::instance_transform(glm::translate(glm::mat4(1.0f), {x, 0.0f, 0.0f})); };
  pr::add_distance_field(scene, "ball", {.glsl = "sized_ball.glsl", .function = "sized_ball_distance", .aabb = {glm::vec3(-1.0f), glm::vec3(1.0f)},
                                         .exact = true, .parameters = {pr::field_parameter(size, &Size::radius)},
                                         .instances = {at(-1.0f), at(1.0f)}, .closest_hit = {{primary, "shade.rchit"}}},
                         size, {{0.4f}, {0.8f}});
  pr::vk::Renderer r(t.ctx, scene, options());
  const auto image = render(r);
  std::size_t left = 0, right = 0;
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      const std::size_t i = 4 * (std::size_t{y} * width + x);
      if ((image[i] | image[i + 1] | image[i + 2]) != 0) (x < width / 2 ? left : right) += 1;
    }
  }
  CHECK(left > 20);
  // Areas as the radii squared (0.25), give or take the perspective of balls off the axis.
  CHECK(double(left) / double(right) > 0.18);
  CHECK(double(left) / double(right) < 0.34);
}

TEST_CASE("a distance field honours the ray's cull flags as a triangle would, by the side its normal faces") {
  TestContext t;
  FieldScene ball("ball.glsl");
  pr::vk::Renderer r(t.ctx, ball.scene, options());
  const auto plain = render(r);
  CHECK(covered(plain) > width * height / 8);
  // From outside, every hit is a front face: culling back faces keeps them, culling front faces drops them.
  CHECK(render(r, pr::march_base_knobs, 1.0f, 0x10u /* gl_RayFlagsCullBackFacingTrianglesEXT */) == plain);
  CHECK(covered(render(r, pr::march_base_knobs, 1.0f, 0x20u /* gl_RayFlagsCullFrontFacingTrianglesEXT */)) == 0);
}

TEST_CASE("a distance field's hit reports its threshold in world units, on a scaled instance, for either threshold mode") {
  TestContext t;
  Scene scene;
  const auto primary = scene.add_ray<Colour>("primary", {.miss = "sky.rmiss"});
  scene.set_global_signature(pr::default_global_signature({constants_slot}));
  scene.add_raygen("field.rgen");
  // Half size: object lengths are twice the world's, so a threshold left in object units reads 1.0, not 0.5.
  const pr::InstanceTransform half = pr::instance_transform(glm::scale(glm::mat4(1.0f), glm::vec3(0.5f)));
  pr::add_distance_field(scene, "ball", {.glsl = "ball.glsl", .function = "ball_distance",
                                         .aabb = {glm::vec3(-1.0f), glm::vec3(1.0f)}, .exact = true,
                                         .instances = {half}, .closest_hit = {{primary, "threshold.rchit"}}});
  pr::vk::Renderer r(t.ctx, scene, options());
  pr::MarchKnobs footprints = pr::march_base_knobs;
  footprints.threshold = 4.0f;
  pr::MarchKnobs absolute = pr::march_base_knobs;
  absolute.threshold_mode = pr::MarchThreshold::absolute;
  absolute.threshold = 0.01f;
  for (const pr::MarchKnobs& k : {footprints, absolute}) {
    const auto image = render(r, k);
    std::size_t hits = 0, off = 0;
    for (std::size_t i = 0; i < image.size(); i += 4) {
      if (image[i + 2] == 0) continue;  // the sky
      ++hits;
      off += std::abs(int(image[i]) - 128) > 2;
    }
    CAPTURE(pr::describe(k));
    CHECK(hits > width * height / 16);
    CHECK(off == 0);
  }
}

TEST_CASE("the classic hit rule fattens a silhouette by its threshold, as the closed form predicts; the default does not") {
  // A unit ball: a ray missing it by delta (closest approach, double) is a classic hit when
  // delta is under the threshold there, k footprints at that distance: the rule's known false
  // hits. Pixels within 30% below and 25% above the threshold are left to where the steps fall.
  TestContext t;
  FieldScene ball("ball.glsl");
  pr::vk::Renderer r(t.ctx, ball.scene, options());
  const Constants c = constants();
  pr::MarchKnobs classic = pr::march_base_knobs;
  classic.threshold = 2.0f;
  pr::set_knob(classic, "refine", "classic");
  pr::MarchKnobs refined = classic;
  refined.refine = 1;
  const auto fat = render(r, classic), exact = render(r, refined);
  std::size_t predicted = 0, fattened = 0, beyond = 0, beyond_hit = 0, exact_false = 0;
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      const glm::dvec3 d = pr::vk::detail::measure_direction(c.camera, x, y, width, height);
      const glm::dvec3 eye(c.camera.eye);
      const double tc = -glm::dot(eye, d), delta = glm::length(eye + tc * d) - 1.0;
      if (delta <= 0.0) continue;  // the truth hits
      const double threshold = classic.threshold * c.camera.pixel_angle * tc;
      const std::size_t i = 4 * (std::size_t{y} * width + x);
      const bool hit = (fat[i] | fat[i + 1] | fat[i + 2]) != 0;
      exact_false += (exact[i] | exact[i + 1] | exact[i + 2]) != 0;
      if (delta < 0.7 * threshold) {
        ++predicted;
        fattened += hit;
      } else if (delta > 1.25 * threshold) {
        ++beyond;
        beyond_hit += hit;
      }
    }
  }
  CAPTURE(predicted);
  CAPTURE(fattened);
  CHECK(predicted > 100);                // a ring about 2 pixels wide around the ball
  CHECK(fattened >= predicted * 97 / 100);  // a step may pass the closest approach between two points
  CHECK(beyond_hit <= 1);
  CHECK(beyond > 1000);
  CHECK(exact_false <= 2);               // a crossing is needed: the same threshold keeps the silhouette
  CHECK(pr::describe(classic).find("refine=classic") != std::string::npos);
}

namespace {
/// True when `spirv` declares a specialization constant with SpecId `id` (OpDecorate %x SpecId id).
bool declares_spec_id(const std::vector<std::uint32_t>& spirv, std::uint32_t id) {
  for (std::size_t i = 5; i < spirv.size();) {
    const std::uint32_t count = spirv[i] >> 16, opcode = spirv[i] & 0xFFFFu;
    if (count == 0) return false;
    if (opcode == 71 && count == 4 && spirv[i + 2] == 1 && spirv[i + 3] == id) return true;  // 1: SpecId
    i += count;
  }
  return false;
}
}  // namespace

TEST_CASE("a field's knobs compiled in (specialized) and read per ray (general) render the same image") {
  TestContext t;
  FieldScene ball("ball.glsl"), gyroid("gyroid.glsl", "", 1.75f);
  pr::vk::RendererOptions general = options();
  general.specialize_fields = false;
  // The field's stage is the generated one, and its SPIR-V declares the knobs as constants.
  const pr::Plan plan = pr::compile(ball.scene);
  const pr::vk::SceneStages stages = pr::vk::compile_scene_stages(plan, options());
  std::size_t field_stages = 0;
  for (std::size_t i = 0; i < plan.pipeline().stages.size(); ++i) {
    if (!plan.pipeline().stages[i].field) continue;
    ++field_stages;
    CHECK(*plan.pipeline().stages[i].field == 0u);
    CHECK(declares_spec_id(stages.spirv[i], pr::field_spec_id));
    CHECK(declares_spec_id(stages.spirv[i], pr::field_spec_id + 1));  // the method
  }
  CHECK(field_stages == 1);
  for (FieldScene* scene : {&ball, &gyroid}) {
    pr::vk::Renderer s(t.ctx, scene->scene, options()), g(t.ctx, scene->scene, general);
    // Each method of march/ the field takes, the classic rule, tetrahedral normals, fixed steps.
    std::vector<pr::MarchKnobs> settings;
    for (pr::MarchMethod m : pr::field_capabilities(s.plan().fields()[0].field).methods) {
      pr::MarchKnobs k = pr::march_base_knobs;
      k.method = m;
      k.relaxation = 1.5f;
      k.fixed_steps = 48;
      settings.push_back(k);
    }
    settings.push_back(settings.front());
    settings.back().refine = 2;
    settings.back().normal = pr::MarchNormal::tetrahedral;
    settings.back().threshold = 2.0f;
    std::vector<std::vector<std::uint8_t>> images;
    for (const pr::MarchKnobs& k : settings) {
      CAPTURE(pr::describe(k));
      images.push_back(render(s, k));
      CHECK(covered(images.back()) > width * height / 10);
      CHECK(images.back() == render(g, k));
    }
    CHECK(images.back() != images.front());  // the knobs reach the specialized shader
    // One pipeline per change of knobs for the specialized renderer (every setting differs from
    // the one before, the first from the defaults; none for equal knobs), none for the general one.
    CHECK(s.timings().rebuilds == settings.size());
    render(s, settings.back());
    CHECK(s.timings().rebuilds == settings.size());
    CHECK(g.timings().rebuilds == 0);
  }
}

TEST_CASE("a ray that reads only whether it hits (a shadow ray) skips the bisection and the normal, same answer") {
  TestContext t;
  FieldScene ball("ball.glsl", "", 0.0f, {}, {}, {pr::Output::steps});
  pr::vk::Renderer r(t.ctx, ball.scene, options());
  const auto frame = [&](std::uint32_t flags) {
    Constants c = constants();
    c.ray_flags = flags;
    r.set(constants_slot, c);
    r.set_pixel_angle(c.camera.pixel_angle);
    return r.render(width, height);
  };
  const std::uint32_t first = 0x4, skip = 0x8;  // gl_RayFlagsTerminateOnFirstHitEXT, ...SkipClosestHitShaderEXT
  const pr::vk::Frame full = frame(first), shadow = frame(first | skip);
  std::size_t hits = 0, same = 0;
  std::uint64_t full_steps = 0, shadow_steps = 0;
  for (std::size_t i = 0; i < std::size_t{width} * height; ++i) {
    const bool hit_full = (full.rgba[4 * i] | full.rgba[4 * i + 1] | full.rgba[4 * i + 2]) != 0;
    const bool hit_shadow = shadow.rgba[4 * i] == 255;  // the payload a skipped closest hit leaves
    hits += hit_full;
    same += hit_full == hit_shadow;
    full_steps += full.outputs.steps[i];
    shadow_steps += shadow.outputs.steps[i];
  }
  CHECK(hits > width * height / 8);
  CHECK(same == std::size_t{width} * height);  // the same pixels hit
  // Per hit: the central normal's 6 evaluations and the bisection's (at least one) saved.
  CHECK(shadow_steps + 7 * hits <= full_steps);
  // A ray that culls needs the normal to tell the face: it pays for the normal and the bisection.
  const pr::vk::Frame culled = frame(first | skip | 0x10);  // ...CullBackFacingTrianglesEXT: the normal decides
  std::uint64_t culled_steps = 0;
  for (std::uint32_t s : culled.outputs.steps) culled_steps += s;
  CHECK(culled_steps > shadow_steps + 6 * hits);
}
