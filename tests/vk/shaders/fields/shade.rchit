#version 460
// The normal as a colour (object space), the record's colour in alpha: tests compare images.
void main() { payload.rgb = 0.5 * hit.normal + 0.5; }
