// The inspector's view of a probe bake (`lumagraph bake --mode probes`, NAME.lgprobes), one
// volume at a time: every probe a small sphere shaded by the irradiance it stores for each
// normal (its octahedral map), probes that are off (inside geometry) small and red, relocation
// offsets as yellow lines from the grid point to the probe, the volume's box, and a slice across
// the volume's up axis of the irradiance the DDGI lookup interpolates there for up-facing
// surfaces (nodes/gi/probes/probe_lookup.h). A probe picked by a click (or by index) shows its
// octahedral irradiance and distance maps; the widget draws those, this file only gives them.
#pragma once

#include <array>
#include <cstddef>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "nodes/gi/probes/probe_file.h"

class vtkRenderer;

namespace lg {

struct ProbeBake {
  std::string path;
  ProbeFile file;
  std::vector<ProbeGrid> grids;  // one per volume, with its probes
};

// The whole bake at `path`; throws BakeFileError naming it when it is missing, damaged, or one
// chunk of a bake (which has to be merged first).
ProbeBake load_probe_bake(const std::string& path);

// What the view shows, for the widget's caption and for tests.
struct ProbeViewState {
  size_t volume = 0, volumes = 0;
  glm::ivec3 counts{0};
  size_t probes = 0, active = 0, relocated = 0;
  double largest_offset = 0;                    // world units
  int slice = 0, slices = 0;                    // the slice's step along the up axis, quarter cells apart
  double slice_height = 0;                      // in grid coordinates along the up axis (probe j at j)
  size_t slice_samples = 0, slice_covered = 0;  // points of the slice, and those the lookup reaches
  double exposure = 1;                          // display scale: 0.6 over the mean probe irradiance
  std::optional<size_t> selected;
};

// A probe's maps as they are stored: irradiance per texel (6 x 6) and mean distance (14 x 14),
// row by row, texel (i, j) at index j * k + i.
struct ProbeMaps {
  size_t probe = 0;
  glm::ivec3 cell{0};
  glm::dvec3 position{0.0};  // relocated
  bool active = false;
  std::vector<glm::vec3> irradiance;
  std::vector<float> distance;
};

class ProbeView {
 public:
  // Adds the probes of volume `volume` of `bake` (which must outlive the view), the box, the slice,
  // the title and the camera to `renderer`. Throws std::out_of_range for a volume the bake lacks.
  // `exposure`: the display's scale, by default chosen from the probes (ProbeViewState::exposure);
  // a live view that refreshes keeps the first one, so that light converging shows as change.
  ProbeView(vtkRenderer* renderer, const ProbeBake& bake, size_t volume, std::optional<double> exposure = {});
  ~ProbeView();

  void set_slice(int step);  // clamped to [0, slices - 1]
  // The probe whose sphere is under display point (x, y) of the renderer, if any.
  std::optional<size_t> pick(int x, int y);
  void select(size_t probe);  // outlines it; ignored past the last probe
  ProbeMaps maps(size_t probe) const;
  ProbeViewState state() const;
  // The display point of a probe's centre, for tests that click on it.
  std::array<double, 2> display_point(size_t probe) const;

 private:
  struct Pipeline;
  std::unique_ptr<Pipeline> pipeline_;
};

}  // namespace lg
