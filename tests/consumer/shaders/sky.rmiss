#version 460
void main() { payload.rgb = constants.sky.rgb; }
