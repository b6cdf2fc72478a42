#version 460
// texture_test.cpp: the sky is the cube map in the ray's direction.
void main() { payload.rgb = textureLod(sky, gl_WorldRayDirectionEXT, 0.0).rgb; }
