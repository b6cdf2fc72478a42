#version 460
// Shadow rays skip closest-hit shaders: reaching the miss shader is the only way to be lit.
void main() { payload.occluded = 0u; }
