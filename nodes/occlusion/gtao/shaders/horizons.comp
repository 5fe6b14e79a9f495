#version 460
#extension GL_GOOGLE_include_directive : require
// Ground-truth ambient occlusion (Jimenez et al. 2016, as structured by Intel's XeGTAO): per
// pixel, a few slices through the view vector; in each the two horizons are found by marching
// the depth buffer, and the cosine-weighted visible arc between them is integrated in closed
// form with the normal projected into the slice. An open plane gives exactly 1. The same
// integral, weighted by direction, gives the bent normal; the visibility gives its cone.
#include "nodes/common/shaders/gbuffer.glsl"
#include "nodes/occlusion/gtao/shaders/ao_guide.glsl"
#include "nodes/occlusion/gtao/shaders/gtao_constants.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

// The quality, fixed when the pipeline is made: loops of known length unroll. With the counts in
// the uniform buffer, lavapipe (Mesa 22.3) kept about 0.5 MiB of host memory per dispatch at
// 64x36 until the pipeline was destroyed (docs/reliability.md, the soak).
layout(constant_id = 0) const uint slices = 2u;
layout(constant_id = 1) const uint steps = 2u;  // per side of each slice
// 1 / resolution_scale: the depth mips' texel size, and which of noisy and surface is written
// (lavapipe runs both sides of a branch on a uniform, masked, so the other store must not be in
// the pipeline); a constant, so that at 1 the sample arithmetic folds to what it was before the
// mips started on the grid.
layout(constant_id = 2) const int grid_divisor = 1;

layout(binding = 1) uniform sampler2D depth_mips;  // device depth with averaged mips
layout(binding = 2) uniform sampler2D gbuffer_normal;
// On the horizon grid (grid_pixel): the G-buffer's extent at resolution_scale 1, else 1/k of it.
layout(binding = 3, r8) uniform writeonly image2D noisy;  // at resolution_scale 1
layout(binding = 4, r8) uniform writeonly image2D edges;
layout(binding = 5, rgba8_snorm) uniform writeonly image2D bent_normals;
// Below resolution_scale 1, noisy's visibility beside the texel's surface (ao_guide.glsl), which
// the denoiser then carries to the upsample.
layout(binding = 6, rgba16f) uniform writeonly image2D surface;

const float PI = 3.14159265358979;
const float HALF_PI = 1.57079632679490;

// Interleaved gradient noise (Jimenez 2014), moved every frame so temporal accumulation sees
// new slice angles and step offsets.
float noise(vec2 pixel, uint frame) {
  pixel += 5.588238 * float(frame % 64u);
  return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}

float fast_acos(float x) {
  return acos(clamp(x, -1.0, 1.0));
}

// The horizon angle h = n + clamp(h_raw - n, -pi/2, pi/2) on side `side` (-1: h0, +1: h1) with
// cos h and sin h, where h_raw = side * acos(horizon_cos), clamped to the normal's tangent plane
// n -+ pi/2.
vec3 clamp_horizon(float horizon_cos, float side, float n, vec2 cs_n) {
  float c = clamp(horizon_cos, -1.0, 1.0);
  float h_raw = side * acos(c);
  if (side * (h_raw - n) > HALF_PI) return vec3(n + side * HALF_PI, -side * cs_n.y, side * cs_n.x);
  return vec3(h_raw, c, side * sqrt(max(1.0 - c * c, 0.0)));
}

// The cosine-weighted visible arc from the view vector to horizon h (h.x the angle, h.yz its
// cosine and sine): (cos n + 2 h sin n - cos(2h - n)) / 4.
float visible_arc(vec3 h, vec2 cs_n) {
  float c2 = h.y * h.y - h.z * h.z, s2 = 2.0 * h.y * h.z;
  return (cs_n.x + 2.0 * h.x * cs_n.y - (c2 * cs_n.x + s2 * cs_n.y)) / 4.0;
}

// One horizon's terms of the bent-normal integral: 6 sin(h - n) - sin(3h - n) - 3 sin(h + n)
// along the slice, -cos(3h - n) - 3 cos(h + n) toward the eye.
vec2 bent_terms(vec3 h, vec2 cs_n) {
  float ch = h.y, sh = h.z, cn = cs_n.x, sn = cs_n.y;
  float c3 = ch * (4.0 * ch * ch - 3.0), s3 = sh * (3.0 - 4.0 * sh * sh);
  float along = 6.0 * (sh * cn - ch * sn) - (s3 * cn - c3 * sn) - 3.0 * (sh * cn + ch * sn);
  float toward = -(c3 * cn + s3 * sn) - 3.0 * (ch * cn - sh * sn);
  return vec2(along, toward);
}

