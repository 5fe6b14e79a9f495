// The march of gi.voxel's cones through the anisotropic chain (voxel_common.glsl), shared by the
// pixels' cones (voxel_cones.comp) and the voxels' sky visibility (voxel_sky.comp): the chain's
// bindings, a cone's samples and its front-to-back march, and the six cones over a hemisphere.
#ifndef LG_VOXEL_TRACE_GLSL
#define LG_VOXEL_TRACE_GLSL

#include "nodes/gi/voxel/shaders/voxel_common.glsl"

// The chain, per axis, trilinear within a level.
layout(binding = 4) uniform sampler3D seen_x;
layout(binding = 7) uniform sampler3D seen_y;
layout(binding = 8) uniform sampler3D seen_z;
layout(binding = 9) uniform sampler3D opacity_image;

const float kTanHalfAngle = 0.57735027;  // tan 30 deg
const float kCentreWeight = 0.25, kSideWeight = 0.15;
const float kCrossing = 4.0;
const int kAllLevels = 1 << 30;

// What a ray travelling along `negative` (0 or 1) of `image`'s axis sees at `uvw` (the grid's
// box in [0, 1]^3) of `level`: within its half, clamped half a voxel inside it so the filter does
// not blend the other half in.
vec4 seen(sampler3D image, vec3 uvw, int level, int negative) {
  int axis = voxel.chain.x;
  float n = float(voxel_level_counts(level)[axis]);
  uvw[axis] = (clamp(uvw[axis], 0.5 / n, 1.0 - 0.5 / n) + float(negative)) * 0.5;
  return textureLod(image, uvw, float(level));
}

// What a cone's sample sees.
struct Sample {
  vec3 radiance;   // of what faces the ray, W/m^2/sr
  float opaque;    // the chain's opacity, whichever way the surfaces face
  float in_front;  // opacity of what faces the ray only
};

// The chain at `uvw` and `level` for a ray along `d` (unit): the three directions facing the ray,
// weighted by d's squared components (they sum to 1). in_front: how much of the voxel faces the
// ray along any of the three directions, each counted fully once the ray crosses that axis at 30
// degrees or more (w >= 1/4), fading below.
Sample sample_chain(vec3 uvw, int level, vec3 d) {
  vec3 w = d * d;
  bvec3 negative = lessThan(d, vec3(0.0));
  vec4 x = seen(seen_x, uvw, level, int(negative.x)), y = seen(seen_y, uvw, level, int(negative.y)),
       z = seen(seen_z, uvw, level, int(negative.z));
  vec3 colour = w.x * x.rgb + w.y * y.rgb + w.z * z.rgb, facing = vec3(x.a, y.a, z.a);
  vec3 in_front = min(vec3(1.0), kCrossing * w) * facing;
  float opaque = dot(w, seen(opacity_image, uvw, level, 0).rgb);
  // Below 1e-3 of a voxel facing the ray, the colour (at most as large) is negligible.
  return Sample(colour / max(dot(w, facing), 1e-3), opaque, max(in_front.x, max(in_front.y, in_front.z)));
}

struct Cone {
  vec3 light;      // radiance gathered, W/m^2/sr
  float opacity;   // of what faced the ray
  float occluded;  // opacity gathered within ao_distance
  float open;      // what the march left unblocked, whichever way the voxels face: the share of
                   // the cone that leaves the grid (or passes the step limit) and sees the sky
  vec3 direction;  // the cone's axis
};

