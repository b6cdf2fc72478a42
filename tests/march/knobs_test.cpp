// march/knobs.hpp: names in and out, and validate's messages for every bad knob.
#include <proceduray/march/knobs.hpp>
#include <proceduray/march/primitives.hpp>

#include <doctest/doctest.h>

#include <cstring>
#include <limits>
#include <string>

using namespace proceduray;

namespace {

const MarchCapabilities& sdf = sdf_capabilities();

MarchKnobs with(const char* name, const char* value, MarchKnobs k = march_base_knobs) {
  set_knob(k, name, value);
  return k;
}

}  // namespace

TEST_CASE("march knobs - every knob round-trips through its text") {
  MarchKnobs a = march_base_knobs;
  const MarchKnobs b{MarchMethod::fixed, 77u, MarchThreshold::absolute, 0.125f, 2.5e-3f, 0.75f, 1.5f, 33u, 0u,
                     MarchNormal::tetrahedral, 0.5f, 9u, MarchIterations::by_distance, 0.03f};
  for (const auto& [name, value] : knob_values(b)) set_knob(a, name, value);
  CHECK(std::memcmp(&a, &b, sizeof a) == 0);
  CHECK(knob_values(b).size() == march_knob_names.size());
  for (std::size_t i = 0; i < march_knob_names.size(); ++i) CHECK(knob_values(b)[i].first == march_knob_names[i]);
  CHECK(describe(b).find("method=fixed max_steps=77 threshold_mode=absolute threshold=0.125") == 0);
  CHECK(with("refine", "off").refine == 0);
  CHECK(with("refine", "on", with("refine", "off")).refine == 1);
  CHECK(with("refine", "classic").refine == 2);  // the classic rule, a method on the charts
  CHECK(describe(with("refine", "classic")).find("refine=classic") != std::string::npos);
}

TEST_CASE("march knobs - unknown names and values list the valid ones") {
  MarchKnobs k = march_base_knobs;
  CHECK_THROWS_WITH_AS(set_knob(k, "stepz", "3"),
                       doctest::Contains("unknown knob 'stepz'; valid: method, max_steps, threshold_mode"), UsageError);
  CHECK_THROWS_WITH_AS(set_knob(k, "method", "marching"),
                       doctest::Contains("unknown method 'marching'; valid: sphere, relaxed, lipschitz, segment, fixed"),
                       UsageError);
  CHECK_THROWS_WITH_AS(set_knob(k, "normal", "sobel"), doctest::Contains("valid: analytic, central, tetrahedral"),
                       UsageError);
  CHECK_THROWS_WITH_AS(set_knob(k, "max_steps", "-3"), doctest::Contains("max_steps '-3' is not a whole number"),
                       UsageError);
  CHECK_THROWS_WITH_AS(set_knob(k, "threshold", "half"), doctest::Contains("threshold 'half' is not a number"),
                       UsageError);
  CHECK_THROWS_WITH_AS(set_knob(k, "refine", "maybe"), doctest::Contains("valid: on, off"), UsageError);
  CHECK(k.max_steps == march_base_knobs.max_steps);  // a refused value changes nothing
}

TEST_CASE("march knobs - validate names the geometry, the knob, the value and the range") {
  CHECK_NOTHROW(validate(march_base_knobs, sdf, "cog"));
  struct Bad {
    const char* knob;
    const char* value;
    const char* message;
  };
  const Bad bad[] = {
      {"max_steps", "0", "max_steps 0 is out of range; give 1 to 65536"},
      {"threshold", "-0.5", "threshold -0.5 must be a positive number (pixel footprints"},
      {"threshold", "0", "threshold 0 must be a positive number"},
      {"threshold", "nan", "threshold nan must be a positive number"},
      {"relaxation", "2", "relaxation 2 must be in [1, 2)"},
      {"relaxation", "0.9", "relaxation 0.9 must be in [1, 2)"},
      {"step_scale", "0", "step_scale 0 must be in [1/1024, 1]"},
      {"step_scale", "1e-30", "step_scale 1e-30 must be in [1/1024, 1]"},
      {"step_scale", "1.5", "step_scale 1.5 must be in [1/1024, 1]"},
      {"epsilon", "-1", "epsilon -1 must be >= 0"},
      {"method", "segment", "method segment does not apply; valid: relaxed, lipschitz, sphere, fixed"},
      {"normal", "analytic", "normal analytic does not apply; valid: central, tetrahedral"},
      {"normal_scale", "0", "normal_scale 0 must be in (0, 64]"},
      {"iteration_mode", "by_distance", "iteration_mode by_distance needs a fractal"},
      {"probe", "0.5", "probe 0.5 must be in [1, 8] distances"},
      {"probe", "9", "probe 9 must be in [1, 8] distances"},
      {"probe", "inf", "probe inf must be in [1, 8] distances"},
  };
  for (const Bad& b : bad) {
    CAPTURE(b.knob);
    CAPTURE(b.value);
    CHECK_THROWS_WITH_AS(validate(with(b.knob, b.value), sdf, "cog"),
                         doctest::Contains((std::string("march knobs of 'cog' (sdf): ") + b.message).c_str()), UsageError);
  }
  MarchKnobs fixed = with("method", "fixed");
  fixed.fixed_steps = fixed.max_steps;
  CHECK_THROWS_WITH_AS(validate(fixed, sdf, "cog"), doctest::Contains("fixed_steps 512 must be in [1, max_steps) = [1, 512)"),
                       UsageError);
  fixed.fixed_steps = 0;
  CHECK_THROWS_AS(validate(fixed, sdf, "cog"), UsageError);
  MarchKnobs bad_enum = march_base_knobs;
  bad_enum.threshold_mode = static_cast<MarchThreshold>(7);
  CHECK_THROWS_WITH_AS(validate(bad_enum, sdf, "cog"), doctest::Contains("threshold_mode 7 is unknown; valid: footprint, absolute"),
                       UsageError);
  bad_enum = march_base_knobs;
  bad_enum.refine = 3;
  CHECK_THROWS_WITH_AS(validate(bad_enum, sdf, "cog"), doctest::Contains("refine 3 must be 0 (off), 1 (on) or 2 (classic)"),
                       UsageError);
  const MarchCapabilities analytic{"analytic", {}, {MarchNormal::analytic}, 0, march_base_knobs};
  CHECK_THROWS_WITH_AS(validate(march_base_knobs, analytic, "box"), doctest::Contains("not marched (analytic)"), UsageError);
}