// The depth mips start on the horizon grid (prefilter.comp): mip 0's texel i is the depth at
// G-buffer pixel k i, and mip m's texel t averages mip-0 texels [2^m t, 2^m (t + 1)), which on a
// plane is the plane's depth at the mean of their pixels: G-buffer pixel
// k 2^m t + (k 2^m - k) / 2, in pixel-centre terms k 2^m (t + 1/2) - (k - 1) / 2 (at k = 1 the
// block's centre). So a sample reads the texel of its level nearest to it and stands at that
// point: a point on the surface, never one lifted off a flat floor by filtering or by a level
// that does not tile the image exactly (odd sizes).
// (Level sizes follow from the grid's, noisy's, without querying the texture per sample.)
vec3 sample_position(vec2 uv, int mip, ivec2 grid) {
  ivec2 level = max(grid >> mip, ivec2(1));
  float texel_pixels = float(grid_divisor << mip);
  // The nearest texel's point: t = floor((x - 1/2 + k/2) / (k 2^mip)) for pixel coordinate x.
  ivec2 t = ivec2((uv * viewport.xy + 0.5 * float(grid_divisor - 1)) / texel_pixels);
  t = clamp(t, ivec2(0), level - 1);
  vec2 point = (vec2(t) * texel_pixels + 0.5 * (texel_pixels - float(grid_divisor - 1))) * viewport.zw;
  return view_position(point, linear_depth(texelFetch(depth_mips, t, mip).r));
}

// Four depth-edge weights (left, right, top, bottom) in 2 bits each: 1 where the neighbour's
// depth continues this texel's plane, 0 across a discontinuity (for the denoiser, which runs on
// the same grid).
float neighbour_depth(ivec2 texel, ivec2 grid) {
  return linear_depth(texelFetch(depth_mips, clamp(texel, ivec2(0), grid - 1), 0).r);
}

float pack_edges(ivec2 texel, ivec2 grid, float z) {
  float l = neighbour_depth(texel + ivec2(-1, 0), grid);
  float r = neighbour_depth(texel + ivec2(1, 0), grid);
  float t = neighbour_depth(texel + ivec2(0, -1), grid);
  float b = neighbour_depth(texel + ivec2(0, 1), grid);
  vec4 delta = vec4(l, r, t, b) - z;
  // Compare against the mirrored neighbour so slopes are not edges.
  vec4 slope = delta + delta.yxwz;
  vec4 w = clamp(1.25 - abs(slope) / (0.011 * z + 1e-4), 0.0, 1.0);
  vec4 q = round(w * 3.0);
  return dot(q, vec4(64.0, 16.0, 4.0, 1.0)) / 255.0;
}

