#version 460
void main() { payload.rgb = arguments.rgb.rgb; }
