// What gi.lpv's compute passes share (lpv_kernel.cpp fills the constants, std140): the grid, the
// light, the fixed-point scales of injection, and SH L1 as lpv_model.h defines it.
#ifndef LG_LPV_COMMON_GLSL
#define LG_LPV_COMMON_GLSL

#define LG_PI 3.14159265358979

struct LpvConstants {
  vec4 origin_cell;  // xyz: the grid's corner (nodes/gi/common/cell_grid.h), w: a cell's edge in metres
  ivec4 counts;      // xyz: cells per axis, w: the RSM's edge in texels
  vec4 light;        // xyz: the way the light travels (unit), w: an RSM texel's area across the beam, m^2
  vec4 scales;       // x: fixed-point units per W/sr of injected intensity, y: per unit of occlusion
};

layout(std140, binding = 0) uniform ConstantsBlock { LpvConstants lpv; };

// Coefficients of Y00, Y1-1 (y), Y10 (z), Y11 (x).
vec4 sh_l1_basis(vec3 d) {
  return vec4(0.28209479, 0.48860251 * d.y, 0.48860251 * d.z, 0.48860251 * d.x);
}

// max(0, n . w) in SH L1: pi Y00 and 2 pi / 3 Y1m(n).
vec4 sh_l1_cosine_lobe(vec3 n) {
  return vec4(0.88622693, 1.02332671 * n.y, 1.02332671 * n.z, 1.02332671 * n.x);
}

uint lpv_cell_index(ivec3 c) {
  return uint((c.z * lpv.counts.y + c.y) * lpv.counts.x + c.x);
}

bool lpv_inside(ivec3 c) {
  return all(greaterThanEqual(c, ivec3(0))) && all(lessThan(c, lpv.counts.xyz));
}

// The cell of a one-invocation-per-cell dispatch (width counts.x, height counts.y x counts.z).
ivec3 lpv_invocation_cell() {
  ivec2 id = ivec2(gl_GlobalInvocationID.xy);
  return ivec3(id.x, id.y % lpv.counts.y, id.y / lpv.counts.y);
}

#endif
