// Tests for proceduray/shader/counted_float.hpp: known expressions count what they do, GLM's
// templates and a mirrored GLSL primitive take the type, and the value is the float's.
#include <proceduray/march/primitives_glsl.hpp>
#include <proceduray/shader/counted_float.hpp>

#include <doctest/doctest.h>

#include <cstdint>

using proceduray::CountedFloat;
using V3 = glm::vec<3, CountedFloat>;

TEST_CASE("counted float: arithmetic counts 1 per operation, comparisons and negation nothing") {
  CountedFloat::reset();
  const CountedFloat a(2.0f), b(3.0f);
  const CountedFloat c = a * b + a;  // 2
  CHECK(c.value() == 8.0f);
  CHECK(CountedFloat::count() == 2u);
  CHECK(a < b);
  CHECK((-a).value() == -2.0f);
  CHECK(CountedFloat::count() == 2u);
  CHECK(sqrt(CountedFloat(16.0f)).value() == 4.0f);
  CHECK(CountedFloat::count() == 3u);
}

TEST_CASE("counted float: GLM's length is 3 products, 2 sums and a root") {
  CountedFloat::reset();
  const CountedFloat r = glm::length(V3(1.0f, 2.0f, 2.0f));
  CHECK(r.value() == 3.0f);
  CHECK(CountedFloat::count() == 6u);
}

TEST_CASE("counted float: the Mandelbulb's estimate, counted from its code, follows its orbit") {
  using Bulb = proceduray::glsl::mandelbulb<CountedFloat>;
  // Outside the bailout: no iteration; length (6) and 0.5 r log(r) / dr (2 *, log, /): 10.
  CountedFloat::reset();
  const CountedFloat far = Bulb::mandelbulb_distance(V3(3.0f, 0.0f, 0.0f), 8u);
  CHECK(CountedFloat::count() == 10u);
  CHECK(far.value() == doctest::Approx(proceduray::glsl::mandelbulb<float>::mandelbulb_distance(glm::vec3(3, 0, 0), 8u)));
  // Inside: all 8 iterations, each the same work, so the count grows by the same step per iteration.
  std::uint64_t counts[3] = {};
  for (std::uint32_t n = 1; n <= 3; ++n) {
    CountedFloat::reset();
    Bulb::mandelbulb_distance(V3(0.1f, 0.2f, 0.1f), n);
    counts[n - 1] = CountedFloat::count();
  }
  CHECK(counts[1] - counts[0] == counts[2] - counts[1]);
  CHECK(counts[1] - counts[0] > 40u);  // a power-8 step: three complex squarings twice, lengths, a division
}
