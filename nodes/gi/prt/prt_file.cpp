// Encoding, decoding and merging .lgprt files (prt_file.h, docs/prt.md).
#include "nodes/gi/prt/prt_file.h"

#include <cmath>
#include <type_traits>

#include "graph/json_writer.h"

namespace lg {
namespace {

constexpr std::string_view magic = "LGPRT001";
constexpr const char* format_name = "lumagraph-prt/1";

template <class File>
auto arrays_of(File& file) {
  using Values = std::conditional_t<std::is_const_v<File>, const std::vector<float>, std::vector<float>>;
  return std::vector<BakeArray<Values>>{
      {"transfer", uint32_t(prt_vertex_floats(file.header.settings.order)), &file.data.transfer},
      {"valid", 1, &file.data.valid}};
}

// Everything but the chunk: what every part of one bake shares.
JsonValue prt_identity_json(const PrtFileHeader& h) {
  JsonValue j = JsonValue::object();
  j.set("format", format_name);
  j.set("input", h.input);
  j.set("input_hash", hex64(h.input_hash));
  j.set("transfer", transfer_kind_name(h.settings.kind));
  j.set("order", uint64_t(h.settings.order));
  j.set("rays", uint64_t(h.settings.rays));
  j.set("bounces", uint64_t(h.settings.bounces));
  j.set("seed", h.settings.seed);
  j.set("vertices", h.vertices);
  JsonValue& parts = j.set("parts", JsonValue::array());
  for (const WorldMesh::Part& p : h.parts) {
    JsonValue part = JsonValue::object();
    part.set("mesh", p.name);
    part.set("first_vertex", uint64_t(p.first_vertex));
    part.set("vertex_count", uint64_t(p.vertex_count));
    parts.push(std::move(part));
  }
  return j;
}

PrtFileHeader parse_header(const JsonValue& j, const HeaderReader& in) {
  PrtFileHeader h;
  if (in.string(j, "format") != format_name) in.fail("format \"" + in.string(j, "format") + "\" is not " + format_name);
  h.input = in.string(j, "input");
  h.input_hash = in.hex64(j, "input_hash");
  const std::optional<TransferKind> kind = parse_transfer_kind(in.string(j, "transfer"));
  if (!kind) in.fail("transfer \"" + in.string(j, "transfer") + "\" is not unshadowed, shadowed or interreflected");
  h.settings.kind = *kind;
  h.settings.order = int(in.integer(j, "order", kPrtMaxOrder));
  h.settings.rays = uint32_t(in.integer(j, "rays", kPrtMaxRays));
  h.settings.bounces = uint32_t(in.integer(j, "bounces", kPrtMaxBounces));
  h.settings.seed = in.integer(j, "seed");
  try {
    check_prt_settings(h.settings);
  } catch (const std::invalid_argument& e) {
    in.fail(std::string("header: ") + e.what());
  }
  h.vertices = in.integer(j, "vertices", kPrtMaxVertices);
  const JsonValue& parts = in.member(j, "parts");
  if (!parts.is_array()) in.fail("header \"parts\" must be an array");
  uint64_t next = 0;
  for (const JsonValue& p : parts.items()) {
    const WorldMesh::Part part{in.string(p, "mesh"), uint32_t(in.integer(p, "first_vertex", kPrtMaxVertices)),
                               uint32_t(in.integer(p, "vertex_count", kPrtMaxVertices))};
    if (part.first_vertex != next)
      in.fail("part " + std::to_string(h.parts.size()) + " (\"" + part.name + "\") must start at vertex " +
              std::to_string(next) + ", where the part before it ends");
    next += part.vertex_count;
    h.parts.push_back(part);
  }
  if (next != h.vertices)
    in.fail("the parts hold " + std::to_string(next) + " vertices, the header says " + std::to_string(h.vertices));
  const JsonValue& chunk = in.member(j, "chunk");
  h.chunk_count = uint32_t(in.integer(chunk, "count", max_bake_chunks));
  h.chunk_index = uint32_t(in.integer(chunk, "index", max_bake_chunks));
  h.range = {in.integer(chunk, "begin"), in.integer(chunk, "end")};
  if (h.chunk_count == 0 || h.chunk_index >= h.chunk_count) in.fail("chunk index must be below the chunk count");
  const PointRange expected = chunk_range(h.vertices, h.chunk_index, h.chunk_count);
  if (h.range.begin != expected.begin || h.range.end != expected.end)
    in.fail("chunk " + std::to_string(h.chunk_index) + "/" + std::to_string(h.chunk_count) + " must hold vertices " +
            std::to_string(expected.begin) + " to " + std::to_string(expected.end));
  return h;
}

void check_values(const PrtFile& file, const HeaderReader& in) {
  const size_t floats = size_t(prt_vertex_floats(file.header.settings.order));
  for (size_t v = 0; v < file.data.valid.size(); ++v) {
    const std::string place = "vertex " + std::to_string(file.header.range.begin + v);
    const float valid = file.data.valid[v];
    if (valid != 0.0f && valid != 1.0f) in.fail(place + ": valid must be 0 or 1");
    for (size_t f = 0; f < floats; ++f) {
      const float t = file.data.transfer[v * floats + f];
      if (!std::isfinite(t)) in.fail(place + ": its transfer holds a non-finite value");
      if (valid == 0.0f && t != 0.0f) in.fail(place + ": is not valid but its transfer is not 0");
    }
  }
}

}  // namespace

PrtFileHeader make_prt_header(const WorldMesh& mesh, const std::string& input, const PrtSettings& settings,
                              uint32_t index, uint32_t count) {
  PrtFileHeader h;
  h.input = input;
  h.input_hash = world_mesh_hash(mesh);
  h.settings = settings;
  h.vertices = mesh.positions.size();
  h.parts = mesh.parts;
  h.chunk_index = index, h.chunk_count = count;
  h.range = chunk_range(h.vertices, index, count);
  return h;
}

std::string encode_prt_file(const PrtFile& file) {
  JsonValue header = prt_identity_json(file.header);
  const auto& h = file.header;
  set_chunk_json(header, h.chunk_index, h.chunk_count, h.range.begin, h.range.end);
  return encode_bake_container(magic, std::move(header), arrays_of(file));
}

void write_prt_file(const std::string& path, const PrtFile& file) {
  write_bake_bytes(path, encode_prt_file(file));
}

bool is_prt_file(const std::string& path) {
  return starts_with_magic(path, magic);
}

PrtFile read_prt_file(const std::string& path) {
  const HeaderReader in(path);
  const BakeContainer container = read_bake_container(path, magic, "PRT bake");
  PrtFile file;
  file.header = parse_header(container.header, in);
  // Sized from the header only once the file is known to hold that much (a forged header must
  // not make the reader allocate gigabytes).
  const uint64_t floats = file.header.range.size() * (prt_vertex_floats(file.header.settings.order) + 1);
  if (container.bytes.size() != container.data_start + floats * sizeof(float))
    in.fail("the file has " + std::to_string(container.bytes.size()) + " bytes; its header describes " +
            std::to_string(container.data_start + floats * sizeof(float)) + " (truncated or damaged)");
  file.data.transfer.resize(file.header.range.size() * prt_vertex_floats(file.header.settings.order));
  file.data.valid.resize(file.header.range.size());
  container.read_arrays(in, arrays_of(file));
  check_values(file, in);
  return file;
}

PrtFile merge_prt_parts(const std::vector<PrtFile>& parts, const std::vector<std::string>& paths) {
  if (parts.empty()) throw BakeFileError("merge: no parts given");
  const PrtFileHeader& first = parts[0].header;
  const std::string identity = write_json(prt_identity_json(first));
  std::vector<ChunkId> chunks;
  for (size_t p = 0; p < parts.size(); ++p) {
    const PrtFileHeader& h = parts[p].header;
    if (write_json(prt_identity_json(h)) != identity)
      throw BakeFileError(paths[p] + ": belongs to another PRT bake than " + paths[0] +
                          " (the input, its geometry, the settings or the seed differ)");
    chunks.push_back({h.chunk_index, h.chunk_count});
  }
  PrtFile merged;
  merged.header = first;
  merged.header.chunk_index = 0, merged.header.chunk_count = 1;
  merged.header.range = {0, first.vertices};
  for (size_t p : chunk_order(chunks, paths)) {
    const PrtData& d = parts[p].data;
    merged.data.transfer.insert(merged.data.transfer.end(), d.transfer.begin(), d.transfer.end());
    merged.data.valid.insert(merged.data.valid.end(), d.valid.begin(), d.valid.end());
  }
  return merged;
}

}  // namespace lg
