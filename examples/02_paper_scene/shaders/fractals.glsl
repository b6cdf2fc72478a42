// The paper scene's fractals as distance fields (paper_scene.hpp declares them with
// add_distance_field): the library marches them, takes their normals by differences and reports
// their hits. The time and the cut planes are parameters read from the scene's uniform each frame
// (field_parameter). Written in the portable subset of common/compat.glsl.
#include "primitives/julia.glsl"
#include "primitives/mandelbulb.glsl"

/// The quaternion Julia set cut by up to two planes (data: SceneConstants::julia_cuts), its
/// constant animated by time.
PROCEDURAY_INLINE pr_real julia_field(pr_real3 p, uint iterations, pr_real time, CutPlanes cuts) {
  return julia_cuts_distance(p, julia_animated_c(time), iterations, cuts.plane[0], cuts.plane[1], cuts.count);
}

/// A cut face's normal is its plane's, exactly (the field's .normal): differences of
/// max(julia, plane) would tilt it wherever the hit lies within their offset of the plane
/// (2.7 degrees median over the face at 320x240). Elsewhere the library takes differences.
PROCEDURAY_INLINE bool julia_field_normal(pr_real3 p, uint iterations, pr_real time, CutPlanes cuts,
                                          PROCEDURAY_OUT(pr_real3) n) {
  uint face = julia_cut_face(p, julia_animated_c(time), iterations, cuts.plane[0], cuts.plane[1], cuts.count);
  if (face >= 2u) return false;
  pr_real4 plane = face == 0u ? cuts.plane[0] : cuts.plane[1];
  n = pr_real3(plane.x, plane.y, plane.z);
  return true;
}

/// The power-8 Mandelbulb whose iteration count counts down from the knobs' with time (the
/// report's animation).
PROCEDURAY_INLINE pr_real mandelbulb_field(pr_real3 p, uint iterations, pr_real time) {
  return mandelbulb_distance(p, mandelbulb_animated_iterations(iterations, time));
}
