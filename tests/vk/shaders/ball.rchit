#version 460
// Flat colour from the record, times the instance's tint from the storage buffer: tests
// compare it exactly.
void main() { payload.rgb = arguments.rgb.rgb * tints.data[gl_InstanceCustomIndexEXT].rgb.rgb; }
