// A gyroid shell clipped to a ball: a distance field the library does not ship. Written to the
// portable subset (shader/glsl_cpp.hpp), so the same file is the GPU's march and the CPU's
// ground truth. The gyroid term g has |grad g| <= sqrt(3) in q = scale p, so the shell
// |g| / scale - thickness is sqrt(3)-Lipschitz in p: declared as 1.75 (checked by sampling).
#include "common/compat.glsl"
PROCEDURAY_CONST pr_real gyroid_scale = PR(4.0);
PROCEDURAY_CONST pr_real gyroid_thickness = PR(0.08);
PROCEDURAY_INLINE pr_real gyroid_distance(pr_real3 p) {
  pr_real3 q = p * gyroid_scale;
  pr_real g = sin(q.x) * cos(q.y) + sin(q.y) * cos(q.z) + sin(q.z) * cos(q.x);
  pr_real shell = abs(g) / gyroid_scale - gyroid_thickness;
  return max(shell, length(p) - PR(1.0));
}
