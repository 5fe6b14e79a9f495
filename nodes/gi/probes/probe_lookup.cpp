#include "nodes/gi/probes/probe_lookup.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "nodes/env/common/sh_basis.h"
#include "nodes/gi/probes/octahedral_map.h"

namespace lg {
namespace {

template <size_t N, class T>
glm::dvec3 sample_map(const std::array<T, N>& map, glm::dvec3 direction, int k) {
  const OctahedralTaps taps = octahedral_taps(direction, k);
  glm::dvec3 sum(0.0);
  for (int n = 0; n < 4; ++n) {
    const T& texel = map[size_t(taps.texel[n].y) * k + taps.texel[n].x];
    if constexpr (std::is_same_v<T, glm::vec3>)
      sum += taps.weight[n] * glm::dvec3(texel);
    else
      sum += taps.weight[n] * glm::dvec3(texel.x, texel.y, 0.0);
  }
  return sum;
}

}  // namespace

double volume_margin(glm::dvec3 g, glm::ivec3 counts) {
  constexpr double grow = kVolumeServedCells + kVolumeBlendRamp;
  double m = g.x + grow;
  for (int a = 0; a < 3; ++a) m = std::min({m, g[a] + grow, counts[a] - 1 + grow - g[a]});
  return m;
}

const char* probe_representation_name(ProbeRepresentation r) {
  switch (r) {
    case ProbeRepresentation::sh_l1:
      return "sh_l1";
    case ProbeRepresentation::sh_l2:
      return "sh_l2";
    case ProbeRepresentation::ambient_cube:
      return "ambient_cube";
    case ProbeRepresentation::octahedral:
      return "octahedral";
  }
  return "?";
}

std::optional<ProbeRepresentation> parse_probe_representation(const std::string& name) {
  for (ProbeRepresentation r : {ProbeRepresentation::sh_l1, ProbeRepresentation::sh_l2,
                                ProbeRepresentation::ambient_cube, ProbeRepresentation::octahedral})
    if (name == probe_representation_name(r)) return r;
  return std::nullopt;
}

glm::dvec3 probe_irradiance(const ProbeData& probe, glm::dvec3 n, ProbeRepresentation representation) {
  switch (representation) {
    case ProbeRepresentation::sh_l1:
    case ProbeRepresentation::sh_l2: {
      double basis[kProbeShCount];
      sh_evaluate(2, n, basis);
      const int count = representation == ProbeRepresentation::sh_l1 ? 4 : kProbeShCount;
      glm::dvec3 e(0.0);
      for (int c = 0; c < count; ++c) e += glm::dvec3(probe.sh[c]) * basis[c];
      return glm::max(e, 0.0);
    }
    case ProbeRepresentation::ambient_cube: {
      glm::dvec3 e(0.0);
      for (int a = 0; a < 3; ++a) e += n[a] * n[a] * glm::dvec3(probe.ambient_cube[2 * a + (n[a] < 0.0 ? 1 : 0)]);
      return e;
    }
    case ProbeRepresentation::octahedral:
      return sample_map(probe.irradiance, n, kProbeIrradianceTexels);
  }
  return glm::dvec3(0.0);
}

std::optional<glm::dvec3> lookup_irradiance(const ProbeGrid& grid, glm::dvec3 position, glm::dvec3 n, glm::dvec3 eye,
                                            const ProbeLookupSettings& settings) {
  const glm::dvec3 g = grid.grid_coordinates(position);
  const glm::ivec3 counts = grid.counts();
  if (!(volume_margin(g, counts) >= 0.0)) return std::nullopt;  // beyond the fade
  const double cell = grid.min_spacing();
  const glm::dvec3 to_eye = glm::normalize(eye - position);
  const glm::dvec3 biased = position + (n * settings.normal_bias + to_eye * settings.view_bias) * cell;
  const glm::dvec3 gb = glm::clamp(grid.grid_coordinates(biased), glm::dvec3(0.0), glm::dvec3(counts - 1));
  const glm::ivec3 base = glm::min(glm::ivec3(glm::floor(gb)), glm::max(counts - 2, glm::ivec3(0)));
  const glm::dvec3 alpha = glm::clamp(gb - glm::dvec3(base), 0.0, 1.0);
  glm::dvec3 sum(0.0);
  double total = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::ivec3 step(corner & 1, (corner >> 1) & 1, corner >> 2);
    const glm::ivec3 c = glm::min(base + step, counts - 1);
    const size_t index = grid.index(c);
    const ProbeData& probe = grid.probes[index];
    if (!probe.active) continue;
    double trilinear = 1.0;
    for (int a = 0; a < 3; ++a) trilinear *= step[a] ? alpha[a] : 1.0 - alpha[a];
    const glm::dvec3 probe_position = grid.grid_position(index) + glm::dvec3(probe.offset);
    const glm::dvec3 to_probe = probe_position - position;
    const double to_probe_length = glm::length(to_probe);
    const double facing = to_probe_length > 0.0 ? glm::dot(to_probe / to_probe_length, n) : 1.0;
    double weight = (facing + 1.0) * 0.5;
    weight = weight * weight + 0.2;
    if (settings.visibility) {
      const glm::dvec3 from_probe = biased - probe_position;
      const double distance = glm::length(from_probe);
      if (distance > 0.0) {
        const glm::dvec3 moments = sample_map(probe.distance, from_probe / distance, kProbeDistanceTexels);
        if (distance > moments.x) {
          const double variance = std::abs(moments.y - moments.x * moments.x);
          const double d = distance - moments.x;
          const double chebyshev = variance / (variance + d * d);
          weight *= std::max(chebyshev * chebyshev * chebyshev, 0.05);
        }
      }
    }
    weight = std::max(weight, 1e-6);
    constexpr double crush = 0.2;
    if (weight < crush) weight *= weight * weight / (crush * crush);
    weight *= trilinear;
    sum += weight * probe_irradiance(probe, n, settings.representation);
    total += weight;
  }
  if (!(total > 0.0)) return std::nullopt;
  return sum / total;
}

VolumeIrradiance lookup_volumes(std::span<const ProbeGrid> grids, glm::dvec3 position, glm::dvec3 n, glm::dvec3 eye,
                                const ProbeLookupSettings& settings) {
  glm::dvec3 sum(0.0);
  double total = 0.0;
  for (const ProbeGrid& grid : grids) {
    const double margin = volume_margin(grid.grid_coordinates(position), grid.counts());
    if (!(margin > 0.0)) continue;
    const std::optional<glm::dvec3> e = lookup_irradiance(grid, position, n, eye, settings);
    if (!e) continue;
    const double t = std::clamp(margin / kVolumeBlendRamp, 0.0, 1.0);
    const double w = t * t * (3.0 - 2.0 * t);  // GLSL's smoothstep
    sum += w * *e;
    total += w;
  }
  if (!(total > 0.0)) return {};
  return {sum / total, std::min(total, 1.0)};
}

}  // namespace lg
