// The probes of gi.irradiance_volume on the device and their lookup: the volumes (std430, as
// nodes/gi/irradiance_volume/probe_atlas.h's GpuProbeVolume) and the atlas images that
// pack_probe_atlas() fills, and the GLSL port of lookup_irradiance() (nodes/gi/probes/
// probe_lookup.cpp) and lookup_volumes(): change one, change the other. The octahedral maps are
// read with one bilinear fetch each from the bordered atlas tiles, which reads the texels and
// weights octahedral_taps() does on the CPU. The includer makes ProbeLookup's representation and
// visibility specialization constants: lavapipe runs both sides of a branch on a value that is
// only uniform, so every form would cost what all of them do.
#ifndef LG_PROBE_VOLUME_GLSL
#define LG_PROBE_VOLUME_GLSL

const int LG_PROBE_IRRADIANCE_TEXELS = 6;  // kProbeIrradianceTexels
const int LG_PROBE_DISTANCE_TEXELS = 14;   // kProbeDistanceTexels
const int LG_PROBE_RECORD_TEXELS = 16;     // kProbeRecordTexels: position, 9 SH, 6 ambient cube
const int LG_MAX_PROBE_VOLUMES = 64;       // kMaxProbeVolumes

struct ProbeVolume {
  mat4 world_from_grid;  // probe (i, j, k) at (i, j, k)
  mat4 grid_from_world;
  ivec4 counts;  // xyz: probes along each axis (at least 1); w: the volume's first probe
  vec4 cell;     // x: the smallest spacing in world units (ProbeGrid::min_spacing)
};

// ProbeRepresentation
const uint LG_PROBE_SH_L1 = 0u, LG_PROBE_SH_L2 = 1u, LG_PROBE_AMBIENT_CUBE = 2u, LG_PROBE_OCTAHEDRAL = 3u;

// A uniform buffer, not a storage buffer: lavapipe loads a storage buffer lane by lane, a uniform
// one at an index every lane shares once.
layout(std140, binding = LG_PROBE_VOLUME_BINDING) uniform ProbeVolumes { ProbeVolume volumes[LG_MAX_PROBE_VOLUMES]; };
layout(binding = LG_PROBE_RECORD_BINDING) uniform sampler2D probe_records;        // nearest
layout(binding = LG_PROBE_IRRADIANCE_BINDING) uniform sampler2D probe_irradiance_atlas;  // linear, clamped
layout(binding = LG_PROBE_DISTANCE_BINDING) uniform sampler2D probe_distance_atlas;      // linear, clamped

// octahedral_map.cpp
vec2 octahedral_encode(vec3 d) {
  vec2 p = d.xy / (abs(d.x) + abs(d.y) + abs(d.z));
  if (d.z < 0.0) p = (1.0 - abs(p.yx)) * vec2(p.x >= 0.0 ? 1.0 : -1.0, p.y >= 0.0 ? 1.0 : -1.0);
  return p * 0.5 + 0.5;
}

// Where probe p's tile sits: tiles fill rows of the records image's width, a power of two of
// tiles (shifts and masks, as lavapipe divides integers lane by lane).
ivec2 probe_tile(int p) {
  int per_row = textureSize(probe_records, 0).x / LG_PROBE_RECORD_TEXELS;
  return ivec2(p & (per_row - 1), p >> findLSB(per_row));
}

vec4 probe_record(ivec2 tile, int k) {
  return texelFetch(probe_records, ivec2(tile.x * LG_PROBE_RECORD_TEXELS + k, tile.y), 0);
}

// The bilinear fetch of direction d in a bordered k x k map: map texel (i, j) sits at tile texel
// (i + 1, j + 1), so coordinates from k * encode(d) - 0.5 reach the borders at -1 and k.
vec4 sample_octahedral(sampler2D atlas, ivec2 tile, vec3 d, int k) {
  vec2 texel = vec2(tile * (k + 2) + 1) + octahedral_encode(d) * float(k);
  return textureLod(atlas, texel / vec2(textureSize(atlas, 0)), 0.0);
}

// probe_irradiance(). The SH basis up to band 2 in closed form: the env basis (sh_basis.glsl:
// orthonormal, index l (l + 1) + m, no Condon-Shortley phase), without its band-4 loop and array.
vec3 probe_irradiance(ivec2 tile, vec3 n, uint representation) {
  if (representation == LG_PROBE_OCTAHEDRAL)
    return sample_octahedral(probe_irradiance_atlas, tile, n, LG_PROBE_IRRADIANCE_TEXELS).rgb;
  if (representation == LG_PROBE_AMBIENT_CUBE) {
    vec3 e = vec3(0.0);
    for (int a = 0; a < 3; ++a) e += n[a] * n[a] * probe_record(tile, 10 + 2 * a + (n[a] < 0.0 ? 1 : 0)).rgb;
    return e;
  }
  vec3 e = 0.282095 * probe_record(tile, 1).rgb +
           0.488603 * (n.y * probe_record(tile, 2).rgb + n.z * probe_record(tile, 3).rgb +
                       n.x * probe_record(tile, 4).rgb);
  if (representation == LG_PROBE_SH_L2)
    e += 1.092548 * (n.x * n.y * probe_record(tile, 5).rgb + n.y * n.z * probe_record(tile, 6).rgb +
                     n.x * n.z * probe_record(tile, 8).rgb) +
         0.315392 * (3.0 * n.z * n.z - 1.0) * probe_record(tile, 7).rgb +
         0.546274 * (n.x * n.x - n.y * n.y) * probe_record(tile, 9).rgb;
  return max(e, vec3(0.0));
}

