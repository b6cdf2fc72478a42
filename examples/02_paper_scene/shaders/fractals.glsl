// The paper scene's fractals as distance fields (paper_scene.hpp declares them with
// add_distance_field): the library marches them, takes their normals by differences and reports
// their hits. The time and the cut planes are parameters read from the scene's uniform each frame
// (field_parameter). Written in the portable subset of common/compat.glsl.
#include "primitives/julia.glsl"
#include "primitives/mandelbulb.glsl"

/// The quaternion Julia set cut by up to two planes (data: SceneConstants::julia_cuts), its
/// constant animated by time. Central differences give a cut face's plane normal exactly: inside
/// the set julia_distance is 0, so each axis reads max(0, +-h n_i) and the gradient is n / 2.
PROCEDURAY_INLINE pr_real julia_field(pr_real3 p, uint iterations, pr_real time, CutPlanes cuts) {
  return julia_cuts_distance(p, julia_animated_c(time), iterations, cuts.plane[0], cuts.plane[1], cuts.count);
}

/// The power-8 Mandelbulb whose iteration count counts down from the knobs' with time (the
/// report's animation).
PROCEDURAY_INLINE pr_real mandelbulb_field(pr_real3 p, uint iterations, pr_real time) {
  return mandelbulb_distance(p, mandelbulb_animated_iterations(iterations, time));
}
