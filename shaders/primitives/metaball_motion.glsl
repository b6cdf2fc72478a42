// proceduray::Metaballs (march/metaballs.hpp), a uniform or record block, at one time: the list
// metaballs.glsl marches. Needs the generated Metaball and Metaballs structs, so include it
// after the declarations of a scene whose uniform or record holds a Metaballs.
//
//   #include "primitives/metaball_motion.glsl"
//   MetaballList balls = metaballs_at(constants.blob, constants.time);
//   metaballs_march(o, u, s_lo, s_hi, balls, constants.blob.threshold, metaball_method_segment, 0u, m, s, n, steps);
#ifndef PROCEDURAY_PRIMITIVES_METABALL_MOTION_GLSL
#define PROCEDURAY_PRIMITIVES_METABALL_MOTION_GLSL

#include "metaballs.glsl"

/// Source i at `time`: centre + amplitude * sin(frequency * time + phase), per axis.
PROCEDURAY_INLINE pr_real3 metaball_position_at(Metaball b, pr_real time) {
  return b.centre + b.amplitude * sin(b.frequency * time + b.phase);
}

/// The block's sources at `time` (at most metaball_max; a count over it is cut there).
PROCEDURAY_INLINE MetaballList metaballs_at(Metaballs blob, pr_real time) {
  MetaballList list;
  list.count = min(blob.count, metaball_max);
  for (uint i = 0u; i < metaball_max; ++i) {
    pr_real3 c = i < list.count ? metaball_position_at(blob.ball[i], time) : pr_real3(PR(0.0));
    list.ball[i] = pr_real4(c.x, c.y, c.z, i < list.count ? blob.ball[i].radius : PR(0.0));
  }
  return list;
}

#endif
