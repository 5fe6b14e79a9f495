#include "nodes/gi/probes/probe_difference.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "nodes/gi/path_tracer/path_transport.h"
#include "nodes/gi/probes/probe_directions.h"

namespace lg {
namespace {

// Sums of squared differences and of reference values, and their count.
struct Sums {
  double squared = 0.0, reference = 0.0, value = 0.0;
  size_t n = 0;
  void add(glm::dvec3 v, glm::dvec3 reference_value) {
    for (int c = 0; c < 3; ++c) {
      const double d = v[c] - reference_value[c];
      squared += d * d, reference += reference_value[c], value += v[c], ++n;
    }
  }
  double relative_rms() const { return n > 0 && reference > 0.0 ? std::sqrt(squared / n) / (reference / n) : 0.0; }
};

}  // namespace

double probe_relative_rms(std::span<const ProbeGrid> probes, std::span<const ProbeGrid> reference) {
  if (probes.size() != reference.size()) throw std::invalid_argument("probe_relative_rms: different volumes");
  Sums sums;
  for (size_t v = 0; v < probes.size(); ++v) {
    if (probes[v].probe_count() != reference[v].probe_count())
      throw std::invalid_argument("probe_relative_rms: volume " + std::to_string(v) + " differs in its probes");
    for (size_t i = 0; i < probes[v].probe_count(); ++i) {
      const ProbeData &a = probes[v].probes[i], &b = reference[v].probes[i];
      if (!a.active || !b.active) continue;
      for (size_t t = 0; t < a.irradiance.size(); ++t)
        sums.add(glm::dvec3(a.irradiance[t]), glm::dvec3(b.irradiance[t]));
    }
  }
  return sums.relative_rms();
}

std::vector<ServedPoint> served_points(const PathScene& scene, std::span<const ProbeGrid> grids, uint32_t per_probe) {
  const PathTransport transport(scene, 1);
  std::vector<ServedPoint> points;
  for (const ProbeGrid& grid : grids)
    for (size_t i = 0; i < grid.probe_count(); ++i) {
      const ProbeData& p = grid.probes[i];
      if (!p.active) continue;
      const glm::dvec3 eye = grid.grid_position(i) + glm::dvec3(p.offset);
      const glm::dmat3 rotation = random_rotation(i);
      for (uint32_t r = 0; r < per_probe; ++r)
        if (const auto s = transport.visible_surface(eye, sphere_direction(r, per_probe, rotation), false))
          points.push_back({s->position, s->normal, eye});
    }
  return points;
}

LookupDifference lookup_difference(std::span<const ProbeGrid> probes, std::span<const ProbeGrid> reference,
                                   std::span<const ServedPoint> points, const ProbeLookupSettings& settings) {
  Sums sums;
  for (const ServedPoint& p : points) {
    const VolumeIrradiance a = lookup_volumes(probes, p.position, p.normal, p.eye, settings);
    const VolumeIrradiance b = lookup_volumes(reference, p.position, p.normal, p.eye, settings);
    sums.add(a.irradiance * a.coverage, b.irradiance * b.coverage);
  }
  return {sums.relative_rms(), sums.reference > 0.0 ? sums.value / sums.reference : 0.0};
}

}  // namespace lg
