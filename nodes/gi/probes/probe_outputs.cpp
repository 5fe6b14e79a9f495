// The .vti files of a whole probe bake (probe_outputs.h).
#include "nodes/gi/probes/probe_outputs.h"

#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <numbers>

#include "nodes/gi/probes/probe_lookup.h"
#include "nodes/raytrace/vti_file.h"

namespace lg {

std::string encode_probe_vti(const ProbeGrid& grid, const std::string& comment) {
  std::vector<float> up, mean, active, offset;
  // Y_00 = 1 / (2 sqrt(pi)) and the basis is orthonormal, so the mean of E over the sphere is c_00 Y_00.
  const double y00 = 0.5 / std::sqrt(std::numbers::pi);
  for (const ProbeData& p : grid.probes) {
    const glm::dvec3 e = probe_irradiance(p, {0.0, 1.0, 0.0}, ProbeRepresentation::octahedral);
    const glm::dvec3 m = glm::dvec3(p.sh[0]) * y00;
    up.insert(up.end(), {float(e.x), float(e.y), float(e.z)});
    mean.insert(mean.end(), {float(m.x), float(m.y), float(m.z)});
    active.push_back(p.active ? 1.0f : 0.0f);
    offset.insert(offset.end(), {p.offset.x, p.offset.y, p.offset.z});
  }
  VtiImage image;
  image.comment = comment;
  const glm::ivec3 counts = grid.counts();
  image.dims = {uint32_t(counts.x), uint32_t(counts.y), uint32_t(counts.z)};
  image.origin = grid.grid_position(0);
  for (int a = 0; a < 3; ++a) {
    // A volume's frame may turn it: VTK's direction matrix carries the unit axes.
    const double length = glm::length(grid.axis(a));
    image.spacing[a] = length;
    image.direction[a] = length > 0.0 ? grid.axis(a) / length : glm::dvec3(0.0);
    if (length == 0.0) image.direction[a][a] = 1.0;
  }
  image.arrays = {{"irradiance_up", 3, up}, {"mean_irradiance", 3, mean}, {"active", 1, active}, {"offset", 3, offset}};
  image.scalars = "irradiance_up", image.vectors = "offset";
  return encode_vti(image);
}

std::vector<std::string> write_probe_outputs(const std::string& path, const ProbeFile& whole) {
  write_probe_file(path, whole);
  std::vector<std::string> written{path};
  const std::vector<ProbeGrid> grids = probe_grids(whole);
  for (size_t v = 0; v < grids.size(); ++v) {
    const std::string extension = grids.size() == 1 ? ".vti" : "." + std::to_string(v) + ".vti";
    written.push_back(std::filesystem::path(path).replace_extension(extension).string());
    const std::string comment = "lumagraph probe bake of " + whole.header.scene + ", volume " + std::to_string(v) +
                                ": " + std::to_string(whole.header.settings.rays) +
                                " rays a probe; active 0 marks probes inside geometry (docs/probe-format.md)";
    write_bake_bytes(written.back(), encode_probe_vti(grids[v], comment));
  }
  return written;
}

}  // namespace lg
