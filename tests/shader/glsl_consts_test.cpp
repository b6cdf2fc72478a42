// Tests for proceduray/shader/glsl_consts.hpp: host constants become GLSL constants under their C++ names.
#include <proceduray/shader/glsl_consts.hpp>

#include <doctest/doctest.h>

#include <cstdint>
#include <string>

namespace glsl_consts_test {
inline constexpr std::uint32_t flag_shadows = 1u, max_depth = 3u;
inline constexpr float exposure = 2.2f;
inline constexpr glm::vec3 up{0.0f, 1.0f, 0.0f};
}  // namespace glsl_consts_test

TEST_CASE("glsl consts name each constant after its C++ name in order") {
  using namespace glsl_consts_test;
  const std::string glsl = PROCEDURAY_GLSL_CONSTS(flag_shadows, max_depth, exposure, up);
  CHECK(glsl == "const uint flag_shadows = 1u;\nconst uint max_depth = 3u;\nconst float exposure = 2.2;\n"
                "const vec3 up = vec3(0.0, 1.0, 0.0);\n");
  CHECK(PROCEDURAY_GLSL_CONSTS(exposure) == proceduray::glsl_const("exposure", exposure));
}
