// Tests for julia.glsl's julia_cuts_distance and julia_cut_face, compiled as C++: the report's
// figure 4 cuts its Julia set by two planes; the planes are data (proceduray::CutPlanes).
#include <proceduray/march/cut_planes.hpp>

#include <proceduray/shader/glsl_cpp.hpp>

namespace julia_cuts_test {
using namespace proceduray::glsl_cpp;
#include "primitives/julia.glsl"
}  // namespace julia_cuts_test

#include <doctest/doctest.h>

using namespace julia_cuts_test;

namespace {
const glm::vec4 c(-0.2f, 0.6f, 0.2f, 0.2f);  // julia_animated_c(0): the origin is inside the set
}

TEST_CASE("julia cuts: each plane removes its side, the face reports its plane, count picks how many") {
  REQUIRE(julia_distance(glm::vec3(0.0f), c, 12u) == 0.0f);  // inside, uncut
  const proceduray::CutPlanes cuts = proceduray::make_cut_planes(
      {proceduray::cut_plane({0.0f, 0.0f, 1.0f}, -0.05f), proceduray::cut_plane({1.0f, 0.0f, 0.0f}, -0.05f)});
  const glm::vec3 origin(0.0f);
  // Both planes cut the origin away; the distance is the farther plane's (both 0.05 here).
  CHECK(julia_cuts_distance(origin, c, 12u, cuts.plane[0], cuts.plane[1], 2u) == doctest::Approx(0.05f));
  // One plane only: the second is ignored.
  const glm::vec3 p(0.02f, 0.0f, -0.1f);  // kept by plane 0 (z <= -0.05), removed by plane 1 (x <= -0.05)
  CHECK(julia_cuts_distance(p, c, 12u, cuts.plane[0], cuts.plane[1], 1u) == julia_distance(p, c, 12u));
  CHECK(julia_cuts_distance(p, c, 12u, cuts.plane[0], cuts.plane[1], 2u) == doctest::Approx(0.07f));
  CHECK(julia_cut_face(p, c, 12u, cuts.plane[0], cuts.plane[1], 2u) == 1u);
  CHECK(julia_cut_face(glm::vec3(-0.1f, 0.0f, 0.02f), c, 12u, cuts.plane[0], cuts.plane[1], 2u) == 0u);
  // No cut: the set's own distance, and no face.
  CHECK(julia_cuts_distance(p, c, 12u, cuts.plane[0], cuts.plane[1], 0u) == julia_distance(p, c, 12u));
  CHECK(julia_cut_face(p, c, 12u, cuts.plane[0], cuts.plane[1], 0u) == 2u);
  // One plane equals julia_cut_distance, bit for bit (the paper scene's figure 3 is unchanged).
  for (const glm::vec3 q : {glm::vec3(0.3f, -0.2f, 0.1f), glm::vec3(1.0f, 1.0f, 1.0f), p}) {
    CHECK(julia_cuts_distance(q, c, 12u, cuts.plane[0], cuts.plane[1], 1u) == julia_cut_distance(q, c, 12u, cuts.plane[0]));
  }
}
