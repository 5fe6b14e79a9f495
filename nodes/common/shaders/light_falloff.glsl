// The falloff of a light with a range, shared by lighting.deferred's direct lights and
// gi.voxel's injected ones, so that the voxels' bounce follows the light the frame shows.
#ifndef LG_LIGHT_FALLOFF_GLSL
#define LG_LIGHT_FALLOFF_GLSL

// A smooth window from 1 to 0 at the range (Karis 2013) at squared distance d2; range 0: none,
// so a cut-off light shows no edge.
float light_range_window(float d2, float range) {
  return range > 0.0 ? pow(clamp(1.0 - pow(d2 / (range * range), 2.0), 0.0, 1.0), 2.0) : 1.0;
}

#endif
