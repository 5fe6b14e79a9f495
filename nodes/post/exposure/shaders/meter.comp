#version 460
#extension GL_GOOGLE_include_directive : require
// The metered average of the histogram between two percentiles, the exposure it asks for, and
// one frame of adaptation from last frame's exposure (the history) at the set speeds. One
// invocation: 256 bins are a short loop. Writes the exposure in EV to the 1x1 output.
#include "nodes/post/exposure/shaders/exposure_common.glsl"

layout(local_size_x = 1) in;

layout(binding = 0, std430) readonly buffer Histogram { uint counts[]; };
layout(binding = 1) uniform sampler2D history;  // last frame's exposure (EV) in red
layout(binding = 2, r32f) uniform writeonly image2D exposure;

void main() {
  float total = 0.0;
  for (uint b = 0u; b < kBins; ++b) total += float(counts[b]);
  float lo = total * low_fraction, hi = total * high_fraction;
  float bin_width = (histogram_max - histogram_min) / float(kBins);
  float below = 0.0, sum = 0.0, weight = 0.0;
  for (uint b = 0u; b < kBins; ++b) {
    float count = float(counts[b]);
    float w = max(0.0, min(below + count, hi) - max(below, lo));
    sum += w * (histogram_min + (float(b) + 0.5) * bin_width);
    weight += w;
    below += count;
  }
  float metered = weight > 0.0 ? sum / weight : 0.5 * (histogram_min + histogram_max);
  float target = log2(0.18) - metered + compensation;
  float previous = texelFetch(history, ivec2(0), 0).r;
  float ev = target;
  if (restart == 0u && !isnan(previous) && !isinf(previous))
    ev = previous + clamp(target - previous, -speed_down * seconds, speed_up * seconds);
  imageStore(exposure, ivec2(0), vec4(ev, 0.0, 0.0, 0.0));
}
