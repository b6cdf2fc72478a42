// The power-8 Mandelbulb as a user's distance field (proceduray-field --sdf ... --iterations 8):
// the paper scene's estimate, measured alone for its evaluations per second.
#include "primitives/mandelbulb.glsl"

PROCEDURAY_INLINE pr_real bulb_distance(pr_real3 p, uint iterations) { return mandelbulb_distance(p, iterations); }
