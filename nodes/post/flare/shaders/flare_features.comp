#version 460
// post.flare's features on the low-res grid, mixed with normalised weights: ghosts (the bright
// part mirrored and scaled through the centre, per channel for the chromatic offset), a halo
// (sampled a fixed distance nearer the centre) and streaks (blurs along a few lines). The model
// and its reasons are stated in nodes/post/flare/flare_model.h; the CPU there computes the same.
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D bright;  // linear, clamped to the edge
layout(binding = 1, rgba16f) uniform writeonly image2D flare;
layout(push_constant) uniform Push {
  float ghost_scales[8];  // kFlareGhostScales
  int ghosts;
  float chromatic;
  float halo_radius;  // image heights
  int streaks;        // lines
  int streak_taps;    // each side
  float streak_step;  // grid texels between taps
  float ghost_weight, halo_weight, streak_weight;
};

const float kSqrt2 = 1.41421356;
const float kPi = 3.14159265;

// The bright part at uv, bilinear; black outside the image.
vec3 bright_at(vec2 uv) {
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return vec3(0.0);
  return textureLod(bright, uv, 0.0).rgb;
}

float window(float t) {
  float s = 1.0 - min(t, 1.0);
  return s * s;
}

vec3 ghosts_at(vec2 uv) {
  if (ghosts <= 0) return vec3(0.0);
  vec3 sum = vec3(0.0);
  for (int i = 0; i < ghosts; ++i)
    for (int c = 0; c < 3; ++c) {
      float g = ghost_scales[i] * (1.0 + chromatic * float(1 - c));
      vec2 s = 0.5 + (uv - 0.5) / g;
      sum[c] += bright_at(s)[c] / (g * g) * window(length(s - 0.5) * kSqrt2);
    }
  return sum / float(ghosts);
}

vec3 halo_at(vec2 uv, float aspect) {
  vec2 q = (uv - 0.5) * vec2(aspect, 1.0);  // image heights from the centre
  float r = length(q);
  if (!(r > 0.0)) return vec3(0.0);
  float k = 1.0 - halo_radius / r;  // the source, on the other side of the centre when r < R
  float rho = abs(r - halo_radius);
  return 0.5 * bright_at(0.5 + q * k / vec2(aspect, 1.0)) * (rho / r) * window(rho / halo_radius);
}

vec3 streaks_at(vec2 centre, vec2 size) {
  if (streaks <= 0) return vec3(0.0);
  float weights = 0.0;
  for (int j = -streak_taps; j <= streak_taps; ++j) weights += exp(-4.0 * float(abs(j)) / float(streak_taps));
  vec3 sum = vec3(0.0);
  for (int line = 0; line < streaks; ++line) {
    float angle = kPi * float(line) / float(streaks);
    vec2 step_texels = vec2(cos(angle), sin(angle)) * streak_step;
    for (int j = -streak_taps; j <= streak_taps; ++j)
      sum += exp(-4.0 * float(abs(j)) / float(streak_taps)) * bright_at((centre + float(j) * step_texels) / size);
  }
  return sum / (weights * float(streaks));
}

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(flare);
  if (any(greaterThanEqual(texel, size))) return;
  vec2 centre = vec2(texel) + 0.5;
  vec2 uv = centre / vec2(size);
  vec3 f = ghost_weight * ghosts_at(uv) + halo_weight * halo_at(uv, float(size.x) / float(size.y)) +
           streak_weight * streaks_at(centre, vec2(size));
  imageStore(flare, texel, vec4(min(f, vec3(65504.0)), 1.0));
}
