// A probe's captured cube as gi.reflection_capture's kernel holds it, before the prefilter, for
// tests and tools that compare captures (raster against path-traced). The executor owns kernels;
// a caller asks one through this interface (dynamic_cast from NodeKernel), between frames.
#pragma once

#include <cstdint>
#include <vector>

namespace lg {

class Submitter;

class CapturedCubeSource {
 public:
  virtual ~CapturedCubeSource() = default;
  // Face `face` (cube_map.h's order) of probe `probe`'s last capture as float RGBA, rows top to
  // bottom; throws std::out_of_range for a probe the kernel has no cube of.
  virtual std::vector<float> read_captured_face(Submitter& submitter, uint32_t probe, int face) = 0;
};

}  // namespace lg
