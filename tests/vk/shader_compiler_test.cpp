#include <proceduray/vk/shader_compiler.hpp>

#include <doctest/doctest.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

using namespace proceduray::vk;

TEST_CASE("compile_glsl produces SPIR-V for a miss shader") {
  const auto spirv = compile_glsl({.stage = ShaderStage::miss,
                                   .name = "ok.rmiss",
                                   .code = "#version 460\n#extension GL_EXT_ray_tracing : require\n"
                                           "layout(location = 0) rayPayloadInEXT vec3 c;\nvoid main() { c = vec3(1); }\n"});
  REQUIRE(spirv.size() > 5);
  CHECK(spirv[0] == 0x07230203u);  // SPIR-V magic number
  CHECK(spirv[1] >= 0x00010400u);  // SPIR-V 1.4 or later, which ray tracing needs
}

TEST_CASE("compile_glsl compiles a compute shader (the benchmarks' peers), GLCompute its model") {
  const auto spirv = compile_glsl({.stage = ShaderStage::compute,
                                   .name = "ok.comp",
                                   .code = "#version 460\nlayout(local_size_x = 64) in;\n"
                                           "layout(std430, binding = 0) buffer B { float v[]; };\n"
                                           "void main() { v[gl_GlobalInvocationID.x] = 1.0; }\n"});
  REQUIRE(spirv.size() > 5);
  bool compute = false;  // OpEntryPoint (15) with execution model GLCompute (5)
  detail::each_spirv_instruction(spirv, [&](std::uint32_t op, std::span<const std::uint32_t> words) {
    if (op == 15 && words.size() > 1 && words[1] == 5) compute = true;
    return true;
  });
  CHECK(compute);
  CHECK(std::string(proceduray::to_string(ShaderStage::compute)) == "compute");
  // A ray-tracing stage refuses the compute built-ins: the stage is what decides.
  CHECK_THROWS_AS(compile_glsl({.stage = ShaderStage::miss, .name = "bad.rmiss",
                                .code = "#version 460\nvoid main() { uvec3 g = gl_GlobalInvocationID; }\n"}),
                  ShaderCompileError);
}

TEST_CASE("compile_glsl reports the shader name and the error line") {
  try {
    compile_glsl({.stage = ShaderStage::closest_hit,
                  .name = "broken.rchit",
                  .code = "#version 460\n#extension GL_EXT_ray_tracing : require\n\nvoid main() {\n  undeclared = 1;\n}\n"});
    FAIL("a broken shader compiled");
  } catch (const ShaderCompileError& e) {
    CHECK(e.name() == "broken.rchit");
    CHECK(e.line() == 5);
    CHECK(e.log().find("undeclared") != std::string::npos);
    CHECK(std::string(e.what()).find("broken.rchit") != std::string::npos);
    CHECK(std::string(e.what()).find("line 5") != std::string::npos);
  }
}

TEST_CASE("compile_glsl resolves library includes") {
  const auto spirv = compile_glsl({.stage = ShaderStage::intersection,
                                   .name = "sphere.rint",
                                   .code = "#version 460\n#extension GL_EXT_ray_tracing : require\n"
                                           "#include \"primitives/sphere.glsl\"\n"
                                           "void main() { float a, b; if (ray_sphere(gl_ObjectRayOriginEXT, "
                                           "gl_ObjectRayDirectionEXT, vec3(0), 1.0, a, b)) reportIntersectionEXT(a, 0u); }\n"});
  CHECK(spirv.size() > 5);
}

TEST_CASE("compile_glsl names a missing include") {
  CHECK_THROWS_WITH_AS(compile_glsl({.stage = ShaderStage::miss,
                                     .name = "missing.rmiss",
                                     .code = "#version 460\n#extension GL_EXT_ray_tracing : require\n"
                                             "#include \"no/such/file.glsl\"\nvoid main() {}\n"}),
                       doctest::Contains("no/such/file.glsl"), ShaderCompileError);
}

TEST_CASE("compile_glsl_file names a missing file") {
  CHECK_THROWS_WITH_AS(compile_glsl_file(ShaderStage::miss, "/nonexistent/x.rmiss"),
                       doctest::Contains("/nonexistent/x.rmiss"), proceduray::EnvironmentError);
}

TEST_CASE("compile_glsl names a shader without an entry point") {
  CHECK_THROWS_WITH_AS(compile_glsl({.stage = ShaderStage::miss,
                                     .name = "no_main.rmiss",
                                     .code = "#version 460\n#extension GL_EXT_ray_tracing : require\n"
                                             "void shade() {}\n"}),
                       doctest::Contains("no_main.rmiss"), ShaderCompileError);
}

