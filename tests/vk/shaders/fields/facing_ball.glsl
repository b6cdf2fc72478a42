// The test's field with a normal function: the unit ball, whose "exact" normal is +z wherever
// p.z > 0 (a stand-in a test can see: those pixels take one colour), differences elsewhere.
#include "common/compat.glsl"
PROCEDURAY_INLINE pr_real facing_ball_distance(pr_real3 p) { return length(p) - PR(1.0); }
PROCEDURAY_INLINE bool facing_ball_normal(pr_real3 p, PROCEDURAY_OUT(pr_real3) n) {
  n = pr_real3(PR(0.0), PR(0.0), PR(1.0));
  return p.z > PR(0.0);
}
