// scene/outputs_glsl.hpp: each output's image and helper, or an empty macro.
#include <proceduray/scene/outputs_glsl.hpp>

#include <doctest/doctest.h>

#include <string>
#include <vector>

using namespace proceduray;

namespace {
bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }
}  // namespace

TEST_CASE("outputs_glsl declares an asked-for output's image with its format and helper") {
  const std::vector<PlannedOutput> planned{{Output::t, 3}, {Output::normal, 4}, {Output::ids, 5}, {Output::steps, 6},
                                           {Output::flags, 7}};
  const std::string text = glsl_outputs(planned);
  CHECK(has(text, "layout(set = 0, binding = 3, r32f) uniform image2D output_t_image;\n"));
  CHECK(has(text, "layout(set = 0, binding = 4, rgba32f) uniform image2D output_normal_image;\n"));
  CHECK(has(text, "layout(set = 0, binding = 5, rgba32ui) uniform uimage2D output_ids_image;\n"));
  CHECK(has(text, "layout(set = 0, binding = 6, r32ui) uniform uimage2D output_steps_image;\n"));
  CHECK(has(text, "void output_steps(uint v) { imageAtomicAdd(output_steps_image, ivec2(gl_LaunchIDEXT.xy), v); }"));
  CHECK(has(text, "void output_flags(uint v) { imageAtomicOr(output_flags_image, ivec2(gl_LaunchIDEXT.xy), v); }"));
  CHECK(has(text, "#define output_flag_exhausted " + std::to_string(output_flag_exhausted) + "u\n"));
  CHECK_FALSE(has(text, "#define output_t(v)"));
}

TEST_CASE("outputs_glsl gives empty macros for outputs not asked for") {
  const std::vector<PlannedOutput> planned{{Output::steps, 2}};
  const std::string text = glsl_outputs(planned);
  for (const char* helper : {"output_t", "output_normal", "output_ids", "output_flags"}) {
    CHECK(has(text, std::string("#define ") + helper + "(v)\n"));
  }
  CHECK(has(text, "void output_steps(uint v)"));
  CHECK(glsl_output_hit(planned) == "#define output_hit(n)\n");
  const std::vector<PlannedOutput> with_t{{Output::t, 2}};
  CHECK(has(glsl_output_hit(with_t), "output_t(gl_HitTEXT)"));
  CHECK_FALSE(has(glsl_outputs({}), "PROCEDURAY_OUTPUTS"));
}
