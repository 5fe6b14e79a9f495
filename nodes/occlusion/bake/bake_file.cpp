// Encoding, decoding and merging .lgbake files (bake_file.h, docs/bake-format.md).
#include "nodes/occlusion/bake/bake_file.h"

#include <cmath>
#include <limits>
#include <type_traits>

#include "graph/json_writer.h"

namespace lg {
namespace {

constexpr std::string_view magic = "LGBAKE01";
constexpr const char* format_name = "lumagraph-bake/1";

const char* falloff_name(OcclusionFalloff f) {
  return f == OcclusionFalloff::none ? "none" : "obscurance";
}

JsonValue number_array(std::initializer_list<double> values) {
  JsonValue a = JsonValue::array();
  for (double v : values) a.push(v);
  return a;
}

// The arrays of a file in their order in it (`File` is BakeFile or const BakeFile).
template <class File>
auto arrays_of(File& file) {
  using Values = std::conditional_t<std::is_const_v<File>, const std::vector<float>, std::vector<float>>;
  std::vector<BakeArray<Values>> arrays{{"visibility", 1, &file.data.visibility},
                                        {"bent_normal", 3, &file.data.bent_normal},
                                        {"valid", 1, &file.data.valid}};
  if (file.header.mode == BakeMode::texel) arrays.push_back({"lightmap_uv", 2, &file.lightmap_uvs});
  return arrays;
}

// Everything but the chunk: what every part of one bake shares.
JsonValue bake_identity_json(const BakeHeader& h) {
  JsonValue j = JsonValue::object();
  j.set("format", format_name);
  j.set("mode", bake_mode_name(h.mode));
  j.set("input", h.input);
  j.set("input_hash", hex64(h.input_hash));
  j.set("rays", h.occlusion.rays);
  j.set("max_distance",
        std::isinf(h.occlusion.max_distance) ? JsonValue("infinite") : JsonValue(double(h.occlusion.max_distance)));
  j.set("falloff", falloff_name(h.occlusion.falloff));
  j.set("seed", h.seed);
  j.set("points", h.points);
  if (h.mode == BakeMode::vertex) {
    JsonValue parts = JsonValue::array();
    for (const WorldMesh::Part& p : h.parts) {
      JsonValue part = JsonValue::object();
      part.set("mesh", p.name);
      part.set("first_vertex", uint64_t(p.first_vertex));
      part.set("vertex_count", uint64_t(p.vertex_count));
      parts.push(std::move(part));
    }
    j.set("vertex", JsonValue::object()).set("parts", std::move(parts));
  } else if (h.mode == BakeMode::texel) {
    JsonValue& t = j.set("texel", JsonValue::object());
    t.set("size", uint64_t(h.lightmap_size));
    t.set("triangles", h.triangles);
  } else {
    JsonValue& v = j.set("volume", JsonValue::object());
    v.set("dims", number_array({double(h.dims[0]), double(h.dims[1]), double(h.dims[2])}));
    v.set("origin", number_array({h.origin.x, h.origin.y, h.origin.z}));
    v.set("spacing", number_array({h.spacing.x, h.spacing.y, h.spacing.z}));
  }
  return j;
}

BakeHeader parse_header(const JsonValue& j, const HeaderReader& in) {
  BakeHeader h;
  if (in.string(j, "format") != format_name) in.fail("format \"" + in.string(j, "format") + "\" is not " + format_name);
  const std::optional<BakeMode> mode = parse_bake_mode(in.string(j, "mode"));
  if (!mode) in.fail("mode \"" + in.string(j, "mode") + "\" is not vertex, texel or volume");
  h.mode = *mode;
  h.input = in.string(j, "input");
  h.input_hash = in.hex64(j, "input_hash");
  h.occlusion.rays = int(in.integer(j, "rays", max_rays_per_point));
  const JsonValue& distance = in.member(j, "max_distance");
  h.occlusion.max_distance = distance.is_string() && distance.as_string() == "infinite"
                                 ? std::numeric_limits<float>::infinity()
                                 : float(in.number(distance, "max_distance"));
  const std::string& falloff = in.string(j, "falloff");
  if (falloff != "none" && falloff != "obscurance") in.fail("falloff \"" + falloff + "\" is not none or obscurance");
  h.occlusion.falloff = falloff == "none" ? OcclusionFalloff::none : OcclusionFalloff::obscurance;
  h.seed = in.integer(j, "seed");
  h.points = in.integer(j, "points", std::numeric_limits<uint32_t>::max());
  const JsonValue& chunk = in.member(j, "chunk");
  h.chunk_count = uint32_t(in.integer(chunk, "count", max_bake_chunks));
  h.chunk_index = uint32_t(in.integer(chunk, "index", max_bake_chunks));
  h.range = {in.integer(chunk, "begin"), in.integer(chunk, "end")};
  if (h.chunk_count == 0 || h.chunk_index >= h.chunk_count) in.fail("chunk index must be below the chunk count");
  const PointRange expected = chunk_range(h.points, h.chunk_index, h.chunk_count);
  if (h.range.begin != expected.begin || h.range.end != expected.end)
    in.fail("chunk " + std::to_string(h.chunk_index) + "/" + std::to_string(h.chunk_count) + " must hold points " +
            std::to_string(expected.begin) + " to " + std::to_string(expected.end));
  if (h.mode == BakeMode::vertex) {
    const JsonValue& parts = in.member(in.member(j, "vertex"), "parts");
    if (!parts.is_array()) in.fail("header \"parts\" must be an array");
    for (const JsonValue& p : parts.items())
      h.parts.push_back({in.string(p, "mesh"), uint32_t(in.integer(p, "first_vertex", UINT32_MAX)),
                         uint32_t(in.integer(p, "vertex_count", UINT32_MAX))});
  } else if (h.mode == BakeMode::texel) {
    const JsonValue& t = in.member(j, "texel");
    h.lightmap_size = uint32_t(in.integer(t, "size", max_lightmap_size));
    h.triangles = in.integer(t, "triangles");
  } else {
    const JsonValue& v = in.member(j, "volume");
    const glm::dvec3 dims = in.vec3(v, "dims");
    for (int a = 0; a < 3; ++a) h.dims[a] = uint32_t(dims[a]);
    h.origin = in.vec3(v, "origin");
    h.spacing = in.vec3(v, "spacing");
  }
  // The layout must describe exactly the bake's points, as the side files rely on it.
  uint64_t described = 0;
  if (h.mode == BakeMode::vertex)
    for (const WorldMesh::Part& p : h.parts) described += p.vertex_count;
  if (h.mode == BakeMode::texel) described = uint64_t(h.lightmap_size) * h.lightmap_size;
  if (h.mode == BakeMode::volume) {
    for (uint32_t d : h.dims)
      if (d < 2 || d > max_volume_axis) in.fail("volume dims must be from 2 to " + std::to_string(max_volume_axis));
    described = uint64_t(h.dims[0]) * h.dims[1] * h.dims[2];
  }
  if (described != h.points)
    in.fail("the " + std::string(bake_mode_name(h.mode)) + " layout describes " + std::to_string(described) +
            " points, the header says " + std::to_string(h.points));
  return h;
}

}  // namespace

BakeHeader make_bake_header(const BakeDomain& domain, const WorldMesh& mesh, const std::string& input,
                            const OcclusionSettings& occlusion, uint64_t seed, uint32_t index, uint32_t count) {
  BakeHeader h;
  h.mode = domain.mode();
  h.input = input;
  h.input_hash = world_mesh_hash(mesh);
  h.occlusion = occlusion;
  h.seed = seed;
  h.points = domain.size();
  h.chunk_index = index, h.chunk_count = count;
  h.range = chunk_range(h.points, index, count);
  if (h.mode == BakeMode::vertex) h.parts = mesh.parts;
  h.lightmap_size = domain.lightmap_size();
  if (h.mode == BakeMode::texel) h.triangles = mesh.triangle_count();
  h.dims = domain.dims();
  h.origin = domain.origin(), h.spacing = domain.spacing();
  return h;
}

std::string encode_bake_file(const BakeFile& file) {
  JsonValue header = bake_identity_json(file.header);
  const auto& h = file.header;
  set_chunk_json(header, h.chunk_index, h.chunk_count, h.range.begin, h.range.end);
  return encode_bake_container(magic, std::move(header), arrays_of(file));
}

void write_bake_file(const std::string& path, const BakeFile& file) {
  write_bake_bytes(path, encode_bake_file(file));
}

BakeFile read_bake_file(const std::string& path) {
  const HeaderReader in(path);
  const BakeContainer container = read_bake_container(path, magic, "bake");
  BakeFile file;
  file.header = parse_header(container.header, in);
  file.data.resize(file.header.range.size());
  if (file.header.mode == BakeMode::texel) file.lightmap_uvs.resize(file.header.triangles * 6);
  container.read_arrays(in, arrays_of(file));
  return file;
}

BakeFile merge_bake_parts(const std::vector<BakeFile>& parts, const std::vector<std::string>& paths) {
  if (parts.empty()) throw BakeFileError("merge: no parts given");
  const BakeHeader& first = parts[0].header;
  const std::string identity = write_json(bake_identity_json(first));
  std::vector<ChunkId> chunks;
  for (size_t p = 0; p < parts.size(); ++p) {
    const BakeHeader& h = parts[p].header;
    if (write_json(bake_identity_json(h)) != identity)
      throw BakeFileError(paths[p] + ": belongs to another bake than " + paths[0] +
                          " (the input, its geometry, the mode, the settings or the seed differ)");
    if (parts[p].lightmap_uvs != parts[0].lightmap_uvs)
      throw BakeFileError(paths[p] + ": its lightmap UVs differ from " + paths[0] + "'s");
    chunks.push_back({h.chunk_index, h.chunk_count});
  }
  BakeFile merged;
  merged.header = first;
  merged.header.chunk_index = 0, merged.header.chunk_count = 1;
  merged.header.range = {0, first.points};
  merged.lightmap_uvs = parts[0].lightmap_uvs;
  for (size_t p : chunk_order(chunks, paths)) {
    const BakeData& d = parts[p].data;
    merged.data.visibility.insert(merged.data.visibility.end(), d.visibility.begin(), d.visibility.end());
    merged.data.bent_normal.insert(merged.data.bent_normal.end(), d.bent_normal.begin(), d.bent_normal.end());
    merged.data.valid.insert(merged.data.valid.end(), d.valid.begin(), d.valid.end());
  }
  return merged;
}

}  // namespace lg
