// Encoding, decoding and merging .lgprobes files (probe_file.h, docs/probe-format.md).
#include "nodes/gi/probes/probe_file.h"

#include <cmath>
#include <span>
#include <type_traits>

#include "graph/json_writer.h"

namespace lg {
namespace {

constexpr std::string_view magic = "LGPROBE1";
constexpr const char* format_name = "lumagraph-probes/1";

// The float fields of a probe after `active`, in the file's order, as spans over its floats.
template <class Probe>
auto float_fields(Probe& p) {
  using Float = std::conditional_t<std::is_const_v<Probe>, const float, float>;
  auto floats = [](auto& field) {
    return std::span<Float>(reinterpret_cast<Float*>(&field), sizeof field / sizeof(float));
  };
  return std::array{floats(p.offset), floats(p.sh), floats(p.ambient_cube), floats(p.irradiance), floats(p.distance)};
}
constexpr const char* field_names[] = {"offset", "sh", "ambient_cube", "irradiance", "distance"};
static_assert(sizeof(ProbeData::sh) == kProbeShCount * 3 * sizeof(float), "glm vectors are packed floats");

// Every field of the probes as one array each, probe after probe.
struct ProbeArrays {
  std::vector<float> active;
  std::array<std::vector<float>, 5> fields;

  template <class Self>
  static auto list(Self& self) {
    using Values = std::conditional_t<std::is_const_v<Self>, const std::vector<float>, std::vector<float>>;
    const ProbeData probe;
    const auto sizes = float_fields(probe);
    std::vector<BakeArray<Values>> arrays{{"active", 1, &self.active}};
    for (size_t f = 0; f < self.fields.size(); ++f)
      arrays.push_back({field_names[f], uint32_t(sizes[f].size()), &self.fields[f]});
    return arrays;
  }
};

ProbeArrays flatten(const std::vector<ProbeData>& probes) {
  ProbeArrays a;
  for (const ProbeData& p : probes) {
    a.active.push_back(p.active ? 1.0f : 0.0f);
    const auto fields = float_fields(p);
    for (size_t f = 0; f < fields.size(); ++f)
      a.fields[f].insert(a.fields[f].end(), fields[f].begin(), fields[f].end());
  }
  return a;
}

JsonValue number_array(std::span<const float> values) {
  JsonValue a = JsonValue::array();
  for (float v : values) a.push(double(v));
  return a;
}

// Everything but the chunk: what every part of one run shares.
JsonValue probe_identity_json(const ProbeFileHeader& h) {
  JsonValue j = JsonValue::object();
  j.set("format", format_name);
  j.set("scene", h.scene);
  j.set("graph", h.graph);
  j.set("environment", h.environment);
  j.set("geometry_hash", hex64(h.geometry_hash));
  j.set("rays", uint64_t(h.settings.rays));
  j.set("bounces", uint64_t(h.settings.bounces));
  j.set("seed", h.settings.seed);
  j.set("probes", h.probes);
  JsonValue& volumes = j.set("volumes", JsonValue::array());
  const std::vector<uint64_t> first = h.first_probes();
  for (size_t v = 0; v < h.volumes.size(); ++v) {
    const IrradianceVolumeData& volume = h.volumes[v];
    JsonValue entry = JsonValue::object();
    entry.set("frame", number_array({&volume.world[0][0], 16}));
    entry.set("size", number_array({&volume.size.x, 3}));
    JsonValue counts = JsonValue::array();
    for (int a = 0; a < 3; ++a) counts.push(volume.probe_counts[a]);
    entry.set("probes", std::move(counts));
    entry.set("first_probe", first[v]);
    volumes.push(std::move(entry));
  }
  return j;
}

JsonValue probe_header_json(const ProbeFileHeader& h) {
  JsonValue j = probe_identity_json(h);
  set_chunk_json(j, h.chunk_index, h.chunk_count, h.range.begin, h.range.end);
  return j;
}

// `count` finite floats from a JSON array.
void read_floats(const JsonValue& object, const char* key, float* out, size_t count, const HeaderReader& in) {
  const JsonValue& v = in.member(object, key);
  if (!v.is_array() || v.size() != count)
    in.fail("header \"" + std::string(key) + "\" must be an array of " + std::to_string(count) + " numbers");
  for (size_t i = 0; i < count; ++i) {
    out[i] = float(in.number(v.items()[i], key));
    if (!std::isfinite(out[i])) in.fail("header \"" + std::string(key) + "\" holds a non-finite number");
  }
}

ProbeFileHeader parse_header(const JsonValue& j, const HeaderReader& in) {
  ProbeFileHeader h;
  if (in.string(j, "format") != format_name) in.fail("format \"" + in.string(j, "format") + "\" is not " + format_name);
  h.scene = in.string(j, "scene");
  h.graph = in.string(j, "graph");
  h.environment = in.string(j, "environment");
  h.geometry_hash = in.hex64(j, "geometry_hash");
  h.settings.rays = uint32_t(in.integer(j, "rays", max_probe_rays));
  h.settings.bounces = uint32_t(in.integer(j, "bounces", max_probe_bounces));
  h.settings.seed = in.integer(j, "seed");
  h.probes = in.integer(j, "probes", max_file_probes);
  const JsonValue& volumes = in.member(j, "volumes");
  if (!volumes.is_array() || volumes.size() == 0 || volumes.size() > max_probe_volumes)
    in.fail("header \"volumes\" must be an array of 1 to " + std::to_string(max_probe_volumes) + " volumes");
  uint64_t probes = 0;
  for (const JsonValue& v : volumes.items()) {
    const std::string place = "volume " + std::to_string(h.volumes.size());
    IrradianceVolumeData volume;
    read_floats(v, "frame", &volume.world[0][0], 16, in);
    read_floats(v, "size", &volume.size.x, 3, in);
    if (volume.size.x <= 0.0f || volume.size.y <= 0.0f || volume.size.z <= 0.0f)
      in.fail(place + ": size must be positive along every axis");
    const glm::dvec3 counts = in.vec3(v, "probes");
    for (int a = 0; a < 3; ++a) {
      if (counts[a] < 1 || counts[a] > max_probes_per_axis || counts[a] != std::floor(counts[a]))
        in.fail(place + ": probe counts must be whole numbers from 1 to " + std::to_string(max_probes_per_axis));
      volume.probe_counts[a] = int(counts[a]);
    }
    if (in.integer(v, "first_probe") != probes)
      in.fail(place + ": first_probe must be " + std::to_string(probes) + ", the probes of the volumes before it");
    probes += uint64_t(counts.x) * uint64_t(counts.y) * uint64_t(counts.z);
    h.volumes.push_back(volume);
  }
  if (probes != h.probes)
    in.fail("the volumes hold " + std::to_string(probes) + " probes, the header says " + std::to_string(h.probes));
  const JsonValue& chunk = in.member(j, "chunk");
  h.chunk_count = uint32_t(in.integer(chunk, "count", max_bake_chunks));
  h.chunk_index = uint32_t(in.integer(chunk, "index", max_bake_chunks));
  h.range = {in.integer(chunk, "begin"), in.integer(chunk, "end")};
  if (h.chunk_count == 0 || h.chunk_index >= h.chunk_count) in.fail("chunk index must be below the chunk count");
  const PointRange expected = chunk_range(h.probes, h.chunk_index, h.chunk_count);
  if (h.range.begin != expected.begin || h.range.end != expected.end)
    in.fail("chunk " + std::to_string(h.chunk_index) + "/" + std::to_string(h.chunk_count) + " must hold probes " +
            std::to_string(expected.begin) + " to " + std::to_string(expected.end));
  return h;
}

}  // namespace

std::vector<uint64_t> ProbeFileHeader::first_probes() const {
  std::vector<uint64_t> first;
  uint64_t at = 0;
  for (const IrradianceVolumeData& v : volumes) {
    first.push_back(at);
    at += probe_count(v);
  }
  return first;
}

ProbeFileHeader make_probe_header(std::vector<IrradianceVolumeData> volumes, uint32_t index, uint32_t count) {
  ProbeFileHeader h;
  for (const IrradianceVolumeData& v : volumes) h.probes += probe_count(v);
  h.volumes = std::move(volumes);
  h.chunk_index = index, h.chunk_count = count;
  h.range = chunk_range(h.probes, index, count);
  return h;
}

std::string encode_probe_file(const ProbeFile& file) {
  const ProbeArrays arrays = flatten(file.probes);
  return encode_bake_container(magic, probe_header_json(file.header), ProbeArrays::list(arrays));
}

void write_probe_file(const std::string& path, const ProbeFile& file) {
  write_bake_bytes(path, encode_probe_file(file));
}

bool is_probe_file(const std::string& path) {
  return starts_with_magic(path, magic);
}

ProbeFile read_probe_file(const std::string& path) {
  const HeaderReader in(path);
  const BakeContainer container = read_bake_container(path, magic, "probe bake");
  ProbeFile file;
  file.header = parse_header(container.header, in);
  const size_t count = file.header.range.size();
  ProbeArrays arrays;
  for (auto& a : ProbeArrays::list(arrays)) a.values->resize(count * a.components);
  container.read_arrays(in, ProbeArrays::list(arrays));
  file.probes.resize(count);
  for (size_t i = 0; i < count; ++i) {
    const std::string place = "probe " + std::to_string(file.header.range.begin + i);
    if (arrays.active[i] != 0.0f && arrays.active[i] != 1.0f) in.fail(place + ": active must be 0 or 1");
    ProbeData& p = file.probes[i];
    p.active = arrays.active[i] == 1.0f;
    const auto fields = float_fields(p);
    for (size_t f = 0; f < fields.size(); ++f) {
      const float* values = arrays.fields[f].data() + i * fields[f].size();
      for (size_t c = 0; c < fields[f].size(); ++c) {
        if (!std::isfinite(values[c])) in.fail(place + ": " + field_names[f] + " holds a non-finite value");
        fields[f][c] = values[c];
      }
    }
  }
  return file;
}

ProbeFile merge_probe_parts(const std::vector<ProbeFile>& parts, const std::vector<std::string>& paths) {
  if (parts.empty()) throw BakeFileError("merge: no parts given");
  const ProbeFileHeader& first = parts[0].header;
  const std::string identity = write_json(probe_identity_json(first));
  std::vector<ChunkId> chunks;
  for (size_t p = 0; p < parts.size(); ++p) {
    const ProbeFileHeader& h = parts[p].header;
    if (write_json(probe_identity_json(h)) != identity)
      throw BakeFileError(paths[p] + ": belongs to another probe bake than " + paths[0] +
                          " (the scene, its geometry or volumes, the graph, the environment, the settings or the "
                          "seed differ)");
    chunks.push_back({h.chunk_index, h.chunk_count});
  }
  ProbeFile merged;
  merged.header = first;
  merged.header.chunk_index = 0, merged.header.chunk_count = 1;
  merged.header.range = {0, first.probes};
  for (size_t p : chunk_order(chunks, paths))
    merged.probes.insert(merged.probes.end(), parts[p].probes.begin(), parts[p].probes.end());
  return merged;
}

std::vector<ProbeGrid> probe_grids(const ProbeFile& whole) {
  std::vector<ProbeGrid> grids;
  size_t at = 0;
  for (const IrradianceVolumeData& volume : whole.header.volumes) {
    ProbeGrid& grid = grids.emplace_back(volume);
    std::copy_n(whole.probes.begin() + at, grid.probe_count(), grid.probes.begin());
    at += grid.probe_count();
  }
  return grids;
}

ProbeFile whole_probe_file(std::span<const ProbeGrid> grids, const ProbeBakeSettings& settings) {
  std::vector<IrradianceVolumeData> volumes;
  for (const ProbeGrid& grid : grids) volumes.push_back(grid.volume());
  ProbeFile file;
  file.header = make_probe_header(std::move(volumes), 0, 1);
  file.header.settings = settings;
  file.probes.reserve(file.header.probes);
  for (const ProbeGrid& grid : grids) file.probes.insert(file.probes.end(), grid.probes.begin(), grid.probes.end());
  return file;
}

}  // namespace lg
