// Part files of a chunked reference: written and read back unchanged, merged into the whole
// image bit for bit, and refused with a message naming the file when they do not make one run.
#include "nodes/gi/path_tracer/reference_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace lg::test {
namespace {

namespace fs = std::filesystem;

// A run's chunk with made-up pixel values that differ per chunk, AOV and pixel.
ReferencePart make_part(uint32_t index, uint32_t count, const std::string& run = "scene=a spp=4") {
  ReferencePart part;
  part.run = run, part.chunk_index = index, part.chunk_count = count;
  ReferenceImage& im = part.image;
  im.width = 5, im.height = 7;
  chunk_rows(im.height, index, count, im.row_begin, im.row_end);
  im.non_finite_samples = index;
  for (size_t a = 0; a < kReferenceAovCount; ++a)
    for (size_t i = 0; i < im.pixel_count(); ++i) {
      const float v = float(a * 1000 + (im.row_begin * im.width + i)) + 0.125f;
      im.mean[a].push_back({v, v + 0.5f, -v});
      im.standard_error[a].push_back({v / 7.0f, 0.0f, 1e-30f});
    }
  return part;
}

class ReferenceFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(LUMAGRAPH_BINARY_DIR) / "reference-file-test";
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(ReferenceFile, ChunkRowsCoverTheImageOnce) {
  uint32_t next = 0;
  for (uint32_t i = 0; i < 3; ++i) {
    uint32_t begin = 0, end = 0;
    chunk_rows(7, i, 3, begin, end);
    EXPECT_EQ(begin, next);
    EXPECT_GE(end - begin, 2u);
    next = end;
  }
  EXPECT_EQ(next, 7u);
}

TEST_F(ReferenceFile, PartsRoundTripAndMergeInAnyOrder) {
  std::vector<ReferencePart> read;
  std::vector<std::string> paths;
  for (uint32_t i : {2u, 0u, 1u}) {
    paths.push_back(path("part" + std::to_string(i)));
    write_reference_part(paths.back(), make_part(i, 3));
    read.push_back(read_reference_part(paths.back()));
    EXPECT_EQ(read.back().run, "scene=a spp=4");
    EXPECT_EQ(read.back().image.mean, make_part(i, 3).image.mean);
    EXPECT_EQ(read.back().image.standard_error, make_part(i, 3).image.standard_error);
  }
  const ReferenceImage merged = merge_reference_parts(read, paths);
  ASSERT_EQ(merged.pixel_count(), 35u);
  EXPECT_EQ(merged.non_finite_samples, 3u);
  const ReferencePart whole = make_part(0, 1);
  EXPECT_EQ(merged.mean, whole.image.mean);
  EXPECT_EQ(merged.standard_error, whole.image.standard_error);
}

TEST_F(ReferenceFile, MergeRefusesPartsThatAreNotOneRun) {
  auto message = [&](const std::vector<ReferencePart>& parts) {
    std::vector<std::string> paths;
    for (size_t i = 0; i < parts.size(); ++i) paths.push_back("p" + std::to_string(i));
    try {
      merge_reference_parts(parts, paths);
    } catch (const ReferenceFileError& e) {
      return std::string(e.what());
    }
    return std::string("merged");
  };
  EXPECT_EQ(message({make_part(0, 2)}), "chunk 1 of 2 is missing");
  EXPECT_EQ(message({make_part(0, 2), make_part(0, 2)}), "p1: error: chunk 0 is given twice");
  EXPECT_NE(message({make_part(0, 2), make_part(1, 2, "scene=b spp=4")}).find("p1: error: belongs to another run"),
            std::string::npos);
}

TEST_F(ReferenceFile, ReadingABrokenPartNamesTheFileAndTheProblem) {
  auto message = [&](const std::string& text) {
    const std::string p = path("broken");
    std::ofstream(p, std::ios::binary) << text;
    try {
      read_reference_part(p);
    } catch (const ReferenceFileError& e) {
      return std::string(e.what()).substr(p.size());
    }
    return std::string("read");
  };
  EXPECT_EQ(message("P6\n"), ": error: not a reference part file (expected the first line 'lumagraph-reference/1')");
  EXPECT_EQ(message("lumagraph-reference/1\nchunk 0 1 width 5\n"),
            ": error: bad header line (expected 'chunk I N width W height H rows BEGIN END non_finite K')");
  EXPECT_EQ(message("lumagraph-reference/1\nchunk 0 1 width 5 height 7 rows 0 9 non_finite 0\nrun\n"),
            ": error: bad header: size, rows or chunk out of range");
  // A fuzzer's finding (fuzz/regressions/reference_part/): sscanf reads "-2" as 4294967294 chunks,
  // for which merging made a table of 32 GB.
  EXPECT_EQ(message("lumagraph-reference/1\nchunk 1 -2 width 3 height 4 rows 0 1 non_finite 0\nrun\n"),
            ": error: bad header: 4294967294 chunks, more than a run can have (65536)");
  EXPECT_EQ(message("lumagraph-reference/1\nchunk 0 1 width 5 height 7 rows 0 7 non_finite 0\nrun\n1234"),
            ": error: truncated: the pixels end early");
  const std::string whole = path("whole");
  write_reference_part(whole, make_part(0, 1));
  std::ofstream(whole, std::ios::app) << "x";
  EXPECT_THROW(read_reference_part(whole), ReferenceFileError);
}

}  // namespace
}  // namespace lg::test
