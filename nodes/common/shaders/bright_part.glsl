// The part of a colour whose luminance is above `threshold`, in the colour's hue (a soft knee:
// nothing at the threshold, all of it far above); all of the colour when the threshold is 0.
// What post.bloom blurs and post.flare spreads (nodes/post/flare/flare_model.cpp on the CPU).
#ifndef LG_BRIGHT_PART_GLSL
#define LG_BRIGHT_PART_GLSL

vec3 bright_part(vec3 c, float threshold) {
  if (threshold <= 0.0) return c;
  float luminance = dot(c, vec3(0.2126, 0.7152, 0.0722));
  return luminance > threshold ? c * ((luminance - threshold) / luminance) : vec3(0.0);
}

#endif
