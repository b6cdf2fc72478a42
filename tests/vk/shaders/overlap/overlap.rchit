#version 460
// The attribute of the intersection this hit is the closest of, as a colour.
void main() { payload.rgb = hit.normal * 0.5 + 0.5; }
