// bench_instances' field and shading, shared by the library's stages (instances.rchit and the
// field's generated intersection) and the compute peer (instances.comp), so both images come
// from the same code: the power-8 Mandelbulb, shaded by its object-space normal (the instances
// are translated and uniformly scaled, so it is the world's).
#ifndef BENCH_INSTANCES_GLSL
#define BENCH_INSTANCES_GLSL

#include "primitives/mandelbulb.glsl"

PROCEDURAY_INLINE pr_real bench_bulb(pr_real3 p, uint iterations) { return mandelbulb_distance(p, iterations); }

PROCEDURAY_INLINE pr_real3 bench_shade(pr_real3 normal) { return PR(0.5) + PR(0.5) * normal; }

#endif
