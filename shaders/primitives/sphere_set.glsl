// proceduray::SphereSet (march/sphere_set.hpp), a uniform or record block, as the list
// spheres.glsl's ray_spheres tests. Needs the generated SphereSet struct: include it after the
// declarations of a scene whose uniform or record holds one.
//
//   #include "primitives/sphere_set.glsl"
//   if (ray_spheres(o, d, sphere_list(constants.balls), 1.0, t_lo, t_hi, 0u, t, n)) ...   // cull: hit.glsl
#ifndef PROCEDURAY_PRIMITIVES_SPHERE_SET_GLSL
#define PROCEDURAY_PRIMITIVES_SPHERE_SET_GLSL

#include "spheres.glsl"

/// The block's spheres (a count over spheres_max is cut there).
PROCEDURAY_INLINE SphereList sphere_list(SphereSet set) {
  SphereList list;
  list.count = min(set.count, spheres_max);
  for (uint i = 0u; i < spheres_max; ++i) list.sphere[i] = i < list.count ? set.sphere[i] : pr_real4(PR(0.0));
  return list;
}

#endif
