// What the depth-of-field passes share (dof_kernel.cpp fills it): the thin lens in pixels.
#ifndef LG_DOF_CONSTANTS_GLSL
#define LG_DOF_CONSTANTS_GLSL

layout(push_constant) uniform Push {
  float coc_scale;   // CoC radius in full-resolution pixels = coc_scale * |1 / focus - 1 / z|
  float focus;       // focus distance, m
  float near_plane;  // reversed-Z infinite projection: device depth = near / distance
  float max_blur;    // largest CoC radius, px
  uint samples;
};

#endif
