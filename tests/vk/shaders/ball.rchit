#version 460
// Flat colour from the record: tests compare it exactly.
void main() { payload.rgb = record.rgb.rgb; }
