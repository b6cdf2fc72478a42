#version 460
#include "instances.glsl"
void main() { payload.rgb = bench_shade(hit.normal); }
