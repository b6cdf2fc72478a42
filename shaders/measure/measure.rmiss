#version 460
void main() { payload.hit = 0u; }
