// march/primitives.hpp: each shipped geometry's defaults are valid settings of its own methods.
#include <proceduray/march/primitives.hpp>

#include <doctest/doctest.h>

#include <algorithm>

using namespace proceduray;

TEST_CASE("march primitives - defaults validate and use the first listed method and normal") {
  for (const MarchCapabilities& caps : {sdf_capabilities(), metaball_capabilities(), fractal_capabilities(8)}) {
    CAPTURE(caps.kind);
    CHECK_NOTHROW(validate(caps.defaults, caps, "default"));
    CHECK(caps.defaults.method == caps.methods.front());
    CHECK(caps.defaults.normal == caps.normals.front());
  }
  // Metaball fields are no distance: no plain or relaxed sphere tracing, and only the analytic gradient.
  const auto& m = metaball_capabilities().methods;
  CHECK(std::find(m.begin(), m.end(), MarchMethod::sphere) == m.end());
  CHECK(std::find(m.begin(), m.end(), MarchMethod::segment) != m.end());
  CHECK(fractal_capabilities(10).defaults.iterations == 10);
  CHECK(fractal_capabilities(10).max_iterations == 16);
  CHECK(sdf_capabilities().max_iterations == 0);
}
