#version 460
#extension GL_GOOGLE_include_directive : require
// env.specular_prefilter's exact method, one dispatch per output mip: the split-sum prefiltered
// radiance (N = V = R), sum of L D(h) (n.l) dw / sum of D(h) (n.l) dw, summed over texels of the
// levels prefilter_exact_chain.comp builds rather than sampled, the same sum the brute-force
// reference (prefilter_reference.cpp) makes over every texel of the input:
// - every texel of a coarse level (16^2 a face for a 128^2 input), weighted at its centre by its
//   exact solid angle;
// - except the coarse texels whose centres are within the near cap of n (angle theta), whose
//   children on a finer level are summed instead, where the lobe's weight curves fastest;
// - plus the peak list: each peak's excess over the chain's bound at its own direction.
// The host picks the levels and the cap per roughness (exact_prefilter.cpp says how, with the
// errors that chose them). Roughness 0 reads the input along n at the mip whose texels match the
// output's. Non-finite radiance counts as 0.
#include "nodes/common/shaders/finite.glsl"
#include "nodes/env/common/shaders/cube_map.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2DArray chain;  // prefilter_exact_chain.comp's levels, all mips
layout(binding = 1, rgba16f) uniform writeonly image2DArray prefiltered_mip;
layout(binding = 2) uniform samplerCube env;  // the input, for roughness 0
// prefilter_exact_chain.comp's peak list, read as a uniform buffer: with it in a storage buffer
// grace.hdr (806 peaks at the then 16x bound) took 2.5x the random environment's time, from a
// uniform buffer 1.5x (lavapipe presumably loads a uniform buffer at a lane-uniform index once
// for all lanes, a storage buffer lane by lane).
layout(binding = 3, std140) uniform Peaks {
  uvec4 peak_header;  // count (may pass capacity), capacity
  vec4 peaks[2 * 511];  // per peak: direction, flux (exact_prefilter.h's kPrefilterPeakCapacity)
};
layout(push_constant) uniform Push {
  float alpha;        // roughness^2; 0: roughness 0
  int coarse_level;   // the chain's level summed everywhere outside the near cap
  int fine_level;     // the level summed inside it
  float cos_near;     // cos theta; above 1: no cap
};

// D(h) (n.l) up to the constant alpha^2 / pi, which cancels in the ratio. (n.h)^2 = (1 + n.l) / 2
// for h = normalize(n + l), and d = (n.h)^2 (alpha^2 - 1) + 1 written as alpha^2 + (1 - alpha^2)
// (1 - n.l) / 2 so that it keeps its precision near the lobe's peak for small alpha.
float lobe(vec3 n, vec3 l, float a2) {
  float n_dot_l = dot(n, l);
  if (n_dot_l <= 0.0) return 0.0;
  float d = a2 + (1.0 - a2) * 0.5 * (1.0 - n_dot_l);
  return n_dot_l / (d * d);
}

// cube_map.glsl's cube_direction(face, uv) as normalize(centre + p.x u + p.y v), p = 2 uv - 1,
// the face's axes from a table once per face rather than cube_direction's six branches per texel.
const vec3 kFaceCentre[6] = vec3[](vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0), vec3(0, 0, 1), vec3(0, 0, -1));
const vec3 kFaceU[6] = vec3[](vec3(0, 0, -1), vec3(0, 0, 1), vec3(1, 0, 0), vec3(1, 0, 0), vec3(1, 0, 0), vec3(-1, 0, 0));
const vec3 kFaceV[6] = vec3[](vec3(0, -1, 0), vec3(0, -1, 0), vec3(0, 0, 1), vec3(0, 0, -1), vec3(0, -1, 0), vec3(0, -1, 0));
mat3 face_basis(int face) {
  return mat3(kFaceCentre[face], kFaceU[face], kFaceV[face]);
}
vec3 texel_direction(mat3 basis, ivec2 texel, float size) {
  return normalize(basis * vec3(1.0, (vec2(texel) + 0.5) * (2.0 / size) - 1.0));
}

// rgb: L w dw, a: w dw for texel `texel` of a level `size` wide, up to the level's factor
// 4 / size^2 on dw (the chain's a holds the rest).
vec4 texel_term(vec3 n, float a2, mat3 basis, int face, ivec2 texel, int lod, float size) {
  vec4 t = texelFetch(chain, ivec3(texel, face), lod);
  float w = lobe(n, texel_direction(basis, texel, size), a2) * t.a;
  return vec4(t.rgb * w, w);
}

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  int face = int(gl_GlobalInvocationID.z);
  int size = imageSize(prefiltered_mip).x;
  if (any(greaterThanEqual(texel, ivec2(size)))) return;
  vec3 n = cube_direction(face, (vec2(texel) + 0.5) / float(size));
  if (alpha == 0.0) {
    float env_size = float(textureSize(env, 0).x);
    imageStore(prefiltered_mip, ivec3(texel, face),
               vec4(finite_or_zero(textureLod(env, n, max(log2(env_size / float(size)), 0.0)).rgb), 1.0));
    return;
  }
  float a2 = alpha * alpha;
  int coarse = textureSize(chain, coarse_level).x, fine = textureSize(chain, fine_level).x;
  int k = fine / coarse;
  // Texel addresses come from loop counters alone, the same in every lane (addresses read from
  // a per-workgroup list in shared memory made this 2.5x slower on lavapipe). A branch is
  // skipped where no lane takes it: the near cap's children, and the coarse texels whose centres
  // are below the horizon (their terms are 0).
  vec4 coarse_sum = vec4(0.0), fine_sum = vec4(0.0);
  for (int f = 0; f < 6; ++f) {
    mat3 basis = face_basis(f);
    for (int j = 0; j < coarse; ++j)
      for (int i = 0; i < coarse; ++i) {
        float n_dot_centre = dot(texel_direction(basis, ivec2(i, j), float(coarse)), n);
        if (n_dot_centre > cos_near) {
          for (int jj = 0; jj < k; ++jj)
            for (int ii = 0; ii < k; ++ii)
              fine_sum += texel_term(n, a2, basis, f, ivec2(i, j) * k + ivec2(ii, jj), fine_level, float(fine));
        } else if (n_dot_centre > 0.0) {
          coarse_sum += texel_term(n, a2, basis, f, ivec2(i, j), coarse_level, float(coarse));
        }
      }
  }
  vec4 sum = coarse_sum * (4.0 / float(coarse * coarse)) + fine_sum * (4.0 / float(fine * fine));
  uint count = min(peak_header.x, peak_header.y);
  for (uint p = 0u; p < count; ++p) sum.rgb += peaks[2u * p + 1u].rgb * lobe(n, peaks[2u * p].xyz, a2);
  imageStore(prefiltered_mip, ivec3(texel, face), vec4(sum.a > 0.0 ? sum.rgb / sum.a : vec3(0.0), 1.0));
}
