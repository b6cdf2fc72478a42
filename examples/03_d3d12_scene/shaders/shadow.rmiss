#version 460
// The shadow ray reached the light: the caller preset occluded = 1 (the sample's ShadowRay miss).
void main() { payload.occluded = 0u; }
