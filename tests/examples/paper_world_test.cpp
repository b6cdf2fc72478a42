// examples/02_paper_scene/world.hpp: the paper scene 1e5 and 1e6 units from (0, 0, 0), drawn
// relative to a WorldOrigin at the camera, against the scene at (0, 0, 0). A translation changes
// no distance along a ray, so the depths of the two must agree to float rounding of coordinates
// near the camera: the bound is 0.1 pixel footprints, median. Without the re-origin the
// same scene at 1e6 is off by pixels, which is what these checks would see if one world point
// (an instance, the eye, the light) missed the origin.
#include "test_knobs.hpp"
#include "vk/test_context.hpp"

#include <02_paper_scene/accuracy.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace proceduray;

namespace {

constexpr std::uint32_t width = 64;
constexpr std::uint32_t height = 48;
// Not on an axis, so every coordinate is rounded: |offset| = 1 (0.36 + 0.2304 + 0.4096).
const glm::dvec3 direction{0.6, 0.48, -0.64};

struct Render {
  std::vector<float> t;
  std::vector<paper::ObjectId> seen;
  std::vector<std::uint8_t> rgba;
  float pixel_angle = 0.0f;
};

/// What a camera sees: the whole scene at this size, or a window on the Mandelbulb with the pixel
/// footprint of the whole view at 1920x1080 (rounding errors count in footprints: the window
/// measures them at the size users render).
enum class View { whole, bulb_at_1080p };

/// The paper scene placed by `world`, with shadows and reflections (the light is a world point).
Render render(const vk::Context& ctx, const paper::World& world, View view = View::whole) {
  const paper::PaperScene scene(paper::accuracy_outputs, paper::Tracing::recursive, paper::max_depth_limit, world);
  vk::Renderer renderer(ctx, scene, scene.renderer_options());
  paper::Frame c = test_knobs::pinned(paper::default_frame(width, height, 0.0f));
  if (view == View::bulb_at_1080p) {
    // default_constants' vertical field of view, 50 degrees over 1080 rows, on `height` rows.
    c.camera = look_at(paper::default_eye, paper::mandelbulb_placement.translation, 50.0f * height / 1080.0f, width, height);
  }
  world.place(c);
  paper::set_frame(renderer, c);
  const vk::Frame f = renderer.render(width, height);
  return {f.outputs.t, paper::device_objects(renderer.plan(), f.outputs.ids), f.rgba, c.camera.pixel_angle};
}

struct Difference {
  double median_px = 0.0;     ///< |t - t at the origin| / footprint, median over pixels both hit
  double disagree = 0.0;      ///< share of pixels where one hits and the other does not, or objects differ
  double colour = 0.0;        ///< share of pixels with a channel off by more than 8 of 255
  std::size_t both = 0;
};

/// `r` against the scene at the origin, over the pixels where `only` is seen there (sky_id: all).
Difference compare(const Render& origin, const Render& r, paper::ObjectId only = paper::sky_id) {
  Difference d;
  std::vector<double> px;
  std::size_t counted = 0, disagree = 0, colour = 0;
  for (std::size_t i = 0; i < origin.t.size(); ++i) {
    if (only != paper::sky_id && origin.seen[i] != only) continue;
    ++counted;
    const bool hit0 = origin.t[i] > 0.0f, hit = r.t[i] > 0.0f;
    if (hit0 != hit || origin.seen[i] != r.seen[i]) ++disagree;
    if (hit0 && hit) px.push_back(std::abs(double(r.t[i]) - origin.t[i]) / (double(origin.pixel_angle) * origin.t[i]));
    for (int k = 0; k < 4; ++k) {
      if (std::abs(int(r.rgba[4 * i + k]) - int(origin.rgba[4 * i + k])) > 8) {
        ++colour;
        break;
      }
    }
  }
  d.both = px.size();
  if (!px.empty()) {
    std::nth_element(px.begin(), px.begin() + px.size() / 2, px.end());
    d.median_px = px[px.size() / 2];
  } else {
    d.median_px = std::numeric_limits<double>::infinity();
  }
  d.disagree = counted ? double(disagree) / counted : 1.0;
  d.colour = counted ? double(colour) / counted : 1.0;
  return d;
}

}  // namespace

TEST_CASE("paper world: 1e5 and 1e6 from the origin, drawn relative to the camera, match the scene at the origin") {
  TestContext t;
  const Render origin = render(t.ctx, {}), bulb_origin = render(t.ctx, {}, View::bulb_at_1080p);
  for (const double distance : {1e5, 1e6}) {
    const paper::World world = paper::World::at(distance * direction);
    INFO("distance " << distance);
    // Every object, the light and the checker (colour): nothing missed the origin.
    const Difference all = compare(origin, render(t.ctx, world));
    CHECK(all.both > width * height / 2);
    CHECK(all.median_px <= 0.1);
    CHECK(all.disagree <= 0.01);
    CHECK(all.colour <= 0.02);
    // The Mandelbulb at 1080p's footprint: the object the issue measured 5.8 px off without the re-origin.
    const Difference bulb = compare(bulb_origin, render(t.ctx, world, View::bulb_at_1080p), paper::mandelbulb_id);
    CHECK(bulb.both > width * height / 4);
    CHECK(bulb.median_px <= 0.1);
    CHECK(bulb.disagree <= 0.02);
    MESSAGE("distance " << distance << ": whole view median " << all.median_px << " px, disagree " << all.disagree
                        << ", colour " << all.colour << "; Mandelbulb at 1080p median " << bulb.median_px << " px, disagree "
                        << bulb.disagree);
  }
}

TEST_CASE("paper world: without the re-origin the scene at 1e6 is pixels off (what the first test guards)") {
  TestContext t;
  const Render origin = render(t.ctx, {}, View::bulb_at_1080p);
  const Render raw = render(t.ctx, paper::World::at(1e6 * direction, paper::Reorigin::off), View::bulb_at_1080p);
  const Difference bulb = compare(origin, raw, paper::mandelbulb_id);
  MESSAGE("raw floats at 1e6: Mandelbulb at 1080p median " << bulb.median_px << " px, disagree " << bulb.disagree);
  CHECK((bulb.median_px > 1.0 || bulb.disagree > 0.1));
}

TEST_CASE("bad input: a scene placed at a non-finite offset is refused, naming paper::World::at and the fix") {
  const double inf = std::numeric_limits<double>::infinity();
  CHECK_THROWS_WITH_AS(paper::World::at({0.0, inf, 0.0}), doctest::Contains("paper::World::at: offset"), UsageError);
  CHECK_THROWS_WITH_AS(paper::World::at({0.0, inf, 0.0}, paper::Reorigin::off), doctest::Contains("pass a finite world position"),
                       UsageError);
}
