// The .lgprobes file and its .vti (nodes/gi/probes/probe_file.h, probe_outputs.h): a file read
// back equals what was written, probe for probe and bit for bit; damaged files fail with a
// message naming the file and what is wrong; merging refuses parts that do not fit and gives
// the single run's bytes; VTK's own reader (what ParaView uses) reads every volume's grid.
#include "nodes/gi/probes/probe_file.h"

#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLImageDataReader.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>

#include "nodes/gi/probes/probe_lookup.h"
#include "nodes/gi/probes/probe_outputs.h"

namespace lg {
namespace {

namespace fs = std::filesystem;

// Two volumes, the second turned and moved, every probe's every float drawn at random (a
// file of zeros would not show a swapped or misplaced array); every fifth probe off.
ProbeFile random_bake(uint32_t chunk_index = 0, uint32_t chunk_count = 1) {
  IrradianceVolumeData a, b;
  a.size = {2.0f, 1.0f, 3.0f}, a.probe_counts = {3, 2, 4};
  b.world = glm::rotate(glm::translate(glm::mat4(1.0f), {1.0f, 2.0f, -3.0f}), 0.7f, glm::vec3(0.0f, 1.0f, 0.0f));
  b.size = {1.5f, 0.5f, 1.0f}, b.probe_counts = {2, 3, 1};
  ProbeFile file;
  file.header = make_probe_header({a, b}, chunk_index, chunk_count);
  file.header.scene = "rooms.json", file.header.graph = "<default>", file.header.environment = "sky.hdr";
  file.header.geometry_hash = 0x0123456789abcdefull;
  file.header.settings = {.rays = 64, .bounces = 2, .seed = 9};
  std::mt19937 random(5);
  std::uniform_real_distribution<float> value(-2.0f, 2.0f);
  std::vector<ProbeData> all(file.header.probes);
  for (size_t i = 0; i < all.size(); ++i) {
    ProbeData& p = all[i];
    p.active = i % 5 != 0;
    float* floats = reinterpret_cast<float*>(&p.offset);
    const size_t count = (sizeof(ProbeData) - offsetof(ProbeData, offset)) / sizeof(float);
    for (size_t f = 0; f < count; ++f) floats[f] = value(random);
  }
  file.probes.assign(all.begin() + file.header.range.begin, all.begin() + file.header.range.end);
  return file;
}

struct TempFile {
  fs::path path = fs::temp_directory_path() / ("lumagraph-probe-file-" + std::to_string(::getpid()) + ".lgprobes");
  ~TempFile() { fs::remove(path); }
  std::string write(const std::string& bytes) const {
    std::ofstream(path, std::ios::binary) << bytes;
    return path.string();
  }
};

std::string read_error(const std::string& bytes) {
  TempFile file;
  try {
    read_probe_file(file.write(bytes));
  } catch (const BakeFileError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(file.path.string() + ": ", 0), 0u) << message;  // names the file first
    return message;
  }
  ADD_FAILURE() << "the file was read";
  return "";
}

TEST(ProbeFile, ReadsBackWhatWasWritten) {
  const ProbeFile file = random_bake();
  EXPECT_EQ(file.header.probes, 24u + 6u);
  TempFile temp;
  write_probe_file(temp.path.string(), file);
  const ProbeFile back = read_probe_file(temp.path.string());
  EXPECT_TRUE(back.probes == file.probes);
  const ProbeFileHeader &h = back.header, &w = file.header;
  EXPECT_EQ(h.scene, w.scene);
  EXPECT_EQ(h.graph, w.graph);
  EXPECT_EQ(h.environment, w.environment);
  EXPECT_EQ(h.geometry_hash, w.geometry_hash);
  EXPECT_EQ(h.settings.rays, 64u);
  EXPECT_EQ(h.settings.bounces, 2u);
  EXPECT_EQ(h.settings.seed, 9u);
  ASSERT_EQ(h.volumes.size(), 2u);
  for (size_t v = 0; v < 2; ++v) {
    EXPECT_EQ(h.volumes[v].world, w.volumes[v].world);  // floats through JSON text, exactly
    EXPECT_EQ(h.volumes[v].size, w.volumes[v].size);
    EXPECT_EQ(h.volumes[v].probe_counts, w.volumes[v].probe_counts);
  }
  EXPECT_EQ(encode_probe_file(back), encode_probe_file(file));
  const std::vector<ProbeGrid> grids = probe_grids(back);
  ASSERT_EQ(grids.size(), 2u);
  EXPECT_TRUE(grids[1].probes[0] == file.probes[24]);
}

TEST(ProbeFile, DamagedFilesSayWhatIsWrong) {
  const std::string good = encode_probe_file(random_bake());
  EXPECT_NE(read_error("").find("not a probe bake file (it does not start with LGPROBE1)"), std::string::npos);
  EXPECT_NE(read_error("LGBAKE01" + good.substr(8)).find("not a probe bake file"), std::string::npos);
  EXPECT_NE(read_error(good.substr(0, 40)).find("runs past the end of the file (truncated?)"), std::string::npos);
  EXPECT_NE(read_error(good.substr(0, good.size() - 4)).find("(truncated or damaged)"), std::string::npos);
  EXPECT_NE(read_error(good + "xxxx").find("(truncated or damaged)"), std::string::npos);
  {
    TempFile missing;
    EXPECT_THROW(read_probe_file(missing.path.string() + ".absent"), BakeFileError);
  }

  ProbeFile bad = random_bake();
  bad.probes[3].sh[2].y = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NE(read_error(encode_probe_file(bad)).find("probe 3: sh holds a non-finite value"), std::string::npos);
  bad = random_bake();
  bad.probes[7].distance[0].x = std::numeric_limits<float>::infinity();
  EXPECT_NE(read_error(encode_probe_file(bad)).find("probe 7: distance holds a non-finite value"), std::string::npos);

  // Counts out of range: the header says so before any probe is read.
  bad = random_bake();
  bad.header.volumes[0].probe_counts.x = 300;
  EXPECT_NE(read_error(encode_probe_file(bad)).find("volume 0: probe counts must be whole numbers from 1 to 256"),
            std::string::npos);
  bad = random_bake();
  bad.header.probes = 31;
  EXPECT_NE(read_error(encode_probe_file(bad)).find("the volumes hold 30 probes, the header says 31"),
            std::string::npos);
  bad = random_bake();
  bad.header.volumes[1].size.y = std::numeric_limits<float>::infinity();
  // JSON has no infinity: the writer leaves null, which the reader refuses.
  EXPECT_NE(read_error(encode_probe_file(bad)).find("header \"size\" must be a number"), std::string::npos);
  bad = random_bake();
  bad.header.volumes[1].size.z = 0.0f;
  EXPECT_NE(read_error(encode_probe_file(bad)).find("volume 1: size must be positive along every axis"),
            std::string::npos);
  bad = random_bake();
  bad.header.volumes.clear();
  EXPECT_NE(read_error(encode_probe_file(bad)).find("\"volumes\" must be an array of 1 to 65536 volumes"),
            std::string::npos);
  bad = random_bake(1, 3);
  bad.header.range.end -= 1;
  EXPECT_NE(read_error(encode_probe_file(bad)).find("chunk 1/3 must hold probes 10 to 20"), std::string::npos);
}

TEST(ProbeFile, MergeGivesTheSingleRunAndRefusesPartsThatDoNotFit) {
  const std::vector<std::string> paths{"p0", "p1", "p2"};
  const std::vector<ProbeFile> parts{random_bake(2, 3), random_bake(0, 3), random_bake(1, 3)};
  EXPECT_EQ(encode_probe_file(merge_probe_parts(parts, paths)), encode_probe_file(random_bake()));

  auto merge_error = [&](const std::vector<ProbeFile>& files) {
    try {
      merge_probe_parts(files, paths);
    } catch (const BakeFileError& e) {
      return std::string(e.what());
    }
    return std::string("merged");
  };
  ProbeFile other = random_bake(1, 3);
  other.header.settings.seed = 10;
  EXPECT_EQ(merge_error({parts[0], other, parts[1]}).rfind("p1: belongs to another probe bake than p0", 0), 0u);
  other = random_bake(1, 3);
  other.header.geometry_hash ^= 1;
  EXPECT_EQ(merge_error({parts[0], other, parts[1]}).rfind("p1: belongs to another probe bake", 0), 0u);
  EXPECT_EQ(merge_error({parts[0], parts[1], parts[1]}), "p2: chunk 0 is also in p1");
  EXPECT_EQ(merge_error({parts[0], parts[1]}), "merge: chunks missing of 3: 1");
  EXPECT_EQ(merge_error({parts[0], random_bake(0, 2)}), "p1: is a chunk of 2, p0 of 3");
}

TEST(ProbeFile, VtkReadsEveryVolumeGrid) {
  const ProbeFile file = random_bake();
  const std::vector<ProbeGrid> grids = probe_grids(file);
  const ProbeGrid& grid = grids[1];  // the turned volume
  TempFile temp;
  const fs::path path = temp.path.string() + ".vti";
  std::ofstream(path, std::ios::binary) << encode_probe_vti(grid, "test");
  auto reader = vtkSmartPointer<vtkXMLImageDataReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  fs::remove(path);
  vtkImageData* image = reader->GetOutput();
  ASSERT_NE(image, nullptr);
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(dims[0], 2);
  EXPECT_EQ(dims[1], 3);
  EXPECT_EQ(dims[2], 1);
  // VTK's own mapping of every point index to world space lands on the probe's grid point
  // (1e-6 m: float frame, double arithmetic on both sides).
  for (size_t i = 0; i < grid.probe_count(); ++i) {
    const glm::ivec3 c = grid.cell(i);
    const int ijk[3] = {c.x, c.y, c.z};
    double xyz[3];
    image->TransformIndexToPhysicalPoint(ijk, xyz);
    const glm::dvec3 expected = grid.grid_position(i);
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(xyz[a], expected[a], 1e-6) << i;
  }
  auto array = [&](const char* name, int components) {
    auto* a = vtkFloatArray::SafeDownCast(image->GetPointData()->GetArray(name));
    EXPECT_NE(a, nullptr) << name;
    if (a) {
      EXPECT_EQ(a->GetNumberOfComponents(), components) << name;
    }
    return a;
  };
  vtkFloatArray *up = array("irradiance_up", 3), *mean = array("mean_irradiance", 3), *active = array("active", 1),
                *offset = array("offset", 3);
  ASSERT_TRUE(up && mean && active && offset);
  for (size_t i = 0; i < grid.probe_count(); ++i) {
    const ProbeData& p = grid.probes[i];
    const glm::dvec3 e = probe_irradiance(p, {0.0, 1.0, 0.0}, ProbeRepresentation::octahedral);
    for (int c = 0; c < 3; ++c) {
      const vtkIdType at = vtkIdType(3 * i + c);
      EXPECT_EQ(up->GetValue(at), float(e[c]));
      EXPECT_EQ(mean->GetValue(at), float(p.sh[0][c] * (0.5 / std::sqrt(std::numbers::pi))));
      EXPECT_EQ(offset->GetValue(at), p.offset[c]);
    }
    EXPECT_EQ(active->GetValue(vtkIdType(i)), p.active ? 1.0f : 0.0f);
  }
  EXPECT_STREQ(image->GetPointData()->GetScalars()->GetName(), "irradiance_up");
  EXPECT_STREQ(image->GetPointData()->GetVectors()->GetName(), "offset");
}

}  // namespace
}  // namespace lg
