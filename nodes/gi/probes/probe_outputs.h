// Writing a whole probe bake (a single run or a merge): the .lgprobes file and beside it, per
// volume, VTK image data for ParaView and the inspector: NAME.vti for a scene with one volume,
// NAME.0.vti, NAME.1.vti... for more (NAME: the path without its extension), with point arrays
// irradiance_up (toward +Y, from the octahedral map; the active scalars), mean_irradiance (the SH
// DC term: the mean over all normals), active (1 or 0) and offset (the relocation, world space;
// the active vectors). Points sit at the probes' grid points, not relocated.
#pragma once

#include <string>
#include <vector>

#include "nodes/gi/probes/probe_file.h"

namespace lg {

// The .vti of one volume's grid.
std::string encode_probe_vti(const ProbeGrid& grid, const std::string& comment);

// Writes `path` and its .vti files; returns every path written. Throws BakeFileError naming the
// file that failed.
std::vector<std::string> write_probe_outputs(const std::string& path, const ProbeFile& whole);

}  // namespace lg
