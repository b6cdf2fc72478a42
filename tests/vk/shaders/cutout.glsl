// Horizontal stripes of the cut-out ball, in object space: every other band is a hole.
bool in_hole(vec3 p) { return fract(p.y * 2.5 + 10.0) < 0.5; }
