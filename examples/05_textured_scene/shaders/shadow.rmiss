#version 460
// Nothing between the point and the light.
void main() { payload.occluded = 0u; }
