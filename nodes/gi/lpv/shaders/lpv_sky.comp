#version 460
#extension GL_GOOGLE_include_directive : require
// gi.lpv's sky, one invocation per cell, with the environment's SH linked: the sky's light that
// reaches the cell's centre through the geometry volume, into images of its own beside the sum
// (not propagated: the march carries it the whole way; read linearly by the lookup, not as the
// sum's lobe, which gives an open floor 12% too much). kSkyDirections fixed directions
// (a spherical Fibonacci set, equal solid angles) are marched from the cell's centre cell by cell
// to the grid's edge; past it lies the sky. A cell's surfaces are one plane there (lpv_resolve.comp:
// their mean plane and how much of the cell they cover); a ray whose stretch in the cell crosses
// the plane loses that much, whichever way the surfaces face (an opaque surface hides the sky
// from both sides: the inside faces of a closed room, turned away from a sky outside, must still
// block it), and a ray running beside the plane loses nothing. The march starts at the centre of
// the cell's own stretch: a floor's cell sees the sky above the floor, not below it, and a wall's
// cell, its centre inside the room, not the sky outside (reading the lobe alone, the cell's own
// surfaces blocked either every way or none, and a closed room under the sky got 6% of it
// inside, an open floor 21%: docs/lpv.md). Still a cell holding a wall thinner than a cell has
// its centre on one side of it, and that side's sky would reach the pixels on the other side
// through the lookup's filter: so the light is stored times the cell's openness, 1 - the
// coverage of its surfaces, with the openness beside it, and the lookup divides the filtered
// light by the filtered openness (a mean over the open cells near it). Every direction's sky radiance (the cosine-convolved SH deconvolved, bands 0-2) times
// its transmittance is projected to SH L1 in the direction the light travels (-w), as radiant
// radiance (W/m^2/sr).
#include "nodes/gi/lpv/shaders/lpv_common.glsl"
#define LG_SKY_SH_BINDING 2  // the environment's irradiance SH
#include "nodes/gi/common/shaders/sky_sh.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1) uniform sampler3D sky_planes;  // lpv_resolve.comp's: normal x coverage, distance
layout(binding = 3, rgba16f) uniform writeonly image3D sky_red;  // SH L1 x openness
layout(binding = 4, rgba16f) uniform writeonly image3D sky_green;
layout(binding = 5, rgba16f) uniform writeonly image3D sky_blue;
layout(binding = 6, rgba16f) uniform writeonly image3D openness;  // r

// 32 directions, 4 pi / 32 sr each: 64 moved the joint benchmark's errors by at most 0.004
// (gallery and Cornell box, docs/lpv.md) for twice the march.
const int kSkyDirections = 32;
const float kGoldenAngle = 2.39996323;
const float kStopBelow = 1e-3;  // transmittance below which a direction's sky is dark

vec3 sky_direction(int k) {
  float z = 1.0 - (2.0 * float(k) + 1.0) / float(kSkyDirections);
  float r = sqrt(max(1.0 - z * z, 0.0));
  float phi = kGoldenAngle * float(k);
  return vec3(r * cos(phi), r * sin(phi), z);
}

// The share of the sky along w that reaches cell c's centre: a walk through the cells the ray
// crosses (each once, entered at distance enter and left at leave, in cells), from c to the
// grid's edge.
float transmittance(ivec3 c, vec3 w) {
  ivec3 cell = c;
  ivec3 step = ivec3(sign(w));
  vec3 delta = 1.0 / max(abs(w), vec3(1e-6));  // along w, per cell crossed on each axis
  vec3 next = 0.5 * delta;                      // to the next face on each axis, from c's centre
  float t = 1.0, enter = 0.0;
  do {
    float leave = min(next.x, min(next.y, next.z));
    vec4 plane = texelFetch(sky_planes, cell, 0);
    float len = length(plane.xyz);  // the coverage, or 1 + it where the surfaces are not one plane
    vec3 n = len > 0.0 ? plane.xyz / len : vec3(0.0);
    vec3 from_centre = vec3(c - cell);  // c's centre from this cell's
    float before = dot(from_centre + enter * w, n) - plane.w, after = dot(from_centre + leave * w, n) - plane.w;
    bool crosses = (before < 0.0) != (after < 0.0) || (len > 1.0 && cell != c);
    if (crosses) t *= 1.0 - (len > 1.0 ? len - 1.0 : len);
    int axis = next.x < next.y ? (next.x < next.z ? 0 : 2) : (next.y < next.z ? 1 : 2);
    cell[axis] += step[axis];
    next[axis] += delta[axis];
    enter = leave;
  } while (t > kStopBelow && lpv_inside(cell));
  return t;
}

void main() {
  ivec3 c = lpv_invocation_cell();
  if (!lpv_inside(c)) return;
  vec3 sky[kSkyRadianceCoefficients];
  sky_radiance_coefficients(sky);
  vec4 red = vec4(0.0), green = vec4(0.0), blue = vec4(0.0);
  int k = 0;
  do {
    vec3 w = sky_direction(k);
    float t = transmittance(c, w);
    if (t > kStopBelow) {
      vec3 l = sky_radiance(sky, w) * t;
      vec4 travelling = sh_l1_basis(-w);
      red += l.r * travelling, green += l.g * travelling, blue += l.b * travelling;
    }
  } while (++k < kSkyDirections);
  float len = length(texelFetch(sky_planes, c, 0).xyz);
  float open = 1.0 - (len > 1.0 ? len - 1.0 : len);
  float weight = 4.0 * LG_PI / float(kSkyDirections) * open;
  imageStore(sky_red, c, clamp(finite_or_zero(red * weight), -65504.0, 65504.0));
  imageStore(sky_green, c, clamp(finite_or_zero(green * weight), -65504.0, 65504.0));
  imageStore(sky_blue, c, clamp(finite_or_zero(blue * weight), -65504.0, 65504.0));
  imageStore(openness, c, vec4(open));
}