// `cosine`: of the cone's axis with the normal (h grows by it per metre of t); `tan_half_angle`:
// of the cone's aperture; `occlusion_distance`: how far its opacity counts into `occluded`;
// `finest_top`: the coarsest level it may read (fewer steps the coarser); `step_scale`: its steps
// over the width of the voxels it reads (1: no voxel skipped or counted twice; below 1 a thin
// slab, which the trilinear filter spreads over two samples of partial opacity, lets less through;
// steps of 1.5 at levels 2 and up, stop 34 to 36, saved 10% of the cones but drew the grid as a
// plaid on the Cornell box's walls and blocks, and the two rooms read 0.672 against 0.605 now).
Cone trace(vec3 origin, vec3 direction, float cosine, float tan_half_angle, float occlusion_distance, int finest_top,
           float step_scale) {
  float cell = voxel.origin_cell.w;
  vec3 grid_size = cell * vec3(voxel.counts.xyz);
  float top = float(min(finest_top, voxel.counts.w - 1));
  vec3 light = vec3(0.0);
  float opacity = 0.0, occluded = 0.0, blocked = 0.0;
  float t = cell;
  int steps = int(128.0 / step_scale);  // as far at any step
  // A do-while: its test at the bottom saves the body that llvmpipe's `for` runs once more with
  // every lane masked (docs/lavapipe-costs.md, rule 2); the first step always runs.
  int s = 0;
  do {
    // The level whose voxels are at most that wide: a whole level, as blending in the next one
    // would reach twice as far.
    float level = min(floor(log2(max(min(2.0 * t * tan_half_angle, (cell + t * cosine) / 1.5), cell) / cell)), top);
    float width = cell * exp2(level);
    vec3 uvw = (origin + direction * t - voxel.origin_cell.xyz) / grid_size;
    if (any(lessThan(uvw, vec3(0.0))) || any(greaterThan(uvw, vec3(1.0)))) break;
    Sample v = sample_chain(uvw, int(level), direction);
    // Light stops at what faces the ray only (a ray never meets the back of a surface); the
    // occlusion counts every voxel, as a one-sided roof occludes the floor below it.
    float a = clamp(v.in_front, 0.0, 1.0);
    light += (1.0 - opacity) * a * max(v.radiance, vec3(0.0));
    opacity += (1.0 - opacity) * a;
    float opaque = clamp(v.opaque, 0.0, 1.0);
    if (t <= occlusion_distance) occluded += (1.0 - occluded) * opaque;
    // The march ends once the voxels are solid whichever way they face (nothing lit is seen
    // through them: closed surfaces face the ray before their backs), but not for the voxels
    // of the surface the cone starts from, which the filter reaches within 2.5 voxels of it. A
    // march ended by facing opacity alone went on through every surface's back.
    if (cell + t * cosine >= 2.5 * cell) blocked += (1.0 - blocked) * opaque;
    t += width * step_scale;
    ++s;
  } while (s < steps && opacity < 0.99 && blocked < 0.99);
  // A march stopped at 99% (below) lets nothing through: a closed room's 1% would be a leak.
  float closed = clamp(max(opacity, blocked), 0.0, 1.0);
  return Cone(light, opacity, occluded, closed < 0.99 ? 1.0 - closed : 0.0, direction);
}

// The six cones of 60 degrees over the hemisphere of unit normal n: cone 0 along n, cones 1 to 5
// tilted 60 degrees from it, 72 degrees apart about it (a frame from n by Duff et al. 2017).
// Weights: the cosine-weighted share of the hemisphere within 30 degrees of n is sin^2(30) = 1/4
// exactly; the five others share the rest, 3/20 each, so pi sum w_i L_i is exact for a uniform L.
const int kHemisphereCones = 6;

float hemisphere_cone_weight(int i) {
  return i == 0 ? kCentreWeight : kSideWeight;
}

// Cone i from `origin` (one voxel out along n), its occlusion counted within `occlusion_distance`,
// reading levels up to `top`, at steps of `step_scale` voxels. One trace call whatever i is
// (lavapipe runs both sides of a branch).
Cone trace_hemisphere_cone(vec3 origin, vec3 n, int i, float occlusion_distance, int top, float step_scale) {
  float s = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + n.z), b = n.x * n.y * a;
  vec3 t1 = vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x), t2 = vec3(b, s + n.y * n.y * a, -n.y);
  float phi = float(i - 1) * (2.0 * LG_PI / 5.0);
  vec3 side = 0.5 * n + 0.86602540 * (cos(phi) * t1 + sin(phi) * t2);
  Cone cone = trace(origin, i == 0 ? n : side, i == 0 ? 1.0 : 0.5, kTanHalfAngle, occlusion_distance, top, step_scale);
  // The share of the cone that was blocked by voxels not facing it (a coarse voxel that a wall
  // only partly fills, the filter at the wall's edge) is taken to shine as the cone's gathered
  // light: without it the cones gathered about 70% of the light in a closed room (each bounce
  // added 0.56 of the last at albedo 0.8, EachBounceAddsTheAlbedosShareOfTheLast; now 0.71).
  // Taking it to shine as what faced the cone on average (light / opacity) measured better still
  // on the path-traced worlds, but lit a shaded floor from the sunlit floor beside it (coplanar,
  // which cannot light it) through a sliver of facing: 13% of the lit case.
  cone.light *= 1.0 + max(1.0 - cone.open - cone.opacity, 0.0);
  return cone;
}

#endif
