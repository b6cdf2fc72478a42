#version 460
// The device's FP32 arithmetic peak, as the field measures it: FMAs in chains. Each loop pass
// does 64 FMAs per thread: INDEPENDENT 1 in 16 independent chains (four vec4s: the peak, latency
// hidden), else in one dependent chain (each FMA waits for the one before). The push constants
// keep the compiler from folding anything; the sums are checked on the host.
layout(local_size_x = 256) in;
layout(push_constant) uniform Push {
  uint iterations;
  float a;
  float b;
} push;
layout(std430, binding = 0) buffer Sums { float sums[]; };

void main() {
  const uint id = gl_GlobalInvocationID.x;
  const float seed = float(id & 255u) * (1.0 / 256.0);
#if INDEPENDENT
  const vec4 a = vec4(push.a), b = vec4(push.b);
  vec4 x0 = vec4(seed, seed + 1.0, seed + 2.0, seed + 3.0), x1 = x0 + 4.0, x2 = x0 + 8.0, x3 = x0 + 12.0;
#define STEP x0 = fma(x0, a, b); x1 = fma(x1, a, b); x2 = fma(x2, a, b); x3 = fma(x3, a, b);
  for (uint i = 0u; i < push.iterations; ++i) {
    STEP STEP STEP STEP
  }
  sums[id] = dot(x0 + x1 + x2 + x3, vec4(1.0));
#else
  float x = seed;
#define STEP x = fma(x, push.a, push.b); x = fma(x, push.a, push.b); x = fma(x, push.a, push.b); x = fma(x, push.a, push.b);
  for (uint i = 0u; i < push.iterations; ++i) {
    STEP STEP STEP STEP STEP STEP STEP STEP STEP STEP STEP STEP STEP STEP STEP STEP
  }
  sums[id] = x;
#endif
}
