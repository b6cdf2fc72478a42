// The D3D12 sample's seven SDFs as distance fields (d3d12_scene.hpp declares one per primitive
// with add_distance_field): sdf.glsl's distance at the record's params, the shape turned by the
// record's spin times the frame's time about the local y axis (a rotation keeps the bound). The
// library marches them, with each primitive's knobs. Portable GLSL (shader/glsl_cpp.hpp).
#ifndef D3D12_SDF_FIELDS_GLSL
#define D3D12_SDF_FIELDS_GLSL

#include "primitives/sdf.glsl"

/// p in the shape's own frame: turned by -spin * time about y.
PROCEDURAY_INLINE pr_real3 sdf_field_point(pr_real3 p, pr_real spin, pr_real time) {
  pr_real a = -spin * time;
  pr_real c = cos(a);
  pr_real s = sin(a);
  return pr_real3(c * p.x + s * p.z, p.y, -s * p.x + c * p.z);
}

#define D3D12_SDF_FIELD(name, kind)                                                                  \
  PROCEDURAY_INLINE pr_real name##_field(pr_real3 p, pr_real4 params, pr_real spin, pr_real time) { \
    return sdf_distance(kind, sdf_field_point(p, spin, time), params);                             \
  }
D3D12_SDF_FIELD(mini_spheres, sdf_mini_spheres)
D3D12_SDF_FIELD(round_cube, sdf_round_cube)
D3D12_SDF_FIELD(square_torus, sdf_square_torus)
D3D12_SDF_FIELD(twisted_torus, sdf_twisted_torus)
D3D12_SDF_FIELD(cog, sdf_cog)
D3D12_SDF_FIELD(cylinder, sdf_cylinder)
D3D12_SDF_FIELD(fractal_pyramid, sdf_fractal_pyramid)
#undef D3D12_SDF_FIELD

#endif