TEST_CASE("march knobs - fractal iterations are checked against the fractal's range") {
  const MarchCapabilities bulb = fractal_capabilities(8);
  CHECK_NOTHROW(validate(bulb.defaults, bulb, "mandelbulb"));
  CHECK_THROWS_WITH_AS(validate(with("iterations", "0", bulb.defaults), bulb, "mandelbulb"),
                       doctest::Contains("iterations 0 must be in [1, 16]"), UsageError);
  CHECK_THROWS_WITH_AS(validate(with("iterations", "17", bulb.defaults), bulb, "mandelbulb"),
                       doctest::Contains("iterations 17 must be in [1, 16]"), UsageError);
  MarchKnobs far = with("iteration_mode", "by_distance", bulb.defaults);
  CHECK_NOTHROW(validate(far, bulb, "mandelbulb"));
  far.iteration_detail = 0.0f;
  CHECK_THROWS_WITH_AS(validate(far, bulb, "mandelbulb"), doctest::Contains("iteration_detail 0 must be a positive world size"),
                       UsageError);
  CHECK_THROWS_WITH_AS(validate(with("method", "lipschitz", bulb.defaults), bulb, "mandelbulb"),
                       doctest::Contains("valid: sphere, relaxed, fixed"), UsageError);
}

TEST_CASE("march knobs no geometry can take are refused wherever they go to a shader") {
  // proceduray_validate is what the renderer runs on every uniform, storage buffer and push
  // constant block holding MarchKnobs (shader/value_check.hpp): limits that keep a frame finite.
  static_assert(type_ops<MarchKnobs>.checked);
  MarchKnobs k = march_base_knobs;
  CHECK_NOTHROW(proceduray_validate(k, "knobs"));
  k.max_steps = 0xFFFFFFFFu;
  CHECK_THROWS_WITH_AS(proceduray_validate(k, "knobs"), doctest::Contains("knobs: max_steps 4294967295 is out of range; give 1 to 65536"),
                       UsageError);
  k.max_steps = march_max_steps_limit;
  CHECK_NOTHROW(proceduray_validate(k, "knobs"));
  k.step_scale = 1e-30f;
  CHECK_THROWS_WITH_AS(proceduray_validate(k, "knobs"), doctest::Contains("step_scale 1e-30 must be in [1/1024, 1]"), UsageError);
  k.step_scale = march_min_step_scale;
  CHECK_NOTHROW(proceduray_validate(k, "knobs"));
  k.iterations = march_max_iterations_limit + 1;
  CHECK_THROWS_WITH_AS(proceduray_validate(k, "knobs"), doctest::Contains("iterations 65 is past 64"), UsageError);
  k.iterations = 8;
  k.method = static_cast<MarchMethod>(9);
  CHECK_THROWS_WITH_AS(proceduray_validate(k, "knobs"),
                       doctest::Contains("method 9 is unknown; valid: sphere, relaxed, lipschitz, segment, fixed"), UsageError);
  k.method = MarchMethod::sphere;
  k.normal = static_cast<MarchNormal>(3);
  CHECK_THROWS_WITH_AS(proceduray_validate(k, "knobs"), doctest::Contains("normal 3 is unknown"), UsageError);
  k.normal = MarchNormal::central;
  k.iteration_detail = std::numeric_limits<float>::quiet_NaN();
  CHECK_THROWS_WITH_AS(proceduray_validate(k, "knobs"), doctest::Contains("iteration_detail nan must be a world size >= 0"),
                       UsageError);
}
