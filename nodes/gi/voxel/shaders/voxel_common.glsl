// What gi.voxel's compute passes share (voxel_kernel.cpp fills the constants, std140): the grid
// (nodes/gi/common/cell_grid.h, every count a power of two), the light and its shadow map's
// projection, and the voxelization's fixed-point sums.
#ifndef LG_VOXEL_COMMON_GLSL
#define LG_VOXEL_COMMON_GLSL

#define LG_PI 3.14159265358979

struct VoxelConstants {
  vec4 origin_cell;        // xyz: the grid's corner, w: a voxel's edge in metres
  ivec4 counts;            // xyz: voxels per axis at level 0, w: levels in the chain
  vec4 light;              // xyz: the way the light travels (unit), w: 1 when there is a light
  vec4 irradiance;         // rgb: the light's irradiance, W/m^2; w: ao_distance, m
  mat4 shadow_from_world;  // into the shadow map's clip space (reversed depth, 1 nearest the light)
  ivec4 chain;             // x: the axis (0, 1, 2) along which the chain's images hold two halves
  // x: 1 with the directional light, y: 1 with the sky (the SH linked: injected, and gathered by
  // the cones that leave the grid), z: the local lights injected, w: 1 when any of those lights
  // the voxels (else the cones write nothing: no coverage)
  ivec4 sources;
};

layout(std140, binding = 0) uniform ConstantsBlock { VoxelConstants voxel; };

// The voxelization's sums, 14 ints a voxel: diffuse colour (rgb), normal (xyz), triangles, then as
// float bits the sky's visibility (voxel_sky.comp), the local lights' irradiance (rgb,
// voxel_local_lights.comp) and the irradiance of the light bounced so far (rgb,
// voxel_bounce.comp). Fixed point, kVoxelUnit to 1: a sum stays below 2^31 up to two million
// triangles a voxel.
#define LG_VOXEL_INTS 14
const float kVoxelUnit = 1024.0;

// The unit mean normal of a voxel's surfaces from its sums (the triangles and the normals' sum),
// or 0 where no triangle marked it or their normals cancel (both faces of a thin wall), as the
// injection tests (voxel_inject.comp).
vec3 voxel_surface_normal(int triangles, ivec3 normal_sum) {
  vec3 n = vec3(normal_sum);
  float len = length(n);
  return triangles > 0 && len > 1e-3 * float(triangles) * kVoxelUnit ? n / len : vec3(0.0);
}

uint voxel_index(ivec3 c) {
  return uint((c.z * voxel.counts.y + c.y) * voxel.counts.x + c.x);
}

// The voxel of a one-invocation-per-voxel dispatch (width counts.x, height counts.y x counts.z)
// over a level whose counts are `counts`.
ivec3 voxel_invocation_cell(ivec3 counts) {
  ivec2 id = ivec2(gl_GlobalInvocationID.xy);
  return ivec3(id.x, id.y % counts.y, id.y / counts.y);
}

// The chain: three 3D images, one per axis, each the light seen by rays travelling along that
// axis, the positive direction in the first half of the image along voxel.chain.x (the grid's
// longest axis, so that every level has both halves) and the negative in the second; mip l is
// level l, whose counts are voxel_level_counts(l). Per image: rgb the radiance of the surfaces
// that face the ray, premultiplied by how much they face it and cover the voxel; a: how much of
// the voxel faces rays travelling that way, composited as the colour is, so that a cone divides
// the colour by it (voxel_cones.comp). A fourth image of the same layout, the opacity image,
// holds in rgb the voxel's opacity for rays along x, y and z, the same in both halves (two
// opacities composite alike either way round). So a cone's sample reads four images, the facing
// of each direction it needs riding with that direction's colour (with the facing in an image
// of its own, read in both halves, it read five).
ivec3 voxel_level_counts(int level) {
  return max(voxel.counts.xyz >> level, ivec3(1));
}

// The level whose voxels are those of a 64-voxel grid (0 at resolution 64 or less, 1 at 128): the
// finest the rebuild's per-voxel rays read (the sky's visibility, voxel_sky.comp; the local
// lights', voxel_local_lights.comp). At level 0 they cost a 128-voxel grid's rebuild 16 times a
// 64-voxel grid's (8 times the voxels, twice the steps): the Cornell box's rebuild at 128 ran
// past lavapipe's 60 s fence timeout at load 15. The chain composites front to back along each
// axis, so a wall stays opaque along its normal at the coarser level. (The level of a 32-voxel
// grid, 1 at 64, made the Cornell box's error at 64 0.539 -> 0.580: the lamp and sky more
// shadowed.)
int voxel_ray_level() {
  return max(0, voxel.counts.w - 7);  // counts.w - 1 = log2 of the longest count; 6 = log2 64
}

// Where voxel c of a level of `counts` lies in its image: in the first half for rays travelling
// the positive way (negative = 0), else in the second.
ivec3 voxel_chain_texel(ivec3 c, ivec3 counts, int negative) {
  ivec3 t = c;
  t[voxel.chain.x] += negative * counts[voxel.chain.x];
  return t;
}

#endif
