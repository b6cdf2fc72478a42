// Tests for shaders/shading/whitted.glsl, compiled as C++: the scene's shadow and reflection
// rays are stand-ins that count their calls.
#include <proceduray/shader/glsl_cpp.hpp>

namespace whitted_test {
using namespace proceduray::glsl_cpp;
int shadow_rays = 0, reflection_rays = 0;
float occlusion = 1.0f;                      // what the shadow ray finds: 1 lit, 0 blocked
glm::vec3 mirrored{0.0f}, reflected_from{0.0f};  // the reflection ray's direction and origin
float reflected_weight = 0.0f;
// Defined first: at namespace scope C++ needs them before whitted.glsl's calls.
static inline float whitted_visibility(glm::vec3, glm::vec3, float) {
  ++shadow_rays;
  return occlusion;
}
static inline glm::vec3 whitted_reflection(glm::vec3 origin, glm::vec3 direction, float weight) {
  ++reflection_rays;
  reflected_from = origin;
  mirrored = direction;
  reflected_weight = weight;
  return glm::vec3(0.0f, 0.0f, 1.0f);  // blue
}
#include "shading/whitted.glsl"
}  // namespace whitted_test

#include <doctest/doctest.h>

using namespace whitted_test;

namespace {
const glm::vec3 up(0, 1, 0);
const WhittedMaterial grey{glm::vec3(0.5f), 1.0f, 0.0f, 1.0f, 0.0f};
void reset() {
  shadow_rays = reflection_rays = 0;
  occlusion = 1.0f;
}
}  // namespace

TEST_CASE("whitted direct light is Phong when lit, 0 when the shadow ray is blocked, and traces none from behind") {
  reset();
  const glm::vec3 lit = whitted_direct(glm::vec3(0), up, up, up, 5.0f, glm::vec3(1.0f), grey, true);
  CHECK(lit.x == doctest::Approx(0.5f));  // diffuse 1 * n.l 1 * albedo 0.5
  CHECK(shadow_rays == 1);
  occlusion = 0.0f;
  CHECK(whitted_direct(glm::vec3(0), up, up, up, 5.0f, glm::vec3(1.0f), grey, true).x == 0.0f);
  CHECK(shadow_rays == 2);
  // A light below the surface: dark, and no ray spent finding out.
  CHECK(whitted_direct(glm::vec3(0), up, up, -up, 5.0f, glm::vec3(1.0f), grey, true).x == 0.0f);
  CHECK(shadow_rays == 2);
  // Shadows off: Phong, no ray.
  occlusion = 0.0f;
  CHECK(whitted_direct(glm::vec3(0), up, up, up, 5.0f, glm::vec3(1.0f), grey, false).x == doctest::Approx(0.5f));
  CHECK(shadow_rays == 2);
  CHECK(whitted_phong(up, up, up, glm::vec3(1.0f), grey) == lit);
}

TEST_CASE("whitted reflection is traced only when it adds at least min_weight, and mixed by f") {
  reset();
  const WhittedMaterial mirror{glm::vec3(1.0f), 1.0f, 0.0f, 1.0f, 0.5f};
  const glm::vec3 n = up, v = glm::normalize(glm::vec3(1, 1, 0));
  const float f = whitted_fresnel(mirror, n, v);
  CHECK(f > 0.5f);  // above f0 off normal incidence
  CHECK(whitted_fresnel(grey, n, v) == 0.0f);  // no reflectance: no reflection
  const glm::vec3 red(1, 0, 0);
  const glm::vec3 c = whitted_reflect(red, glm::vec3(1, 2, 3), n, v, f, 1.0f, 0.01f);
  CHECK(reflection_rays == 1);
  CHECK(c.x == doctest::Approx(1.0f - f));
  CHECK(c.z == doctest::Approx(f));
  CHECK(mirrored.x == doctest::Approx(-v.x));  // reflect(-v, n) mirrors v about n
  CHECK(mirrored.y == doctest::Approx(v.y));
  CHECK(reflected_from == glm::vec3(1, 2, 3));
  CHECK(reflected_weight == doctest::Approx(f));
  // Deep enough that the reflection would add under min_weight: not traced, colour kept.
  CHECK(whitted_reflect(red, glm::vec3(0), n, v, f, 0.001f, 0.01f) == red);
  CHECK(whitted_reflect(red, glm::vec3(0), n, v, 0.0f, 1.0f, 0.0f) == red);
  CHECK(reflection_rays == 1);
}

TEST_CASE("whitted facing turns the normal to the viewer's side") {
  CHECK(whitted_facing(up, up) == up);
  CHECK(whitted_facing(up, -up) == -up);
}
