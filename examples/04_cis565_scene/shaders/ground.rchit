#version 460
// The ground: y = 0, normal +y.
#include "surface.glsl"

void main() { shade(gl_WorldRayOriginEXT + gl_HitTEXT * gl_WorldRayDirectionEXT, vec3(0.0, 1.0, 0.0)); }
