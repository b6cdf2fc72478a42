#version 460
// The shadow ray reached the light: the caller preset occluded = 1.
void main() { payload.occluded = 0u; }
