// How much of a pixel is the defocused layer, by its circle of confusion's radius in pixels: none
// under half a pixel, all over two. The composite blends by it and the gather weighs its taps by
// it, so each pixel's light is in the sharp image or the blur, never both.
#ifndef LG_DOF_BLEND_GLSL
#define LG_DOF_BLEND_GLSL

float defocus_blend(float radius) {
  return smoothstep(0.5, 2.0, radius);
}

#endif
