// A baked irradiance volume: probes on a regular grid filling a box (IrradianceVolumeData), the
// corners included, each holding its irradiance over the sphere of normals in the forms the
// lookup can choose from, and in the DDGI layout (Majercik et al. 2019, "Dynamic Diffuse Global
// Illumination with Ray-Traced Irradiance Fields") the distance to the surfaces around it:
// - SH: irradiance as 9 coefficients per channel (L2; its first 4 are L1), in the env basis
//   (nodes/env/common/sh_basis.h);
// - ambient cube: irradiance toward +X, -X, +Y, -Y, +Z, -Z (read back with weights n_i^2);
// - octahedral: irradiance at the centre of each of 6 x 6 texels (octahedral_map.h);
// - distance: the mean and mean square of the distance to the nearest surface, weighted by
//   cos^50 about each of 14 x 14 texels, for Chebyshev visibility.
// Every probe is also classified (off: inside geometry, seeing mostly back faces) and may sit
// moved from its grid point (relocation, at most half a cell along each axis). Probes are
// numbered x fastest, then y, then z. Light straight from the scene's lights is not in them:
// lighting.deferred adds it; what they hold is the environment and every bounce.
#pragma once

#include <array>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "runtime/scene/scene_view.h"

namespace lg {

inline constexpr int kProbeIrradianceTexels = 6;
inline constexpr int kProbeDistanceTexels = 14;
inline constexpr int kProbeShCount = 9;

struct ProbeData {
  bool active = false;
  glm::vec3 offset{0.0f};  // relocation, world space
  std::array<glm::vec3, kProbeShCount> sh{};
  std::array<glm::vec3, 6> ambient_cube{};
  std::array<glm::vec3, kProbeIrradianceTexels * kProbeIrradianceTexels> irradiance{};  // row by row
  std::array<glm::vec2, kProbeDistanceTexels * kProbeDistanceTexels> distance{};        // mean, mean square

  bool operator==(const ProbeData&) const = default;
};

// The probes of a volume: its counts, each at least 1, multiplied.
size_t probe_count(const IrradianceVolumeData& volume);

class ProbeGrid {
 public:
  explicit ProbeGrid(const IrradianceVolumeData& volume);

  const IrradianceVolumeData& volume() const { return volume_; }
  glm::ivec3 counts() const { return counts_; }
  size_t probe_count() const { return size_t(counts_.x) * counts_.y * counts_.z; }
  size_t index(glm::ivec3 cell) const { return (size_t(cell.z) * counts_.y + cell.y) * counts_.x + cell.x; }
  glm::ivec3 cell(size_t index) const;
  // The probe's grid point in world space (without its relocation).
  glm::dvec3 grid_position(size_t index) const;
  // The spacing along each local axis (the whole size where a count is 1) and the smallest one
  // in world units that is not 0.
  glm::dvec3 spacing() const { return spacing_; }
  double min_spacing() const;
  // World space to the volume's grid coordinates: probe (i, j, k) at (i, j, k).
  glm::dvec3 grid_coordinates(glm::dvec3 world) const;
  // The local axes in world space, scaled to one cell each (for offsets per axis).
  glm::dvec3 axis(int a) const { return axes_[a]; }

  std::vector<ProbeData> probes;

 private:
  IrradianceVolumeData volume_;
  glm::ivec3 counts_;
  glm::dvec3 spacing_;
  glm::dmat4 world_from_grid_, grid_from_world_;
  glm::dvec3 axes_[3];
};

}  // namespace lg
