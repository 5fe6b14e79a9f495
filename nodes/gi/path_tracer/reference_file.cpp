#include "nodes/gi/path_tracer/reference_file.h"

#include <algorithm>
#include <bit>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "runtime/image/image_file.h"

namespace lg {
namespace {

constexpr const char* kMagic = "lumagraph-reference/1";
constexpr uint32_t kMaxSide = 65536;

static_assert(std::endian::native == std::endian::little, "part files store floats as the machine does");

ReferenceFileError error(const std::string& path, const std::string& what) {
  return ReferenceFileError(path + ": error: " + what);
}

}  // namespace

void chunk_rows(uint32_t height, uint32_t index, uint32_t count, uint32_t& row_begin, uint32_t& row_end) {
  const uint32_t base = height / count, extra = height % count;
  row_begin = index * base + std::min(index, extra);
  row_end = row_begin + base + (index < extra ? 1 : 0);
}

void write_reference_part(const std::string& path, const ReferencePart& part) {
  const ReferenceImage& im = part.image;
  char header[160];
  std::snprintf(header, sizeof header, "chunk %u %u width %u height %u rows %u %u non_finite %llu", part.chunk_index,
                part.chunk_count, im.width, im.height, im.row_begin, im.row_end,
                static_cast<unsigned long long>(im.non_finite_samples));
  const std::filesystem::path target(path);
  const std::filesystem::path temporary = target.parent_path() / ("." + target.filename().string() + ".partial");
  {
    std::ofstream out(temporary, std::ios::binary);
    out << kMagic << '\n' << header << '\n' << part.run << '\n';
    for (const auto* planes : {&im.mean, &im.standard_error})
      for (const std::vector<glm::vec3>& plane : *planes)
        out.write(reinterpret_cast<const char*>(plane.data()), std::streamsize(plane.size() * sizeof(glm::vec3)));
    if (!out.flush()) throw error(path, "writing failed");
  }
  std::error_code ec;
  std::filesystem::rename(temporary, target, ec);
  if (ec) throw error(path, "cannot replace the file: " + ec.message());
}

ReferencePart read_reference_part(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw error(path, "cannot open the file");
  std::string magic, header;
  ReferencePart part;
  if (!std::getline(in, magic) || magic != kMagic)
    throw error(path, "not a reference part file (expected the first line '" + std::string(kMagic) + "')");
  ReferenceImage& h = part.image;
  unsigned long long non_finite = 0;
  char tail = 0;
  if (!std::getline(in, header) ||
      std::sscanf(header.c_str(), "chunk %u %u width %u height %u rows %u %u non_finite %llu%c", &part.chunk_index,
                  &part.chunk_count, &h.width, &h.height, &h.row_begin, &h.row_end, &non_finite, &tail) != 7)
    throw error(path, "bad header line (expected 'chunk I N width W height H rows BEGIN END non_finite K')");
  h.non_finite_samples = non_finite;
  if (!std::getline(in, part.run)) throw error(path, "the run line is missing");
  const ReferenceImage& im = part.image;
  if (im.width == 0 || im.width > kMaxSide || im.height == 0 || im.height > kMaxSide || im.row_begin > im.row_end ||
      im.row_end > im.height || part.chunk_count == 0 || part.chunk_index >= part.chunk_count)
    throw error(path, "bad header: size, rows or chunk out of range");
  // Merging keeps a slot per chunk: a count no run can have would be gigabytes of them.
  if (part.chunk_count > max_reference_chunks)
    throw error(path, "bad header: " + std::to_string(part.chunk_count) + " chunks, more than a run can have (" +
                          std::to_string(max_reference_chunks) + ")");
  for (auto* planes : {&part.image.mean, &part.image.standard_error})
    for (std::vector<glm::vec3>& plane : *planes) {
      plane.resize(part.image.pixel_count());
      if (!in.read(reinterpret_cast<char*>(plane.data()), std::streamsize(plane.size() * sizeof(glm::vec3))))
        throw error(path, "truncated: the pixels end early");
    }
  if (in.peek() != std::ifstream::traits_type::eof()) throw error(path, "unexpected bytes after the pixels");
  return part;
}

ReferenceImage merge_reference_parts(const std::vector<ReferencePart>& parts, const std::vector<std::string>& paths) {
  if (parts.empty()) throw ReferenceFileError("no part files to merge");
  const ReferencePart& first = parts[0];
  std::vector<const ReferencePart*> by_chunk(first.chunk_count, nullptr);
  for (size_t i = 0; i < parts.size(); ++i) {
    const ReferencePart& p = parts[i];
    if (p.run != first.run || p.chunk_count != first.chunk_count || p.image.width != first.image.width ||
        p.image.height != first.image.height)
      throw error(paths[i], "belongs to another run than " + paths[0] + " (its run: " + p.run + ")");
    uint32_t begin = 0, end = 0;
    chunk_rows(p.image.height, p.chunk_index, p.chunk_count, begin, end);
    if (p.image.row_begin != begin || p.image.row_end != end)
      throw error(paths[i], "its rows do not match its chunk " + std::to_string(p.chunk_index));
    if (by_chunk[p.chunk_index]) throw error(paths[i], "chunk " + std::to_string(p.chunk_index) + " is given twice");
    by_chunk[p.chunk_index] = &p;
  }
  for (uint32_t c = 0; c < first.chunk_count; ++c)
    if (!by_chunk[c])
      throw ReferenceFileError("chunk " + std::to_string(c) + " of " + std::to_string(first.chunk_count) +
                               " is missing");
  ReferenceImage out;
  out.width = first.image.width, out.height = first.image.height, out.row_begin = 0, out.row_end = out.height;
  for (const ReferencePart* p : by_chunk) {
    for (size_t a = 0; a < kReferenceAovCount; ++a) {
      out.mean[a].insert(out.mean[a].end(), p->image.mean[a].begin(), p->image.mean[a].end());
      out.standard_error[a].insert(out.standard_error[a].end(), p->image.standard_error[a].begin(),
                                   p->image.standard_error[a].end());
    }
    out.non_finite_samples += p->image.non_finite_samples;
  }
  return out;
}

std::string standard_error_path(const std::string& out) {
  std::filesystem::path p(out);
  return (p.parent_path() / (p.stem().string() + ".stderr" + p.extension().string())).string();
}

std::vector<std::string> write_reference_exr(const std::string& out, const ReferenceImage& image, ReferenceAov aov) {
  auto rgba = [&](const std::vector<glm::vec3>& plane) {
    std::vector<float> pixels(plane.size() * 4);
    for (size_t i = 0; i < plane.size(); ++i)
      pixels[4 * i] = plane[i].r, pixels[4 * i + 1] = plane[i].g, pixels[4 * i + 2] = plane[i].b, pixels[4 * i + 3] = 1;
    return pixels;
  };
  const uint32_t rows = image.row_end - image.row_begin;
  const std::string error_path = standard_error_path(out);
  save_image(out, image.width, rows, rgba(image.mean_of(aov)), {.full_float = true});
  save_image(error_path, image.width, rows, rgba(image.error_of(aov)), {.full_float = true});
  return {out, error_path};
}

}  // namespace lg
