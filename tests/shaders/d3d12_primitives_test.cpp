// Tests for the D3D12 sample's primitives in shaders/ (box.glsl, spheres.glsl, metaballs.glsl,
// sdf.glsl, d3d12_primitives.glsl), compiled as C++: hits where the closed form says, axis-parallel
// and inside-origin rays, cull bits, the two metaball marches agreeing, Lipschitz bounds holding,
// the AABB clip, and no NaN over many rays and degenerate parameters.
#include <proceduray/shader/glsl_cpp.hpp>

namespace d3d12_primitives_test {
using namespace proceduray::glsl_cpp;
#include "primitives/d3d12_primitives.glsl"
}  // namespace d3d12_primitives_test

#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace d3d12_primitives_test;

namespace {

MarchSettings settings() { return MarchSettings{512u, 1e-4f, 0.0f, 1.0f, 1.0f}; }

glm::vec4 default_params(std::uint32_t kind) {
  if (kind == primitive_box) return {0.6f, 0.6f, 0.6f, 0.0f};
  if (kind == primitive_metaballs) return {0.6f, 0.25f, 0.0f, 0.0f};
  if (kind == sdf_twisted_torus) return {1.0f, 3.0f, 0.0f, 0.0f};
  if (kind == sdf_fractal_pyramid) return {1.0f, 4.0f, 0.0f, 0.0f};
  return {1.0f, 0.0f, 0.0f, 0.0f};
}

struct Hit {
  bool found = false;
  float t = 0, steps = 0;
  glm::vec3 n{0.0f};
};

Hit intersect(std::uint32_t kind, glm::vec3 o, glm::vec3 d, std::uint32_t cull = 0u, float t_lo = 0.0f,
              float t_hi = 1e30f, std::uint32_t method = metaball_method_fixed, glm::vec4 params = glm::vec4(-1.0f)) {
  Hit h;
  if (params.x < 0.0f) params = default_params(kind);
  h.found = d3d12_intersect(kind, params, 0.0f, 0.0f, o, d, t_lo, t_hi, cull, settings(), method, 128u, d3d12_sdf_march_default(), h.t, h.n,
                            h.steps);
  return h;
}

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

TEST_CASE("box hits its face with the axis normal and leaves from inside") {
  const Hit h = intersect(primitive_box, {0.1f, 0.2f, -5.0f}, {0.0f, 0.0f, 2.0f});
  REQUIRE(h.found);
  CHECK(h.t == doctest::Approx((5.0f - 0.6f) / 2.0f));
  CHECK(h.n == glm::vec3(0.0f, 0.0f, -1.0f));
  const Hit inside = intersect(primitive_box, {0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f});
  REQUIRE(inside.found);
  CHECK(inside.t == doctest::Approx(0.6f));
  CHECK(inside.n == glm::vec3(1.0f, 0.0f, 0.0f));
  // The exit is back facing: culling back faces leaves nothing for a ray from inside.
  CHECK_FALSE(intersect(primitive_box, {0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, hit_cull_back).found);
  // Culling front faces skips the entry and reports the exit.
  const Hit back = intersect(primitive_box, {0.1f, 0.2f, -5.0f}, {0.0f, 0.0f, 1.0f}, hit_cull_front);
  REQUIRE(back.found);
  CHECK(back.t == doctest::Approx(5.6f));
}

TEST_CASE("SDF primitives from inside report the exit as the box does") {
  // sphere_trace marches the negated distance from inside: the exit, back facing, so the cull
  // bits treat a marched primitive as they treat the closed forms.
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (std::uint32_t kind = sdf_mini_spheres; kind <= sdf_fractal_pyramid; ++kind) {
    CAPTURE(kind);
    std::size_t tried = 0, exits = 0;
    for (int i = 0; i < 2000 && tried < 40; ++i) {
      const glm::vec3 o(0.9f * u(rng), 0.9f * u(rng), 0.9f * u(rng));
      if (!(sdf_distance(kind, o, default_params(kind)) < -0.01f)) continue;
      ++tried;
      const glm::vec3 d = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + glm::vec3(1e-3f));
      const Hit h = intersect(kind, o, d);
      REQUIRE(h.found);
      exits += h.t > 0.0f && glm::dot(h.n, d) > 0.0f;
      // Within the refinement of the crossing, from the inside: -threshold/32 < distance < 0.
      const float at = sdf_distance(kind, o + h.t * d, default_params(kind));
      CHECK(at <= 0.0f);
      CHECK(at > -1e-4f);
      CHECK_FALSE(intersect(kind, o, d, hit_cull_back).found);
    }
    CHECK(tried >= 20);
    CHECK(exits == tried);
  }
}

TEST_CASE("box slab test needs no infinities for zero and signed zero directions") {
  // Exactly axis-parallel with -0 components, origin on a slab plane: a hit, finite values.
  const Hit on_plane = intersect(primitive_box, {0.6f, 0.0f, -3.0f}, {-0.0f, -0.0f, 1.0f});
  CHECK(on_plane.found);
  CHECK(std::isfinite(on_plane.t));
  CHECK_FALSE(intersect(primitive_box, {0.7f, 0.0f, -3.0f}, {0.0f, 0.0f, 1.0f}).found);
  const Hit denormal = intersect(primitive_box, {0.0f, 0.0f, -3.0f}, {1e-40f, -1e-40f, 1.0f});
  REQUIRE(denormal.found);
  CHECK(denormal.t == doctest::Approx(2.4f));
}

TEST_CASE("several spheres report the nearest sphere with a radial normal") {
  // Along +z through sphere 1's centre (0.1, 0.1, 0.4) radius 0.3: it lies in front of sphere 0.
  const Hit h = intersect(primitive_spheres, {0.1f, 0.1f, 5.0f}, {0.0f, 0.0f, -1.0f});
  REQUIRE(h.found);
  CHECK(h.t == doctest::Approx(5.0f - 0.7f));
  CHECK(h.n.z == doctest::Approx(1.0f));
  // t range: with t_hi before the surface there is no hit.
  CHECK_FALSE(intersect(primitive_spheres, {0.1f, 0.1f, 5.0f}, {0.0f, 0.0f, -1.0f}, 0u, 0.0f, 4.0f).found);
}

TEST_CASE("metaball fixed and Lipschitz marches find the same surface") {
  for (float y : {-0.25f, 0.0f, 0.3f}) {
    const Hit fixed = intersect(primitive_metaballs, {-0.3f, y, -3.0f}, {0.0f, 0.0f, 1.0f});
    const Hit lipschitz =
        intersect(primitive_metaballs, {-0.3f, y, -3.0f}, {0.0f, 0.0f, 1.0f}, 0u, 0.0f, 1e30f, metaball_method_lipschitz);
    CAPTURE(y);
    REQUIRE(fixed.found == lipschitz.found);
    if (!fixed.found) continue;
    CHECK(fixed.t == doctest::Approx(lipschitz.t).epsilon(2e-3));
    // On the isosurface, and the normal faces the ray.
    CHECK(metaball_field(glm::vec3(-0.3f, y, -3.0f + fixed.t), 0.6f, 0.0f) == doctest::Approx(0.25f).epsilon(0.02));
    CHECK(fixed.n.z < 0.0f);
    CHECK(lipschitz.steps > 0.0f);
  }
}

TEST_CASE("metaball marches agree on coverage with a footprint threshold") {
  // A coarse threshold (as far pixels get): the Lipschitz march must not accept near misses.
  MarchSettings m = settings();
  m.footprint = 0.01f;
  std::size_t fixed_hits = 0, lipschitz_hits = 0, differ = 0;
  for (int y = 0; y < 40; ++y) {
    for (int x = 0; x < 40; ++x) {
      const glm::vec3 o(-1.0f + 0.05f * x, -1.0f + 0.05f * y, -4.0f);
      float s = 0.0f;
      glm::vec3 n;
      std::uint32_t steps = 0;
      const bool a = metaballs_march(o, {0.0f, 0.0f, 1.0f}, 3.0f, 5.0f, 0.6f, 0.25f, 0.0f, metaball_method_fixed, 128u,
                                     m, s, n, steps);
      const bool b = metaballs_march(o, {0.0f, 0.0f, 1.0f}, 3.0f, 5.0f, 0.6f, 0.25f, 0.0f, metaball_method_lipschitz,
                                     128u, m, s, n, steps);
      fixed_hits += a;
      lipschitz_hits += b;
      differ += a != b;
    }
  }
  CHECK(fixed_hits > 100);
  CHECK(differ <= 8);
  CHECK(std::abs(double(fixed_hits) - double(lipschitz_hits)) <= 8.0);
}

TEST_CASE("metaball falloff slope stays within the Lipschitz bound") {
  float steepest = 0.0f;
  for (int i = 0; i < 1000; ++i) {
    const float x = static_cast<float>(i) / 1000.0f, h = 1e-3f;
    steepest = std::max(steepest, std::abs(metaball_falloff(x + h) - metaball_falloff(x)) / h);
  }
  CHECK(steepest <= 1.875f + 1e-3f);
  CHECK(steepest >= 1.85f);  // and the bound is tight
  CHECK(metaball_falloff(1.0f) == 0.0f);
  CHECK(metaball_falloff(0.0f) == 1.0f);
}

TEST_CASE("SDF distances respect their Lipschitz bounds") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (std::uint32_t kind = sdf_mini_spheres; kind < primitive_kind_count; ++kind) {
    const glm::vec4 params = default_params(kind);
    float worst = 0.0f;
    for (int i = 0; i < 4000; ++i) {
      const glm::vec3 p(u(rng), u(rng), u(rng));
      const glm::vec3 q = p + 0.01f * glm::vec3(u(rng), u(rng), u(rng));
      const float ratio = std::abs(sdf_distance(kind, p, params) - sdf_distance(kind, q, params)) / glm::length(p - q);
      worst = std::max(worst, ratio);
    }
    CAPTURE(kind);
    // Sampled slopes: the fold seams of the pyramid and repetition cells may jump; the rest are bounded.
    if (kind != sdf_fractal_pyramid) CHECK(worst <= sdf_lipschitz(kind, params) * 1.01f);
    CHECK(worst > 0.1f);
  }
}

