#version 460
void main() { payload.colour = mix(vec3(0.9, 0.93, 1.0), vec3(0.35, 0.5, 0.8), 0.5 + 0.5 * gl_WorldRayDirectionEXT.y); }
