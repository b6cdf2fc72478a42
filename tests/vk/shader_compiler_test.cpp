#include <proceduray/vk/shader_compiler.hpp>

#include <doctest/doctest.h>

#include <string>

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
                       doctest::Contains("/nonexistent/x.rmiss"), std::runtime_error);
}

TEST_CASE("compile_glsl names a shader without an entry point") {
  CHECK_THROWS_WITH_AS(compile_glsl({.stage = ShaderStage::miss,
                                     .name = "no_main.rmiss",
                                     .code = "#version 460\n#extension GL_EXT_ray_tracing : require\n"
                                             "void shade() {}\n"}),
                       doctest::Contains("no_main.rmiss"), ShaderCompileError);
}