namespace {
/// Centres of the pyramid's 5^levels smallest copies: points of the solid fractal.
void pyramid_leaf_centres(glm::vec3 offset, float scale, int levels, std::vector<glm::vec3>& out) {
  if (levels == 0) {
    out.push_back(offset + scale * glm::vec3(0.0f, -0.5f, 0.0f));
    return;
  }
  for (int k = 0; k < 5; ++k) pyramid_leaf_centres(offset + 0.5f * scale * sdf_pyramid_vertex(k), 0.5f * scale, levels - 1, out);
}
}  // namespace

TEST_CASE("fractal pyramid distance never exceeds the distance to its solid") {
  // A step of this size never crosses the surface, at fold seams too (following one copy only failed here).
  std::vector<glm::vec3> centres;
  pyramid_leaf_centres(glm::vec3(0.0f), 1.0f, 4, centres);
  REQUIRE(centres.size() == 625);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1.2f, 1.2f);
  std::size_t over = 0;
  for (int i = 0; i < 3000; ++i) {
    const glm::vec3 p(u(rng), u(rng), u(rng));
    float nearest = 1e30f;
    for (const glm::vec3& c : centres) nearest = std::min(nearest, glm::length(p - c));
    over += sdf_fractal_pyramid_distance(p, 4u) > nearest + 1e-5f;
  }
  CHECK(over == 0);
  CHECK(sdf_lipschitz(sdf_fractal_pyramid, glm::vec4(1.0f, 4.0f, 0.0f, 0.0f)) == 1.0f);
}

