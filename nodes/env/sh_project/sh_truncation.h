// The truncation error of SH irradiance of an environment, measured as env.sh_project's
// benchmark does (tests/bench/env_bench.cpp): the irradiance of the double-precision projection
// (order `order`, cosine-convolved, no window) against brute-force irradiance, relative RMS over
// `directions` random directions and the three channels. The yardstick the SH-based GI nodes
// (gi.prt) are held to.
#pragma once

#include <cstdint>

#include "nodes/env/common/cube_map.h"

namespace lg {

double sh_irradiance_truncation_rms(const CubeImage& env, int order, int directions = 200, uint64_t seed = 7);

}  // namespace lg
