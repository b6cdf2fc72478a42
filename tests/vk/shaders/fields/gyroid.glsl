// A gyroid shell clipped to a ball: no primitive the library ships. The gyroid term g has
// |grad g| <= sqrt(3) in q = scale p (sampled: 1.7318), so |g| / scale is sqrt(3)-Lipschitz in p
// and so is the shell: the test declares L = 1.75.
#include "common/compat.glsl"
PROCEDURAY_CONST pr_real gyroid_scale = PR(4.0);
PROCEDURAY_CONST pr_real gyroid_thickness = PR(0.08);
PROCEDURAY_INLINE pr_real gyroid_distance(pr_real3 p) {
  pr_real3 q = p * gyroid_scale;
  pr_real g = sin(q.x) * cos(q.y) + sin(q.y) * cos(q.z) + sin(q.z) * cos(q.x);
  pr_real shell = abs(g) / gyroid_scale - gyroid_thickness;
  return max(shell, length(p) - PR(1.0));
}
