// gi.prt's frame against the path-traced reference, shared by its accuracy test and its
// benchmark: per pixel the node covers (coverage 1) and the reference sees a surface, per
// channel, the relative difference between the node's irradiance and the reference's,
// E = pi x indirect_diffuse / the visible surface's diffuse colour (what lighting.ibl multiplies
// the node's output by). The reference's own noise (its standard error, relative) is stated, and
// the RMS beyond it (mean squares subtracted: independent errors add in squares). Also the RMS of
// the absolute differences over the reference's mean, as lumagraph-bench-probes measures
// relative_rms (no single dark pixel dominates it; predicting 0 everywhere gives at least 1).
#pragma once

#include <cstddef>
#include <vector>

#include "nodes/gi/path_tracer/path_tracer.h"

namespace lg::test {

struct PrtComparison {
  double relative_rms = 0, reference_noise = 0, beyond_noise = 0;
  double rms_over_mean = 0, noise_over_mean = 0;  // the probe benchmark's measure, and the reference's noise in it
  double mean_over_mean = 0;                      // the frame's mean over the reference's: 1 unbiased, below 1 too dark
  size_t values = 0;                              // pixels x channels compared
};

// `frame`: the node's irradiance output read back (RGBA floats, rows top down, the reference's
// size); `scene`: what the reference was traced in.
PrtComparison compare_with_reference(const PathScene& scene, const ReferenceImage& reference,
                                     const std::vector<float>& frame);

}  // namespace lg::test
