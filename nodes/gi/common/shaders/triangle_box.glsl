// The separating-axis test of a triangle against a grid cell (Akenine-Moller 2001): the box's three
// axes (callers loop over the triangle's bounding box), the triangle's normal and the nine cross
// products of its edges with the axes. gi.voxel's voxelization and gi.lpv's geometry volume.
#ifndef LG_TRIANGLE_BOX_GLSL
#define LG_TRIANGLE_BOX_GLSL

// Whether the projections of the corners onto `axis` and the projection of a half-size-0.5 box at
// the origin overlap (touching counts).
bool overlap_on(vec3 axis, vec3 a, vec3 b, vec3 c) {
  float pa = dot(axis, a), pb = dot(axis, b), pc = dot(axis, c);
  float r = 0.5 * (abs(axis.x) + abs(axis.y) + abs(axis.z));
  return min(pa, min(pb, pc)) <= r && max(pa, max(pb, pc)) >= -r;
}

// The triangle a, b, c (n its unnormalized normal) against the box of half-size 0.5 at the
// origin (grid units, relative to the cell's centre); touching counts.
bool triangle_overlaps_box(vec3 a, vec3 b, vec3 c, vec3 n) {
  if (abs(dot(n, a)) > 0.5 * (abs(n.x) + abs(n.y) + abs(n.z))) return false;
  vec3 edges[3] = vec3[3](b - a, c - b, a - c);
  for (int e = 0; e < 3; ++e)
    for (int k = 0; k < 3; ++k) {
      vec3 unit = vec3(0.0);
      unit[k] = 1.0;
      if (!overlap_on(cross(unit, edges[e]), a, b, c)) return false;
    }
  return true;
}

#endif