TEST_CASE("traces_rays finds OpTraceRayKHR in SPIR-V words, not OpExecuteCallableKHR") {
  // Header (magic, version, generator, bound, schema), then instructions: word count << 16 | opcode.
  const std::vector<std::uint32_t> header{0x07230203u, 0x00010400u, 0u, 10u, 0u};
  auto module = [&](std::vector<std::uint32_t> body) {
    std::vector<std::uint32_t> words = header;
    words.insert(words.end(), body.begin(), body.end());
    return words;
  };
  const std::uint32_t nop = (1u << 16) | 0u;                 // OpNop
  const std::uint32_t execute_callable = (3u << 16) | 4446u;  // OpExecuteCallableKHR %sbt %callable
  const std::uint32_t trace_ray = (12u << 16) | 4445u;        // OpTraceRayKHR with its 11 operands
  CHECK_FALSE(traces_rays(header));
  CHECK_FALSE(traces_rays(module({nop, execute_callable, 1u, 2u})));
  std::vector<std::uint32_t> traced{nop, execute_callable, 1u, 2u, trace_ray};
  traced.resize(traced.size() + 11, 0u);
  CHECK(traces_rays(module(traced)));
  // An operand that happens to equal 4445 is not an instruction.
  CHECK_FALSE(traces_rays(module({(2u << 16) | 0u, 4445u})));
  CHECK_FALSE(traces_rays(module({0u, trace_ray})));  // a zero word count stops the scan (malformed)
  CHECK_FALSE(traces_rays(std::vector<std::uint32_t>{}));
}

TEST_CASE("traces_rays on compiled shaders: a closest-hit that calls traceRayEXT, one that calls a callable") {
  const std::string prefix = "#version 460\n#extension GL_EXT_ray_tracing : require\n"
                             "layout(set = 0, binding = 0) uniform accelerationStructureEXT tlas;\n"
                             "layout(location = 0) rayPayloadInEXT vec3 c;\n";
  const auto tracing = compile_glsl({.stage = ShaderStage::closest_hit, .name = "tracing.rchit",
                                     .code = prefix + "layout(location = 1) rayPayloadEXT vec3 s;\n"
                                                      "void main() { traceRayEXT(tlas, 0, 0xFF, 0, 1, 0, vec3(0), 0.0, "
                                                      "vec3(0, 1, 0), 1.0, 1); c = s; }\n"});
  CHECK(traces_rays(tracing));
  const auto calling = compile_glsl({.stage = ShaderStage::closest_hit, .name = "calling.rchit",
                                     .code = prefix + "layout(location = 0) callableDataEXT vec3 d;\n"
                                                      "void main() { executeCallableEXT(0, 0); c = d; }\n"});
  CHECK_FALSE(traces_rays(calling));
}

TEST_CASE("trace_info names the payload variables a shader traces with, and callable calls") {
  const std::string head = "#version 460\n#extension GL_EXT_ray_tracing : require\n"
                           "layout(set = 0, binding = 0) uniform accelerationStructureEXT tlas;\n"
                           "struct P { vec4 c; };\n"
                           "layout(location = 0) rayPayloadInEXT P payload;\n"
                           "layout(location = 2) rayPayloadEXT P shadow;\n"
                           "layout(location = 0) callableDataEXT P call;\n";
  const auto traces_shadow = compile_glsl({.stage = ShaderStage::closest_hit, .name = "t.rchit", .code = head +
      "void main() { traceRayEXT(tlas, 0, 0xFF, 0, 1, 0, vec3(0), 0.0, vec3(0, 1, 0), 1.0, 2); }\n"});
  const TraceInfo a = trace_info(traces_shadow);
  CHECK(a.payloads == std::vector<std::string>{"shadow"});
  CHECK_FALSE(a.unnamed);
  CHECK_FALSE(a.calls);
  const auto both = compile_glsl({.stage = ShaderStage::closest_hit, .name = "t.rchit", .code = head +
      "void main() { traceRayEXT(tlas, 0, 0xFF, 0, 1, 0, vec3(0), 0.0, vec3(0, 1, 0), 1.0, 0);\n"
      "  traceRayEXT(tlas, 0, 0xFF, 0, 1, 0, vec3(0), 0.0, vec3(0, 1, 0), 1.0, 2);\n"
      "  executeCallableEXT(0, 0); }\n"});
  const TraceInfo b = trace_info(both);
  CHECK(b.payloads == std::vector<std::string>{"payload", "shadow"});  // the incoming payload too
  CHECK(b.calls);
  const auto none = compile_glsl({.stage = ShaderStage::closest_hit, .name = "t.rchit", .code = head + "void main() {}\n"});
  CHECK(trace_info(none).payloads.empty());
  CHECK_FALSE(trace_info(none).unnamed);
  CHECK(trace_info(std::vector<std::uint32_t>{0x07230203u, 0, 0, 0, 0, 0}).unnamed);  // a zero word count: malformed
}

TEST_CASE("compile_glsl blames an error in the preamble on the preamble, not on a line of the file") {
  // glslang numbers preamble lines as string -1; the old message said "line 4" of a 5-line file.
  try {
    compile_glsl({.stage = ShaderStage::miss, .name = "sky.rmiss",
                  .code = "#version 460\n#extension GL_EXT_ray_tracing : require\nvoid main() {\n}\n",
                  .preamble = "const uint a_ray = 0u;\nconst uint b = 1u;\nconst uint a_ray = 2u;\n"});
    FAIL("the redefinition compiled");
  } catch (const ShaderCompileError& e) {
    const std::string what = e.what();
    CHECK(what.find("shader 'sky.rmiss' failed to compile in its preamble (the generated declarations, then the extra "
                    "ones; its line 3: `const uint a_ray = 2u;`)") != std::string::npos);
    CHECK(e.line() == 0);
  }
}
