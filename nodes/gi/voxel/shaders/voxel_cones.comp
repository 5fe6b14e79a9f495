#version 460
#extension GL_GOOGLE_include_directive : require
// gi.voxel's cones, one invocation per G-buffer pixel (or per texel of the smaller target at
// resolution_scale 1/k, as gi.lpv's lookup): six cones of 60 degrees (half-angle 30) over the
// normal's hemisphere, one along the normal and five 60 degrees from it, 72 degrees apart. Each
// starts one voxel out along the normal and marches front to back through the anisotropic chain
// (voxel_common.glsl; the three directions facing the ray, weighted by the squares of its
// components). A sample's radiance is the colour of the surfaces facing the ray over how much
// faces it (the chain's alpha), so a floor seen obliquely keeps its whole radiance though only
// the chain's vertical direction shows it, and what faces away from the ray (a sunlit roof seen
// from the room below it) adds nothing. A sample at distance t reads, trilinearly within one level, the level whose
// voxels are as wide as the cone there (2 t tan 30, rounded down to a level), but never wider
// than 2/3 of the sample's height h above the surface's tangent plane: the filter reaches one
// voxel beyond the sample, so voxels of width w <= h / 1.5 never blend in the surface the cone
// starts from (with the cone's own width an open floor lit itself through every coarse level:
// E = 1.76 W/m^2 under a 10 W/m^2 sun, 82% of its own radiance times pi). Steps of one sample's
// width, so that no voxel is skipped or counted twice; it stops once 99% opaque or out of the
// grid. With the sky (the SH linked), each cone adds the sky's radiance along its axis times what
// it left open (voxel_trace.glsl's Cone.open), so that the output holds all the diffuse light
// lighting.ibl replaces by it: the sky's own, the voxels' bounce of the sun, the sky and the local
// lights. Without it nothing beyond the grid lights it. A cone's openness at coarse levels
// overstates the sky it sees (a coarse sample of a slab is partly opaque, and the next step is
// out of the grid: 6.2% of the sky's light inside a closed room), so the sky's share of the six
// cones is capped by the sky visibility of the surface's own voxel (voxel_sky.comp, level 0
// only: 0.3% in that room).
// Weights: the cosine-weighted share of the hemisphere inside the normal's cone is
// sin^2(30 deg) = 1/4 exactly; the other five share the rest, 3/20 each. E = pi sum w_i L_i,
// exact for a uniform radiance L. Ambient occlusion: 1 - sum w_i a_i with each cone's opacity
// a_i gathered within ao_distance.
// The specular cone: one more cone along the reflection of the view about the normal, its
// half-angle from the GGX lobe (voxel_specular_half_angle_tan), marched the same way; it writes
// the radiance of what it met (its gathered light over its opacity, W/m^2/sr, before the BRDF)
// and its opacity as the coverage, so lighting.ibl mixes the prefiltered environment toward it as
// toward a reflection probe's (the part of the cone that leaves the grid sees the environment).
// rgb: irradiance, W/m^2; a: coverage, 1 where the surface lies in the grid's box and there is a
// light, else 0.
#include "nodes/gi/voxel/shaders/voxel_common.glsl"
#include "nodes/gi/voxel/shaders/voxel_trace.glsl"
#include "nodes/common/shaders/camera.glsl"
#include "nodes/common/shaders/finite.glsl"
#include "nodes/common/shaders/gbuffer.glsl"
#include "nodes/common/shaders/joint_upsample.glsl"
#define LG_SKY_SH_BINDING 12
#include "nodes/gi/common/shaders/sky_sh.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std140, binding = 1) uniform CameraBlock { Camera camera; };  // at the G-buffer's size
layout(binding = 2) uniform sampler2D depth_tex;
layout(binding = 3) uniform sampler2D normal_tex;
layout(binding = 5, rgba16f) uniform writeonly image2D irradiance;
layout(binding = 6, r8) uniform writeonly image2D ao;
layout(binding = 10) uniform sampler2D material_tex;  // r: perceptual roughness
layout(binding = 11, rgba16f) uniform writeonly image2D specular;
// The voxelization's sums (voxel_common.glsl): a voxel's triangles and sky visibility.
layout(std430, binding = 13) readonly buffer Grid { int grid[]; };
layout(push_constant) uniform Push {
  int k;  // the G-buffer's resolution over the targets'
};
// Specialization constants (lavapipe runs both sides of a branch on a run-time flag,
// docs/lavapipe-costs.md): 0 where nothing reads the specular output (it stays 0), and 0 where the
// sky is not linked (no sky to gather).
layout(constant_id = 0) const int kTraceSpecular = 1;
layout(constant_id = 1) const int kGatherSky = 1;

// The tangent of the specular cone's half-angle for perceptual roughness r (GGX, alpha = r^2):
// the reflected lobe's half width at half maximum. GGX's D(h) falls to half its peak where
// tan^2 theta_h = (sqrt 2 - 1) alpha^2 / (1 - sqrt 2 alpha^2), i.e. tan theta_h = 0.6436 alpha for
// small alpha (the form used here, finite for every alpha); the reflection turns twice as far as
// the half vector, so theta = 2 atan(0.6436 alpha): 0 at r = 0 (a mirror: one voxel wide, the
// finest level), 3 degrees at r = 0.2, 18 at 0.5, 65.5 at 1.
float voxel_specular_half_angle_tan(float roughness) {
  float x = 0.64359425 * roughness * roughness;  // sqrt(sqrt 2 - 1) alpha
  return 2.0 * x / (1.0 - x * x);                // tan(2 atan x), x <= 0.644
}