void store_visibility(ivec2 texel, float visibility, float device_depth, vec3 world_n) {
  if (grid_divisor > 1)
    imageStore(surface, texel, pack_ao_guide(visibility, device_depth, world_n));
  else
    imageStore(noisy, texel, vec4(visibility));
}

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 grid = imageSize(noisy);
  if (any(greaterThanEqual(texel, grid))) return;
  ivec2 pixel = grid_pixel(texel);
  vec2 uv = (vec2(pixel) + 0.5) * viewport.zw;
  float device_depth = texelFetch(depth_mips, texel, 0).r;
  float z = linear_depth(device_depth);
  bool sky = !(z < 1e7);  // no surface: nothing occludes the sky (its lanes' arithmetic below is unused)
  vec3 p = view_position(uv, z);
  vec3 view_vec = normalize(-p);
  vec3 world_n = decode_normal(texelFetch(gbuffer_normal, pixel, 0).rgb);
  vec3 normal = normalize(mat3(view_from_world) * world_n);

  float radius = search.x;
  float screen_radius = min(radius * search.y / z, search.w);  // pixels
  // Samples fade out between 62% and 100% of the radius: weight (radius - d) / (radius - from),
  // 1 at `from` and 0 at the radius.
  float falloff_from = 0.62 * radius;
  float falloff_mul = -1.0 / (radius - falloff_from);
  float falloff_add = -radius * falloff_mul;
  float min_t = min(1.3 / max(screen_radius, 1e-3), 1.0);
  float last_mip = float(textureQueryLevels(depth_mips) - 1);
  float slice_noise = noise(vec2(texel), counts.z);
  float step_noise = noise(vec2(texel) + vec2(17.0, 31.0), counts.z);

  float visibility = 0.0, open_weight = 0.0;
  vec3 bent = vec3(0.0);
  for (uint slice = 0u; slice < slices; ++slice) {
    float phi = (float(slice) + slice_noise) / float(slices) * PI;
    vec2 omega = vec2(cos(phi), sin(phi));
    // Screen y grows downward while view y grows upward.
    vec3 direction = vec3(omega.x, -omega.y, 0.0);
    vec3 ortho_direction = direction - dot(direction, view_vec) * view_vec;
    vec3 axis = normalize(cross(ortho_direction, view_vec));
    vec3 projected_normal = normal - axis * dot(normal, axis);
    float projected_length = length(projected_normal);
    if (projected_length < 1e-5) continue;
    float sign_n = sign(dot(ortho_direction, projected_normal));
    float cos_n = clamp(dot(projected_normal, view_vec) / projected_length, 0.0, 1.0);
    float sin_n = sign_n * sqrt(max(1.0 - cos_n * cos_n, 0.0));
    float n = sign_n * fast_acos(cos_n);
    float low0 = -sin_n, low1 = sin_n;  // cos(n + pi/2), cos(n - pi/2): the tangent plane
    float horizon0 = low0, horizon1 = low1;
    for (uint s = 0u; s < steps; ++s) {
      // Evenly spaced (jittered) from 1.3 pixels out (closer, a sample sees only the pixel's own
      // surface, as in XeGTAO) to the radius. Squared spacing, denser near the centre, left the
      // outer half of the radius with one sample in three and missed most of the occlusion
      // there: against the ray-traced bunny, 3x3 had a mean absolute error of 0.045 with it
      // and 0.038 evenly spaced (tests/occlusion, 320x180).
      float t = min_t + (1.0 - min_t) * (float(s) + step_noise) / float(steps);
      vec2 offset = omega * (t * screen_radius) * viewport.zw;
      float offset_px = t * screen_radius;
      // A mip texel (k 2^mip pixels) at most 1/80 of the offset, or mip 0: averaged depth across
      // a silhouette is a surface that is not there, and coarser levels (1/10, as XeGTAO) raised
      // the bunny's error at 1280x720 from 0.037 to 0.042 (lumagraph-bench-ao).
      int mip = int(clamp(log2(max(offset_px, 1.0) / float(grid_divisor)) - 6.3, 0.0, last_mip));
      for (int side = 0; side < 2; ++side) {
        vec2 suv = side == 0 ? uv + offset : uv - offset;
        if (any(lessThan(suv, vec2(0.0))) || any(greaterThan(suv, vec2(1.0)))) continue;
        vec3 delta = sample_position(suv, mip, grid) - p;
        float dist_squared = dot(delta, delta);
        if (!(dist_squared > 1e-12)) continue;
        float shc = dot(delta, view_vec) * inversesqrt(dist_squared);
        // Thin occluders: depth differences count more in the falloff (search.z >= 1).
        float falloff_dist = length(vec3(delta.xy, delta.z * search.z));
        float weight = clamp(falloff_dist * falloff_mul + falloff_add, 0.0, 1.0);
        if (side == 0)
          horizon0 = max(horizon0, mix(low0, shc, weight));
        else
          horizon1 = max(horizon1, mix(low1, shc, weight));
      }
    }
    // Horizon angles measured from the view vector, clamped to the hemisphere of the normal,
    // with their cosines and sines (the integrals below need no further trigonometry).
    vec2 cs_n = vec2(cos_n, sin_n);
    vec3 h0 = clamp_horizon(horizon1, -1.0, n, cs_n);
    vec3 h1 = clamp_horizon(horizon0, 1.0, n, cs_n);
    visibility += projected_length * (visible_arc(h0, cs_n) + visible_arc(h1, cs_n));
    open_weight += projected_length * (cos_n + n * sin_n);  // the same with both horizons open
    // The visible arc's direction-weighted integral (XeGTAO's bent normal) in the slice's own
    // basis: t0 along the marching direction, t1 toward the eye.
    vec2 b0 = bent_terms(h0, cs_n), b1 = bent_terms(h1, cs_n);
    float t0 = (b0.x + b1.x + 16.0 * sin_n) / 12.0;
    float t1 = (b0.y + b1.y + 8.0 * cos_n) / 12.0;
    bent += (normalize(ortho_direction) * t0 + view_vec * t1) * projected_length;
  }
  // Normalised by what the same slices give an open hemisphere rather than by their count: a
  // slice's share of the integral is exact only on average over slice angles, so one slice
  // alone gave up to 1.3 on open surfaces, clamped to 1, and less elsewhere (a dark bias of
  // single-slice settings); the ratio is 1 on any open surface for any slice count.
  visibility = open_weight > 0.0 ? clamp(visibility / open_weight, 0.0, 1.0) : 1.0;
  float bent_length = length(bent);
  vec3 world_bent = bent_length > 1e-6 ? normalize(mat3(world_from_view) * (bent / bent_length)) : world_n;
  // A cosine-weighted visible cone of half-angle a has visibility sin^2 a: its cosine is
  // sqrt(1 - visibility).
  // One set of stores for sky and surface: lavapipe runs both sides of a branch, so the sky's
  // early return cost a second set every pixel.
  store_visibility(texel, sky ? 1.0 : visibility, sky ? 0.0 : device_depth, sky ? vec3(0.0, 0.0, 1.0) : world_n);
  imageStore(edges, texel, vec4(sky ? 1.0 : pack_edges(texel, grid, z)));
  imageStore(bent_normals, texel, sky ? vec4(0.0) : vec4(world_bent, sqrt(max(1.0 - visibility, 0.0))));
}
