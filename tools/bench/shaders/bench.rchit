#version 460
void main() { payload.rgb = vec3(float(gl_PrimitiveID % 7u) / 7.0, float(gl_InstanceID % 5) / 5.0, 1.0); }