TEST_CASE("every primitive reports hits inside its own AABB only") {
  // Rays that enter [-1, 1]^3 near a corner, where no primitive reaches, and rays from outside
  // the box towards it that pass beside it (as a driver's enlarged AABB would still invoke).
  for (std::uint32_t kind = 0; kind < primitive_kind_count; ++kind) {
    CAPTURE(kind);
    CHECK_FALSE(intersect(kind, {0.99f, 0.99f, -5.0f}, {0.0f, 0.0f, 1.0f}).found);
    CHECK_FALSE(intersect(kind, {1.05f, 0.0f, -5.0f}, {0.0f, 0.0f, 1.0f}).found);
    CHECK_FALSE(intersect(kind, {0.0f, -1.02f, -5.0f}, {0.0f, 0.0f, 1.0f}).found);
  }
}

TEST_CASE("every primitive is hit through its centre and gives finite unit normals everywhere") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (std::uint32_t kind = 0; kind < primitive_kind_count; ++kind) {
    CAPTURE(kind);
    std::size_t hits = 0, bad = 0;
    for (int i = 0; i < 400; ++i) {
      const glm::vec3 o = 3.0f * glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + glm::vec3(0.0f, 0.0f, 1e-3f));
      const glm::vec3 target(0.8f * u(rng), 0.8f * u(rng), 0.8f * u(rng));
      const Hit h = intersect(kind, o, target - o);
      if (!h.found) continue;
      ++hits;
      const glm::vec3 p = o + h.t * (target - o);
      bad += !finite(h.n) || std::abs(glm::length(h.n) - 1.0f) > 1e-3f || !std::isfinite(h.t) ||
             glm::any(glm::greaterThan(glm::abs(p), glm::vec3(1.0f + 1e-4f)));
    }
    CHECK(hits > 20);
    CHECK(bad == 0);
  }
}

