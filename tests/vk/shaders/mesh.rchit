#version 460
// The renderer's MeshRef test (mesh_buffers_test.cpp): the hit's vertex struct, interpolated from
// the three corners at the hit's barycentrics; mode 0 shows its colour, mode 1 its normal.
hitAttributeEXT vec2 bary;
void main() {
  MeshVertex v = interpolate(arguments.mesh, gl_PrimitiveID, bary);
  payload.rgb = arguments.mode == 0u ? v.colour : normalize(v.normal) * 0.5 + 0.5;
}
