// What post.exposure's two passes share: their push constants, the bin count and the bin of a
// luminance (nodes/post/exposure/exposure_metering.h is the same on the CPU).
#ifndef LG_EXPOSURE_COMMON_GLSL
#define LG_EXPOSURE_COMMON_GLSL

const uint kBins = 256u;

layout(push_constant) uniform Push {
  float histogram_min;  // log2 luminance of the first bin's lower edge
  float histogram_max;  // and of the last bin's upper edge
  float low_fraction;   // the metered window, of the pixel count, darkest first
  float high_fraction;
  float compensation;   // EV
  float speed_up;       // EV per second while exposure rises
  float speed_down;     // and while it falls
  float seconds;        // since the previous frame
  uint restart;         // 1: no usable history (first frame, camera cut, unlinked)
};

float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

uint luminance_bin(float l) {
  float ev = log2(max(l, exp2(histogram_min)));
  float t = floor((ev - histogram_min) / (histogram_max - histogram_min) * float(kBins));
  return uint(clamp(t, 0.0, float(kBins - 1u)));
}

#endif