TEST_CASE("degenerate parameters give misses not NaN") {
  Hit h = intersect(primitive_metaballs, {0.0f, 0.0f, -3.0f}, {0.0f, 0.0f, 1.0f}, 0u, 0.0f, 1e30f,
                    metaball_method_fixed, {0.0f, 0.25f, 0.0f, 0.0f});
  CHECK_FALSE(h.found);
  h = intersect(primitive_spheres, {0.0f, 0.0f, -3.0f}, {0.0f, 0.0f, 1.0f}, 0u, 0.0f, 1e30f, 0u, glm::vec4(0.0f));
  CHECK_FALSE(h.found);
  h = intersect(primitive_box, {0.0f, 0.0f, -3.0f}, {0.0f, 0.0f, 1.0f}, 0u, 0.0f, 1e30f, 0u, {-0.5f, 0.5f, 0.5f, 0.0f});
  CHECK(std::isfinite(h.t));
  CHECK_FALSE(intersect(sdf_cog, {0.0f, 0.0f, -3.0f}, {0.0f, 0.0f, 0.0f}).found);  // zero direction
  CHECK(std::isfinite(sdf_distance(sdf_cog, glm::vec3(0.0f), default_params(sdf_cog))));
  CHECK(std::isfinite(sdf_length8(glm::vec2(0.0f))));
}

TEST_CASE("spin turns a primitive about y in local space") {
  float t0, t1, steps0, steps1;
  glm::vec3 n0, n1;
  const glm::vec4 params = default_params(sdf_cog);
  // Still, a ray along -x meets the tooth on +x (outer face 0.92 from the axis); turned by half
  // a tooth spacing (15 degrees) it passes between two teeth to the disc (radius 0.7).
  const bool a = d3d12_intersect(sdf_cog, params, 0.0f, 0.0f, {3.0f, 0.0f, 0.0f}, {-1.0f, 0.0f, 0.0f}, 0.0f, 1e30f,
                                 0u, settings(), 0u, 128u, d3d12_sdf_march_default(), t0, n0, steps0);
  const bool b = d3d12_intersect(sdf_cog, params, 0.2617994f, 1.0f, {3.0f, 0.0f, 0.0f}, {-1.0f, 0.0f, 0.0f}, 0.0f,
                                 1e30f, 0u, settings(), 0u, 128u, d3d12_sdf_march_default(), t1, n1, steps1);
  REQUIRE(a);
  REQUIRE(b);
  CHECK(rotate_y(glm::vec3(1.0f, 0.0f, 0.0f), 1.5707964f).z == doctest::Approx(-1.0f));
  CHECK(t0 == doctest::Approx(3.0f - 0.92f).epsilon(1e-3));
  CHECK(t1 == doctest::Approx(3.0f - 0.7f).epsilon(1e-3));
  CHECK(n0.x == doctest::Approx(1.0f).epsilon(1e-2));
  CHECK(n1.x == doctest::Approx(1.0f).epsilon(1e-2));
}