struct ProbeLookup {
  uint representation;
  bool visibility;
  float normal_bias, view_bias;  // in cells
};

// volume_margin(): cells from grid coordinates `g` to the outer edge of a volume's fade (negative
// beyond it); the volume serves its box grown by half a cell in full and fades over the next
// quarter cell.
const float LG_PROBE_VOLUME_RAMP = 0.25;   // kVolumeBlendRamp, in cells
const float LG_PROBE_VOLUME_SERVED = 0.5;  // kVolumeServedCells
float probe_volume_margin(vec3 g, ivec3 counts) {
  const float grow = LG_PROBE_VOLUME_SERVED + LG_PROBE_VOLUME_RAMP;
  vec3 m = min(g + grow, vec3(counts - 1) + grow - g);
  return min(m.x, min(m.y, m.z));
}

// lookup_irradiance() for a point the caller found inside volume v's served box: rgb the
// irradiance, a 1; vec4(0) when no probe around the point is on.
vec4 lookup_irradiance(int v, vec3 position, vec3 n, vec3 eye, ProbeLookup s) {
  mat4 grid_from_world = volumes[v].grid_from_world;
  ivec3 counts = volumes[v].counts.xyz;
  int first = volumes[v].counts.w;
  float cell = volumes[v].cell.x;
  vec3 to_eye = normalize(eye - position);
  vec3 biased = position + (n * s.normal_bias + to_eye * s.view_bias) * cell;
  vec3 gb = clamp((grid_from_world * vec4(biased, 1.0)).xyz, vec3(0.0), vec3(counts - 1));
  ivec3 base = min(ivec3(floor(gb)), max(counts - 2, ivec3(0)));
  vec3 alpha = clamp(gb - vec3(base), 0.0, 1.0);
  vec3 sum = vec3(0.0);
  float total = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    ivec3 step = ivec3(corner & 1, (corner >> 1) & 1, corner >> 2);
    ivec3 c = min(base + step, counts - 1);
    ivec2 tile = probe_tile(first + (c.z * counts.y + c.y) * counts.x + c.x);
    vec4 probe_position = probe_record(tile, 0);
    if (probe_position.w == 0.0) continue;
    vec3 t = mix(1.0 - alpha, alpha, vec3(step));
    float trilinear = t.x * t.y * t.z;
    vec3 to_probe = probe_position.xyz - position;
    float to_probe_length = length(to_probe);
    float facing = to_probe_length > 0.0 ? dot(to_probe / to_probe_length, n) : 1.0;
    float weight = (facing + 1.0) * 0.5;
    weight = weight * weight + 0.2;
    if (s.visibility) {
      vec3 from_probe = biased - probe_position.xyz;
      float distance = length(from_probe);
      if (distance > 0.0) {
        vec2 moments = sample_octahedral(probe_distance_atlas, tile, from_probe / distance, LG_PROBE_DISTANCE_TEXELS).xy;
        if (distance > moments.x) {
          float variance = abs(moments.y - moments.x * moments.x);
          float d = distance - moments.x;
          // The CPU's variance / (variance + d^2) in double; the floor keeps 0 / 0 out of float.
          float chebyshev = variance / max(variance + d * d, 1e-30);
          weight *= max(chebyshev * chebyshev * chebyshev, 0.05);
        }
      }
    }
    weight = max(weight, 1e-6);
    const float crush = 0.2;
    if (weight < crush) weight *= weight * weight / (crush * crush);
    weight *= trilinear;
    sum += weight * probe_irradiance(tile, n, s.representation);
    total += weight;
  }
  if (!(total > 0.0)) return vec4(0.0);
  return vec4(sum / total, 1.0);
}

// lookup_volumes(): every volume's irradiance weighted by smoothstep(0, LG_PROBE_VOLUME_RAMP,
// margin), so that a volume fades out toward its border; rgb the blend, a the coverage (the
// weights' sum, at most 1). vec4(0) outside every volume.
vec4 lookup_volumes(int count, vec3 position, vec3 n, vec3 eye, ProbeLookup s) {
  vec3 sum = vec3(0.0);
  float total = 0.0;
  for (int v = 0; v < count; ++v) {
    vec3 g = (volumes[v].grid_from_world * vec4(position, 1.0)).xyz;
    float margin = probe_volume_margin(g, volumes[v].counts.xyz);
    if (!(margin > 0.0)) continue;
    vec4 e = lookup_irradiance(v, position, n, eye, s);
    if (e.a == 0.0) continue;
    float w = smoothstep(0.0, LG_PROBE_VOLUME_RAMP, margin);
    sum += w * e.rgb;
    total += w;
  }
  if (!(total > 0.0)) return vec4(0.0);
  return vec4(sum / total, min(total, 1.0));
}

#endif
