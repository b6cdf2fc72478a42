#version 460
void main() { payload.rgb = record.rgb.rgb; }