// The specular cone from `origin` (one voxel out along the unit normal n of the surface at p):
// along the view's reflection, pulled up into the tangent plane when the shading normal puts it
// below, its aperture from the roughness. rgb: the radiance it met (W/m^2/sr, before the BRDF),
// a: its opacity, the share of the lobe that met surfaces facing it (lit or dark) rather than
// leaving the grid.
vec4 specular_cone(vec3 origin, vec3 p, vec3 n, float roughness) {
  vec3 v = camera.position.xyz - p;
  float v_len = length(v);
  vec3 r = v_len > 0.0 ? reflect(-v / v_len, n) : n;
  r -= n * min(dot(r, n), 0.0);
  float r_len = length(r);
  r = r_len > 1e-4 ? r / r_len : n;
  Cone cone = trace(origin, r, max(dot(r, n), 0.0), voxel_specular_half_angle_tan(clamp(roughness, 0.0, 1.0)),
                    voxel.irradiance.w, kAllLevels, 1.0);
  float a = clamp(cone.opacity, 0.0, 1.0);
  // Below 1e-4 the light gathered (at most a times the brightest voxel) is negligible.
  vec3 radiance = a > 1e-4 ? cone.light / a : vec3(0.0);
  return vec4(clamp(finite_or_zero(radiance), 0.0, 65504.0), a);
}

// The sky visibility measured for voxel c (voxel_sky.comp), or -1 where none was: no triangle
// marked it, its normals cancel (voxel_sky.comp's -1), or the sky is not injected.
float voxel_sky_visibility(vec3 g) {
  ivec3 c = clamp(ivec3(floor(g)), ivec3(0), voxel.counts.xyz - 1);
  uint base = LG_VOXEL_INTS * voxel_index(c);
  return voxel.sources.y == 1 && grid[base + 6u] > 0 ? intBitsToFloat(grid[base + 7u]) : -1.0;
}

// The sky visibility of the voxel that holds the surface at p (normal n): a quarter voxel behind
// it, else (a face on a voxel boundary marks only one side) a quarter voxel in front, else 1.
float surface_sky_visibility(vec3 p, vec3 n) {
  vec3 g = (p - voxel.origin_cell.xyz) / voxel.origin_cell.w;
  float behind = voxel_sky_visibility(g - 0.25 * n), in_front = voxel_sky_visibility(g + 0.25 * n);
  return behind >= 0.0 ? behind : in_front >= 0.0 ? in_front : 1.0;
}

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(irradiance)))) return;
  ivec2 source = upsample_source_texel(texel, k, textureSize(depth_tex, 0));
  float depth = texelFetch(depth_tex, source, 0).r;
  float cell = voxel.origin_cell.w;
  vec3 p = depth > 0.0 ? world_position(camera, source, depth) : vec3(0.0);
  vec3 g = (p - voxel.origin_cell.xyz) / cell;
  vec3 n = decode_normal_unnormalized(texelFetch(normal_tex, source, 0).rgb);
  float len = length(n);
  // Off the grid, on the sky or without a light: no light, unoccluded, no reflection, stored with
  // the rest at the end (on lavapipe an early return is a branch too: the other lanes would store
  // again, docs/lavapipe-costs.md rule 1).
  bool lit = depth > 0.0 && all_finite(vec4(p, 0.0)) && !any(lessThan(g, vec3(0.0))) &&
             !any(greaterThan(g, vec3(voxel.counts.xyz))) && len > 1e-6 && voxel.sources.w != 0;
  vec4 e = vec4(0.0), reflected = vec4(0.0);
  float unoccluded = 1.0;
  if (lit) {
    n /= len;
    vec3 origin = p + n * cell;
    vec3 light = vec3(0.0), sky_light = vec3(0.0);
    float occluded = 0.0, open = 0.0;
    vec3 sky[kSkyRadianceCoefficients];
    sky_radiance_coefficients(sky);  // zero without the SH (an empty buffer is bound)
    for (int i = 0; i < kHemisphereCones; ++i) {
      Cone cone = trace_hemisphere_cone(origin, n, i, voxel.irradiance.w, kAllLevels, 1.0);
      light += hemisphere_cone_weight(i) * cone.light;
      if (kGatherSky == 1) sky_light += hemisphere_cone_weight(i) * cone.open * sky_radiance(sky, cone.direction);
      occluded += hemisphere_cone_weight(i) * cone.occluded;
      open += hemisphere_cone_weight(i) * cone.open;
    }
    if (kGatherSky == 1) light += sky_light * min(1.0, surface_sky_visibility(p, n) / max(open, 1e-6));
    e = vec4(clamp(finite_or_zero(LG_PI * light), 0.0, 65504.0), 1.0);
    unoccluded = clamp(1.0 - occluded, 0.0, 1.0);
    if (kTraceSpecular == 1) reflected = specular_cone(origin, p, n, texelFetch(material_tex, source, 0).r);
  }
  imageStore(irradiance, texel, e);
  imageStore(ao, texel, vec4(unoccluded));
  // Not written where nothing reads it (kTraceSpecular 0): the store leaves the pipeline too.
  if (kTraceSpecular == 1) imageStore(specular, texel, reflected);
}
