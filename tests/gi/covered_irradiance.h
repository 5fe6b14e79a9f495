// What a GI node's irradiance output shows (rgb W/m^2, a its coverage), for the tests of gi.lpv
// and gi.voxel: how many pixels it covers (a > 0.5), the mean green irradiance over them (0 where
// none), and how many of its values are not finite.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

namespace lg::test {

struct CoveredIrradiance {
  double mean_green = 0;
  size_t covered = 0;
  size_t non_finite = 0;
};

inline CoveredIrradiance covered_irradiance(const std::vector<float>& rgba) {
  CoveredIrradiance c;
  for (size_t i = 0; i + 3 < rgba.size(); i += 4) {
    for (size_t k = 0; k < 4; ++k) c.non_finite += !std::isfinite(rgba[i + k]);
    if (rgba[i + 3] > 0.5f) c.mean_green += rgba[i + 1], ++c.covered;
  }
  if (c.covered) c.mean_green /= double(c.covered);
  return c;
}

}  // namespace lg::test
