// The probes of gi.irradiance_volume on the device and their lookup: the std430 layout that
// nodes/gi/irradiance_volume/probe_buffer.h fills (GpuProbeVolume, GpuProbe; the sizes are
// checked there), and the GLSL port of lookup_irradiance() (nodes/gi/probes/probe_lookup.cpp)
// and lookup_volumes(), line by line: change one, change the other.
#ifndef LG_PROBE_VOLUME_GLSL
#define LG_PROBE_VOLUME_GLSL

const int LG_PROBE_IRRADIANCE_TEXELS = 6;  // kProbeIrradianceTexels
const int LG_PROBE_DISTANCE_TEXELS = 14;   // kProbeDistanceTexels

struct ProbeVolume {
  mat4 world_from_grid;  // probe (i, j, k) at (i, j, k)
  mat4 grid_from_world;
  ivec4 counts;  // xyz: probes along each axis (at least 1); w: the volume's first probe
  vec4 cell;     // x: the smallest spacing in world units (ProbeGrid::min_spacing)
};

struct Probe {
  vec4 position;  // xyz: the grid point plus its relocation, world space; w: 1 active, 0 off
  vec4 sh[9];     // rgb
  vec4 ambient_cube[6];
  vec4 irradiance[LG_PROBE_IRRADIANCE_TEXELS * LG_PROBE_IRRADIANCE_TEXELS];  // row by row
  vec2 distance[LG_PROBE_DISTANCE_TEXELS * LG_PROBE_DISTANCE_TEXELS];        // mean, mean square
};

// ProbeRepresentation
const uint LG_PROBE_SH_L1 = 0u, LG_PROBE_SH_L2 = 1u, LG_PROBE_AMBIENT_CUBE = 2u, LG_PROBE_OCTAHEDRAL = 3u;

// octahedral_map.cpp
vec2 octahedral_encode(vec3 d) {
  vec2 p = d.xy / (abs(d.x) + abs(d.y) + abs(d.z));
  if (d.z < 0.0) p = (1.0 - abs(p.yx)) * vec2(p.x >= 0.0 ? 1.0 : -1.0, p.y >= 0.0 ? 1.0 : -1.0);
  return p * 0.5 + 0.5;
}

ivec2 octahedral_wrap(int i, int j, int k) {
  bool out_i = i < 0 || i >= k, out_j = j < 0 || j >= k;
  if (out_i && out_j) return ivec2(i < 0 ? k - 1 : 0, j < 0 ? k - 1 : 0);
  if (out_i) return ivec2(i < 0 ? 0 : k - 1, k - 1 - j);
  if (out_j) return ivec2(k - 1 - i, j < 0 ? 0 : k - 1);
  return ivec2(i, j);
}

// The bilinear taps of `d` in a k x k map: texel indices (row by row) and weights.
void octahedral_taps(vec3 d, int k, out int texel[4], out float weight[4]) {
  vec2 p = octahedral_encode(d) * float(k) - 0.5;
  vec2 f = floor(p), t = p - f;
  for (int n = 0; n < 4; ++n) {
    int dx = n & 1, dy = n >> 1;
    ivec2 c = octahedral_wrap(int(f.x) + dx, int(f.y) + dy, k);
    texel[n] = c.y * k + c.x;
    weight[n] = (dx != 0 ? t.x : 1.0 - t.x) * (dy != 0 ? t.y : 1.0 - t.y);
  }
}

layout(std430, binding = LG_PROBE_VOLUME_BINDING) readonly buffer ProbeVolumes { ProbeVolume volumes[]; };
layout(std430, binding = LG_PROBE_BINDING) readonly buffer Probes { Probe probes[]; };

vec3 sample_irradiance_map(int p, vec3 d) {
  int texel[4];
  float weight[4];
  octahedral_taps(d, LG_PROBE_IRRADIANCE_TEXELS, texel, weight);
  vec3 sum = vec3(0.0);
  for (int n = 0; n < 4; ++n) sum += weight[n] * probes[p].irradiance[texel[n]].rgb;
  return sum;
}

vec2 sample_distance_map(int p, vec3 d) {
  int texel[4];
  float weight[4];
  octahedral_taps(d, LG_PROBE_DISTANCE_TEXELS, texel, weight);
  vec2 sum = vec2(0.0);
  for (int n = 0; n < 4; ++n) sum += weight[n] * probes[p].distance[texel[n]];
  return sum;
}

// probe_irradiance(). The SH basis up to band 2 in closed form: the env basis (sh_basis.glsl:
// orthonormal, index l (l + 1) + m, no Condon-Shortley phase), without its band-4 loop and array.
vec3 probe_irradiance(int p, vec3 n, uint representation) {
  if (representation == LG_PROBE_OCTAHEDRAL) return sample_irradiance_map(p, n);
  if (representation == LG_PROBE_AMBIENT_CUBE) {
    vec3 e = vec3(0.0);
    for (int a = 0; a < 3; ++a) e += n[a] * n[a] * probes[p].ambient_cube[2 * a + (n[a] < 0.0 ? 1 : 0)].rgb;
    return e;
  }
  vec3 e = 0.282095 * probes[p].sh[0].rgb + 0.488603 * (n.y * probes[p].sh[1].rgb + n.z * probes[p].sh[2].rgb +
                                                        n.x * probes[p].sh[3].rgb);
  if (representation == LG_PROBE_SH_L2)
    e += 1.092548 * (n.x * n.y * probes[p].sh[4].rgb + n.y * n.z * probes[p].sh[5].rgb +
                     n.x * n.z * probes[p].sh[7].rgb) +
         0.315392 * (3.0 * n.z * n.z - 1.0) * probes[p].sh[6].rgb +
         0.546274 * (n.x * n.x - n.y * n.y) * probes[p].sh[8].rgb;
  return max(e, vec3(0.0));
}

struct ProbeLookup {
  uint representation;
  bool visibility;
  float normal_bias, view_bias;  // in cells
};

// Cells from grid coordinates `g` to the nearest face of the box grown by half a cell (negative
// outside): where a volume serves.
float probe_volume_margin(vec3 g, ivec3 counts) {
  vec3 m = min(g + 0.5, vec3(counts) - 0.5 - g);
  return min(m.x, min(m.y, m.z));
}

// lookup_irradiance(): rgb the irradiance, a 1; vec4(0) where the volume does not serve.
vec4 lookup_irradiance(int v, vec3 position, vec3 n, vec3 eye, ProbeLookup s) {
  mat4 grid_from_world = volumes[v].grid_from_world;
  ivec3 counts = volumes[v].counts.xyz;
  int first = volumes[v].counts.w;
  vec3 g = (grid_from_world * vec4(position, 1.0)).xyz;
  if (!(probe_volume_margin(g, counts) >= 0.0)) return vec4(0.0);
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
    int p = first + (c.z * counts.y + c.y) * counts.x + c.x;
    vec4 probe_position = probes[p].position;
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
        vec2 moments = sample_distance_map(p, from_probe / distance);
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
    sum += weight * probe_irradiance(p, n, s.representation);
    total += weight;
  }
  if (!(total > 0.0)) return vec4(0.0);
  return vec4(sum / total, 1.0);
}

// lookup_volumes(): every volume's irradiance weighted by smoothstep(0, LG_PROBE_VOLUME_RAMP,
// margin), so that a volume fades out toward its border; rgb the blend, a the coverage (the
// weights' sum, at most 1). vec4(0) outside every volume.
const float LG_PROBE_VOLUME_RAMP = 0.25;  // kVolumeBlendRamp, in cells
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
