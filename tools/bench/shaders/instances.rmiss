#version 460
void main() { payload.rgb = vec3(0.0); }
