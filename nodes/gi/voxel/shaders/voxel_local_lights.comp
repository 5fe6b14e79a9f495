#version 460
#extension GL_GOOGLE_include_directive : require
// gi.voxel's local lights, one invocation per voxel of level 0: the irradiance the scene's point,
// spot, sphere, tube and rectangle lights give the voxel's surface (its mean normal), into its
// sums for the second injection (voxel_inject.comp: albedo x E / pi). Each light is a point at
// its centre (voxel_local_lights.cpp's light()): E = I(-l) max(0, n . l) W / (d^2 + s), with I
// its intensity toward the voxel (a spot's KHR falloff, a rectangle's cosine), W the range
// window of lighting.deferred and s the squared size of an area light (area / pi: a disk's
// on-axis irradiance exactly, L pi R^2 / (d^2 + R^2)), at least a quarter voxel squared so that a
// light inside a voxel stays finite. Visibility from the voxels' own opacity (not the shadow
// atlas: the volume is rebuilt without lighting.deferred's passes): a ray through the chain's
// opacity at voxel_ray_level() (voxel_common.glsl), from 1.5 of its voxels out along the normal
// (where the trilinear filter no longer reaches the surface's own voxels) to 1.5 short of the
// light (a lamp lies in its ceiling's voxels; a light that shines one way is aimed at from 1.5
// of them out of it that way), transmittance the product of (1 - opacity) at steps of one of
// those voxels. A coarser
// level keeps a wall opaque along its normal (the chain composites front to back along each
// axis) but lets a ray past a thin object's edge more easily.
#include "nodes/gi/voxel/shaders/voxel_common.glsl"
#include "nodes/gi/voxel/shaders/voxel_trace.glsl"
#include "nodes/common/shaders/finite.glsl"
#include "nodes/common/shaders/light_falloff.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 1) buffer Grid { int grid[]; };

// voxel_local_lights.h's VoxelLocalLight.
struct LocalLight {
  vec4 position_range;  // xyz: the light's centre; w: its range (0: none)
  vec4 intensity_size;  // rgb: W/sr toward the axis (every way for kind 0); w: s, m^2
  vec4 axis_kind;       // xyz: the axis, the way the light travels; w: 0 every way, 1 spot,
                        // 2 one-sided Lambertian, 3 two-sided Lambertian
  vec4 spot;            // x, y: the spot's ramp t = clamp(cos x + y, 0, 1)
};
const int kMaxLocalLights = 16;  // voxel_local_lights.h's kMaxVoxelLocalLights
layout(std140, binding = 10) uniform LightsBlock { LocalLight lights[kMaxLocalLights]; };

const int kMaxSteps = 128;  // voxel_ray_level()'s grid's diagonal is 111 voxels

// The width of a voxel of voxel_ray_level().
float ray_cell() {
  return voxel.origin_cell.w * exp2(float(voxel_ray_level()));
}

// The share of the light that passes from `from` to `to` through the opacity of voxel_ray_level().
float transmittance(vec3 from, vec3 to) {
  int level = voxel_ray_level();
  float cell = ray_cell();
  vec3 grid_size = voxel.origin_cell.w * vec3(voxel.counts.xyz);  // the counts are level 0's
  vec3 d = to - from;
  float length_left = length(d) - 1.5 * cell;
  if (!(length_left > 0.0)) return 1.0;
  d = normalize(d);
  vec3 w = d * d;
  float passed = 1.0;
  float t = 0.0;
  int s = 0;
  do {
    vec3 uvw = (from + d * t - voxel.origin_cell.xyz) / grid_size;
    // Outside the grid (a light beyond the scene's box) nothing blocks.
    float inside = float(all(greaterThanEqual(uvw, vec3(0.0))) && all(lessThanEqual(uvw, vec3(1.0))));
    passed *= 1.0 - inside * clamp(dot(w, seen(opacity_image, uvw, level, 0).rgb), 0.0, 1.0);
    t += cell;
    ++s;
  } while (t < length_left && passed > 1e-3 && s < kMaxSteps);
  return passed > 1e-3 ? passed : 0.0;
}

vec3 irradiance(LocalLight light, vec3 p, vec3 n, vec3 from) {
  vec3 to_light = light.position_range.xyz - p;
  float d2 = dot(to_light, to_light);
  vec3 l = to_light * inversesqrt(max(d2, 1e-12));
  float cosine = max(dot(n, l), 0.0);
  float window = light_range_window(d2, light.position_range.w);
  float along = dot(light.axis_kind.xyz, -l);  // cosine at the light, toward the voxel
  int kind = int(light.axis_kind.w);
  float toward = 1.0;
  if (kind == 1) toward = pow(clamp(along * light.spot.x + light.spot.y, 0.0, 1.0), 2.0);
  if (kind == 2) toward = max(along, 0.0);
  if (kind == 3) toward = abs(along);
  float size = max(light.intensity_size.w, 0.25 * voxel.origin_cell.w * voxel.origin_cell.w);
  float e = cosine * toward * window / (d2 + size);
  if (!(e > 0.0)) return vec3(0.0);
  // A light that shines one way (a spot, a rectangle: toward the voxel's side for a two-sided one)
  // is aimed at from 1.5 ray voxels out of it that way, past the voxels of the ceiling or wall it
  // lies on: a ray ending beside the light ran along that surface, whose filtered opacity took up
  // to 26% of a ceiling lamp's light (ACeilingLampsLightReachesTheFloorVoxelsPastTheCeiling).
  float out_of_surface = kind == 0 ? 0.0 : (along < 0.0 ? -1.5 : 1.5) * ray_cell();
  vec3 aim = light.position_range.xyz + light.axis_kind.xyz * out_of_surface;
  return light.intensity_size.rgb * (e * transmittance(from, aim));
}

void main() {
  ivec3 c = voxel_invocation_cell(voxel.counts.xyz);
  if (any(greaterThanEqual(c, voxel.counts.xyz))) return;
  uint base = LG_VOXEL_INTS * voxel_index(c);
  vec3 n = voxel_surface_normal(grid[base + 6u], ivec3(grid[base + 3u], grid[base + 4u], grid[base + 5u]));
  if (n == vec3(0.0)) return;
  float cell = voxel.origin_cell.w;
  vec3 p = voxel.origin_cell.xyz + (vec3(c) + 0.5) * cell;
  vec3 from = p + n * (1.5 * ray_cell());
  vec3 e = vec3(0.0);
  int count = min(voxel.sources.z, kMaxLocalLights);
  for (int i = 0; i < count; ++i) e += irradiance(lights[i], p, n, from);
  e = clamp(finite_or_zero(e), 0.0, 65504.0);
  grid[base + 8u] = floatBitsToInt(e.r);
  grid[base + 9u] = floatBitsToInt(e.g);
  grid[base + 10u] = floatBitsToInt(e.b);
}
