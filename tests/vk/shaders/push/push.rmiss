#version 460
void main() { payload.rgb = knobs.tint.rgb; }
